// Snow on a plain scene: the roles and effects a scene author would declare
// for "let it snow on this model", chosen from the geometry alone. Only
// parts the scene leaves undeclared are filled in, and the result goes
// through the same build path (build_scene) as declared ones.
#include "game/scene/scene_auto_snow.hpp"

#include "systems/flakes/snowfall.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// Cell edge for a cover whose longer side is `side` m: at least
/// auto_cover_min_cell, rounded up to whole centimetres so the cover never
/// exceeds auto_cover_cells_per_side cells along it.
float auto_cover_cell(float side) {
    const double fine = static_cast<double>(side) / auto_cover_cells_per_side;
    return std::max(auto_cover_min_cell, static_cast<float>(std::ceil(fine * 100.0) / 100.0));
}

/// A cover over the meshes' xz footprint.
CoverDef footprint_cover(const Aabb& meshes, const std::string& field) {
    CoverDef c;
    c.min_x = meshes.min.x;
    c.min_z = meshes.min.z;
    c.max_x = meshes.max.x;
    c.max_z = meshes.max.z;
    const float side_x = c.max_x - c.min_x, side_z = c.max_z - c.min_z;
    c.cell = auto_cover_cell(std::max(side_x, side_z));
    if (std::round(side_x / c.cell) < 1.0f || std::round(side_z / c.cell) < 1.0f) {
        scene_fail(field, "needs a footprint of at least one " + number_text(c.cell) +
                              " m cell each way for its snow cover (the meshes span " +
                              number_text(side_x) + " × " + number_text(side_z) + " m in x × z)");
    }
    return c;
}

/// Sky-map texels about the cover's cell over the bounds, within [256, 1024].
OcclusionCamera occlusion_for(const Aabb& bounds, float cover_cell) {
    const glm::vec3 size = bounds.size();
    const double texels = std::ceil(std::max(size.x, size.z) / static_cast<double>(cover_cell));
    OcclusionCamera cam;
    cam.resolution = static_cast<std::uint32_t>(std::clamp(texels, 256.0, 1024.0));
    return cam;
}

/// auto_flakes_per_m2_s over the top of the bounds, but no more than keeps
/// about half the flake pool airborne while flakes fall through the bounds.
Emitter emitter_for(const SimConfig& config) {
    Emitter e;
    const glm::vec3 size = config.bounds.size();
    const auto mean_fall_speed = static_cast<float>(spectrum_means(e).fall_speed);
    const float fall_seconds = std::max(size.y, 1.0f) / mean_fall_speed;
    e.rate = std::min(auto_flakes_per_m2_s * size.x * size.z,
                      0.5f * static_cast<float>(config.max_flakes) / fall_seconds);
    // Parcels hold at most max_flake_units: over a footprint too large for the
    // pool it snows more lightly instead of overfilling the pool.
    e.snowfall_kg_m2_h = std::min(
        e.snowfall_kg_m2_h, heaviest_snowfall_kg_m2_h(e, static_cast<double>(size.x) * size.z));
    return e;
}

/// The default view's direction and field of view, far enough back that a
/// sphere around the meshes fills the frame's height.
CameraDef framing_camera(const Aabb& meshes) {
    CameraDef c;
    const glm::vec3 center = 0.5f * (meshes.min + meshes.max);
    const float radius = std::max(0.5f * glm::length(meshes.size()), 1.0f);
    const float distance = radius / std::sin(glm::radians(0.5f * c.fov_y_deg));
    c.target = center;
    c.position = center + distance * glm::normalize(glm::vec3(0.0f, 0.5f, 1.0f));
    c.far_plane = std::max(c.far_plane, 4.0f * (distance + radius));
    return c;
}

} // namespace

std::optional<Aabb> mesh_bounds(const SceneGeometry& g) {
    std::optional<Aabb> b;
    for (const WorldNode& n : g.nodes) {
        if (!n.primitives.empty()) {
            b = b ? Aabb{glm::min(b->min, n.bounds.min), glm::max(b->max, n.bounds.max)} : n.bounds;
        }
    }
    return b;
}

void add_auto_snow(const SceneGeometry& g, const SimConfig& config, const std::string& field,
                   std::vector<NodeSnow>& roles, SceneSnow& settings) {
    const std::optional<Aabb> meshes = mesh_bounds(g);
    if (!meshes) {
        scene_fail(field,
                   "asks for snow on the scene's meshes, but the scene has no triangle mesh");
    }
    for (std::size_t i = 0; i < g.nodes.size(); ++i) {
        NodeSnow& role = roles[i];
        if (!g.nodes[i].primitives.empty() && !role.surface && !role.collider && !is_body(role)) {
            role.collider = ColliderKind::mesh;
        }
    }
    if (!settings.cover) {
        settings.cover = footprint_cover(*meshes, field);
    }
    if (!settings.occlusion) {
        settings.occlusion = occlusion_for(config.bounds, settings.cover->cell);
    }
    if (!settings.emitter) {
        settings.emitter = emitter_for(config);
    }
    if (!settings.camera) {
        settings.camera = framing_camera(*meshes);
    }
}

} // namespace snow
