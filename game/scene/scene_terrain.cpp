// The terrain mesh from a height map. Heights and positions are computed in
// double from the sample indices and rounded once to float, so every load
// gives the same mesh bit for bit.
#include "game/scene/scene_terrain.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace snow {

WorldDef read_world(const Json& j, const std::string& path) {
    WorldDef def = read_struct(j, path, world_fields, UnknownKeys::reject);
    if (def.extent.size() != 2) {
        scene_fail(path + ".extent",
                   "must be [x, z] (got " + std::to_string(def.extent.size()) + " numbers)");
    }
    if (def.height.size() != 2) {
        scene_fail(path + ".height",
                   "must be [min, max] (got " + std::to_string(def.height.size()) + " numbers)");
    }
    if (!(def.height[1] >= def.height[0])) {
        scene_fail(path + ".height", "max must be >= min (got [" + number_text(def.height[0]) +
                                         ", " + number_text(def.height[1]) + "])");
    }
    return def;
}

std::uint64_t terrain_triangle_count(std::uint32_t width, std::uint32_t height) {
    return width < 2 || height < 2 ? 0 : 2 * std::uint64_t{width - 1} * (height - 1);
}

Aabb terrain_bounds(const WorldDef& def) {
    const double hx = 0.5 * def.extent[0], hz = 0.5 * def.extent[1];
    return {glm::vec3(static_cast<float>(-hx), static_cast<float>(def.height[0]),
                      static_cast<float>(-hz)),
            glm::vec3(static_cast<float>(hx), static_cast<float>(def.height[1]),
                      static_cast<float>(hz))};
}

TerrainMesh terrain_mesh(const WorldDef& def, const HeightSamples& s) {
    const std::uint32_t w = s.width, h = s.height;
    const double step_x = def.extent[0] / (w - 1), step_z = def.extent[1] / (h - 1);
    const double x0 = -0.5 * def.extent[0], z0 = -0.5 * def.extent[1];
    const double y_per_grey = (def.height[1] - def.height[0]) / 65535.0;
    const auto y_at = [&](std::uint32_t i, std::uint32_t j) {
        return def.height[0] + y_per_grey * s.values[std::size_t{j} * w + i];
    };
    TerrainMesh m;
    const std::size_t count = std::size_t{w} * h;
    m.positions.resize(count);
    m.normals.resize(count);
    for (std::uint32_t j = 0; j < h; ++j) {
        for (std::uint32_t i = 0; i < w; ++i) {
            const std::size_t v = std::size_t{j} * w + i;
            // The last sample sits exactly on the far edge, not a rounding off it.
            const double x = i + 1 == w ? -x0 : x0 + step_x * i;
            const double z = j + 1 == h ? -z0 : z0 + step_z * j;
            m.positions[v] = glm::vec3(static_cast<float>(x), static_cast<float>(y_at(i, j)),
                                       static_cast<float>(z));
            // Central differences (one-sided at the border) for the slope.
            const std::uint32_t il = i == 0 ? 0 : i - 1, ir = std::min(i + 1, w - 1);
            const std::uint32_t jl = j == 0 ? 0 : j - 1, jr = std::min(j + 1, h - 1);
            const double dx = (y_at(ir, j) - y_at(il, j)) / (step_x * (ir - il));
            const double dz = (y_at(i, jr) - y_at(i, jl)) / (step_z * (jr - jl));
            m.normals[v] = glm::vec3(glm::normalize(glm::dvec3(-dx, 1.0, -dz)));
        }
    }
    m.indices.reserve(static_cast<std::size_t>(terrain_triangle_count(w, h)) * 3);
    for (std::uint32_t j = 0; j + 1 < h; ++j) {
        for (std::uint32_t i = 0; i + 1 < w; ++i) {
            const std::uint32_t v00 = j * w + i, v10 = v00 + 1, v01 = v00 + w, v11 = v01 + 1;
            // Counter-clockwise seen from +y: (x, z) → (x, z + 1) → (x + 1, z).
            m.indices.insert(m.indices.end(), {v00, v01, v10, v10, v01, v11});
        }
    }
    return m;
}

std::vector<glm::vec3> terrain_triangles(const TerrainMesh& mesh) {
    std::vector<glm::vec3> out;
    out.reserve(mesh.indices.size());
    for (const std::uint32_t i : mesh.indices) {
        out.push_back(mesh.positions[i]);
    }
    return out;
}

} // namespace snow
