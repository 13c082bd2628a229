#include "render/surface_mesh.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <bit>
#include <span>

namespace snow {

namespace {

/// Height (m) of a cell's bare top.
float base_y(const SnowSurface& s, std::size_t i) {
    return s.height(s.base_level[i]);
}

/// Corner (ix, iz), 0..nx × 0..nz: averages of the up to four cells around it.
struct CornerSample {
    float top = 0.0f;
    float base = 0.0f;
};

CornerSample corner_sample(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz) {
    float top = 0.0f, base = 0.0f;
    int n = 0;
    for (std::uint32_t cz = (iz > 0 ? iz - 1 : 0); cz <= std::min(iz, s.nz - 1); ++cz) {
        for (std::uint32_t cx = (ix > 0 ? ix - 1 : 0); cx <= std::min(ix, s.nx - 1); ++cx) {
            const std::size_t i = s.index(cx, cz);
            if (s.is_void(i)) {
                continue; // a cover's cell with no geometry: no snow, not drawn
            }
            top += s.top_y(i);
            base += base_y(s, i);
            ++n;
        }
    }
    if (n == 0) {
        return {};
    }
    return {top / static_cast<float>(n), base / static_cast<float>(n)};
}

void push_vertex(std::vector<float>& v, const glm::vec3& p, const glm::vec3& n, float depth) {
    v.insert(v.end(), {p.x, p.y, p.z, n.x, n.y, n.z, depth});
}

} // namespace

void build_surface_mesh(const SnowSurface& s, std::vector<float>& vertices,
                        std::vector<std::uint32_t>* indices) {
    vertices.clear();
    if (s.nx == 0 || s.nz == 0 || s.snow.size() != static_cast<std::size_t>(s.nx) * s.nz ||
        s.base_level.size() != s.snow.size()) {
        if (indices != nullptr) {
            indices->clear();
        }
        return;
    }
    const std::uint32_t cx = s.nx + 1, cz = s.nz + 1; // corners per side
    const auto corner = [cx](std::uint32_t ix, std::uint32_t iz) { return iz * cx + ix; };
    // Corner heights first, so normals can difference their neighbours.
    std::vector<CornerSample> samples(static_cast<std::size_t>(cx) * cz);
    for (std::uint32_t iz = 0; iz < cz; ++iz) {
        for (std::uint32_t ix = 0; ix < cx; ++ix) {
            samples[corner(ix, iz)] = corner_sample(s, ix, iz);
        }
    }
    vertices.reserve((samples.size() + 4u * (s.nx + s.nz + 2u)) * surface_vertex_floats);
    for (std::uint32_t iz = 0; iz < cz; ++iz) {
        for (std::uint32_t ix = 0; ix < cx; ++ix) {
            const std::uint32_t l = ix > 0 ? ix - 1 : ix, r = ix + 1 < cx ? ix + 1 : ix;
            const std::uint32_t b = iz > 0 ? iz - 1 : iz, f = iz + 1 < cz ? iz + 1 : iz;
            const float dhdx = (samples[corner(r, iz)].top - samples[corner(l, iz)].top) /
                               (static_cast<float>(r - l) * s.cell);
            const float dhdz = (samples[corner(ix, f)].top - samples[corner(ix, b)].top) /
                               (static_cast<float>(f - b) * s.cell);
            const CornerSample& c = samples[corner(ix, iz)];
            push_vertex(vertices,
                        {s.x0 + static_cast<float>(ix) * s.cell, c.top,
                         s.z0 + static_cast<float>(iz) * s.cell},
                        glm::normalize(glm::vec3(-dhdx, 1.0f, -dhdz)), c.top - c.base);
        }
    }
    // Apron: a vertical strip from the snow edge down to the bare top, facing out.
    struct Edge {
        std::uint32_t x0, z0, dx, dz, length;
        glm::vec3 out;
        bool flip; // swap winding so the strip is front-facing from outside
    };
    const Edge edges[4] = {{0, 0, 1, 0, s.nx, {0.0f, 0.0f, -1.0f}, true},
                           {0, s.nz, 1, 0, s.nx, {0.0f, 0.0f, 1.0f}, false},
                           {0, 0, 0, 1, s.nz, {-1.0f, 0.0f, 0.0f}, false},
                           {s.nx, 0, 0, 1, s.nz, {1.0f, 0.0f, 0.0f}, true}};
    const std::uint32_t grid_vertices = cx * cz;
    std::uint32_t next = grid_vertices;
    if (indices != nullptr) {
        indices->clear();
        indices->reserve(static_cast<std::size_t>(s.nx) * s.nz * 6u + 12u * (s.nx + s.nz));
        for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
            for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
                if (s.is_void(s.index(ix, iz))) {
                    continue;
                }
                const std::uint32_t a = corner(ix, iz), b = corner(ix + 1, iz),
                                    c = corner(ix, iz + 1), d = corner(ix + 1, iz + 1);
                indices->insert(indices->end(), {a, c, b, b, c, d}); // counter-clockwise from +y
            }
        }
    }
    // A cover's border cuts through geometry or void: no apron there.
    for (const Edge& e : s.closed.empty() ? std::span<const Edge>(edges) : std::span<const Edge>()) {
        const std::uint32_t first = next;
        for (std::uint32_t k = 0; k <= e.length; ++k) {
            const std::uint32_t ix = e.x0 + k * e.dx, iz = e.z0 + k * e.dz;
            const CornerSample& c = samples[corner(ix, iz)];
            const float x = s.x0 + static_cast<float>(ix) * s.cell;
            const float z = s.z0 + static_cast<float>(iz) * s.cell;
            push_vertex(vertices, {x, c.top, z}, e.out, c.top - c.base);
            push_vertex(vertices, {x, c.base, z}, e.out, c.top - c.base);
            next += 2;
        }
        if (indices != nullptr) {
            for (std::uint32_t k = 0; k < e.length; ++k) {
                const std::uint32_t t0 = first + 2 * k, b0 = t0 + 1, t1 = t0 + 2, b1 = t0 + 3;
                if (e.flip) {
                    indices->insert(indices->end(), {t0, t1, b0, t1, b1, b0});
                } else {
                    indices->insert(indices->end(), {t0, b0, t1, t1, b0, b1});
                }
            }
        }
    }
}

std::uint64_t surface_fingerprint(const SnowSurface& s) {
    // FNV-1a over the grid description and every cell's snow.
    std::uint64_t h = 1469598103934665603ull;
    const auto mix = [&h](std::uint64_t v) {
        h ^= v;
        h *= 1099511628211ull;
    };
    mix(s.nx);
    mix(s.nz);
    mix(std::bit_cast<std::uint32_t>(s.x0));
    mix(std::bit_cast<std::uint32_t>(s.z0));
    mix(std::bit_cast<std::uint32_t>(s.cell));
    mix(std::bit_cast<std::uint32_t>(s.unit_height));
    mix(s.base_level.size());
    mix(s.base_version); // a cover's base follows its geometry
    const std::size_t n = s.snow.size();
    std::size_t i = 0;
    for (; i + 1 < n; i += 2) {
        mix(static_cast<std::uint64_t>(s.snow[i]) |
            (static_cast<std::uint64_t>(s.snow[i + 1]) << 32));
    }
    if (i < n) {
        mix(s.snow[i]);
    }
    return h;
}

} // namespace snow
