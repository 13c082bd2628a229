#include "game/export/snow_mesh.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <utility>

namespace snow {

namespace {

constexpr std::uint32_t no_vertex = ~0u;

bool holds_snow(const SnowSurface& s, std::size_t i) {
    return !s.is_void(i) && s.snow[i] > 0;
}

/// Side bits as in SnowSurface::closed: 0 -x, 1 +x, 2 -z, 3 +z; side ^ 1 faces back.
bool edge_open(const SnowSurface& s, std::size_t i, unsigned side) {
    return s.closed.empty() || (s.closed[i] & (1u << side)) == 0;
}

/// Cells i and j, neighbours across `side` of i, share one snow top.
bool joined(const SnowSurface& s, std::size_t i, std::size_t j, unsigned side) {
    return holds_snow(s, i) && holds_snow(s, j) && edge_open(s, i, side) &&
           edge_open(s, j, side ^ 1u);
}

/// The top's vertices: one per grid corner and patch meeting there.
/// Fills `corner_of` (4 per cell: corners -x-z, +x-z, -x+z, +x+z) and the
/// bare base under each vertex.
void top_vertices(const SnowSurface& s, SnowMesh& m, std::vector<std::uint32_t>& corner_of,
                  std::vector<float>& base_of) {
    corner_of.assign(s.cell_count() * 4, no_vertex);
    const std::size_t corners = static_cast<std::size_t>(s.nx + 1) * (s.nz + 1);
    m.positions.reserve(corners);
    base_of.reserve(corners);
    for (std::uint32_t cz = 0; cz <= s.nz; ++cz) {
        for (std::uint32_t cx = 0; cx <= s.nx; ++cx) {
            // Slots around the corner: 0 (-x-z), 1 (+x-z), 2 (-x+z), 3 (+x+z);
            // cx - 1 wraps past nx at the border, which is off the grid.
            std::size_t cell[4] = {};
            bool in[4] = {};
            int patch[4] = {0, 1, 2, 3};
            for (unsigned k = 0; k < 4; ++k) {
                const std::uint32_t x = cx - 1 + (k & 1u), z = cz - 1 + (k >> 1);
                in[k] = x < s.nx && z < s.nz && holds_snow(s, s.index(x, z));
                cell[k] = in[k] ? s.index(x, z) : 0;
            }
            const unsigned links[4][3] = {{0, 1, 1}, {2, 3, 1}, {0, 2, 3}, {1, 3, 3}};
            for (const auto& [a, b, side] : links) {
                if (in[a] && in[b] && joined(s, cell[a], cell[b], side)) {
                    const int from = patch[b];
                    for (int& p : patch) {
                        p = p == from ? patch[a] : p;
                    }
                }
            }
            for (unsigned k = 0; k < 4; ++k) {
                if (!in[k] || corner_of[cell[k] * 4 + (3 - k)] != no_vertex) {
                    continue;
                }
                float top = 0.0f, base = 0.0f;
                int n = 0;
                for (unsigned q = k; q < 4; ++q) {
                    if (in[q] && patch[q] == patch[k]) {
                        top += s.top_y(cell[q]);
                        base += s.height(s.base_level[cell[q]]);
                        ++n;
                    }
                }
                const auto v = static_cast<std::uint32_t>(m.positions.size());
                m.positions.push_back({s.x0 + static_cast<float>(cx) * s.cell,
                                       top / static_cast<float>(n),
                                       s.z0 + static_cast<float>(cz) * s.cell});
                base_of.push_back(base / static_cast<float>(n));
                // The cell in slot q has this grid corner as its corner 3 - q.
                for (unsigned q = k; q < 4; ++q) {
                    if (in[q] && patch[q] == patch[k]) {
                        corner_of[cell[q] * 4 + (3 - q)] = v;
                    }
                }
            }
        }
    }
}

/// One skirt triangle with its own vertices, wound to face `out`; none when degenerate.
void skirt_triangle(SnowMesh& m, glm::vec3 a, glm::vec3 b, glm::vec3 c, const glm::vec3& out) {
    const glm::vec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, n) <= 0.0f) {
        return;
    }
    if (glm::dot(n, out) < 0.0f) {
        std::swap(b, c);
    }
    for (const glm::vec3& p : {a, b, c}) {
        m.indices.push_back(static_cast<std::uint32_t>(m.positions.size()));
        m.positions.push_back(p);
        m.normals.push_back(out);
    }
}

} // namespace

SnowMesh build_snow_mesh(const SnowSurface& s) {
    SnowMesh m;
    std::vector<std::uint32_t> corner_of;
    std::vector<float> base_of;
    top_vertices(s, m, corner_of, base_of);
    // The top: two triangles per cell, counter-clockwise from +y; vertex
    // normals sum the area-weighted normals of the triangles around them.
    m.normals.assign(m.positions.size(), glm::vec3(0.0f));
    m.indices.reserve(s.cell_count() * 6);
    for (std::size_t i = 0; i < s.cell_count(); ++i) {
        if (!holds_snow(s, i)) {
            continue;
        }
        const std::uint32_t* c = &corner_of[i * 4];
        for (const auto& [p, q, r] : {std::array{c[0], c[2], c[1]}, std::array{c[1], c[2], c[3]}}) {
            const glm::vec3 n =
                glm::cross(m.positions[q] - m.positions[p], m.positions[r] - m.positions[p]);
            for (const std::uint32_t v : {p, q, r}) {
                m.normals[v] += n;
                m.indices.push_back(v);
            }
        }
    }
    for (glm::vec3& n : m.normals) {
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    // Skirts: down from the top to the base along every edge where the snow ends.
    const unsigned side_corners[4][2] = {{0, 2}, {1, 3}, {0, 1}, {2, 3}};
    const glm::vec3 side_out[4] = {{-1, 0, 0}, {1, 0, 0}, {0, 0, -1}, {0, 0, 1}};
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const std::size_t i = s.index(ix, iz);
            if (!holds_snow(s, i)) {
                continue;
            }
            const bool has[4] = {ix > 0, ix + 1 < s.nx, iz > 0, iz + 1 < s.nz};
            const std::size_t nb[4] = {i - 1, i + 1, i - s.nx, i + s.nx};
            for (unsigned side = 0; side < 4; ++side) {
                if (has[side] && joined(s, i, nb[side], side)) {
                    continue;
                }
                const std::uint32_t v0 = corner_of[i * 4 + side_corners[side][0]];
                const std::uint32_t v1 = corner_of[i * 4 + side_corners[side][1]];
                const glm::vec3 t0 = m.positions[v0], t1 = m.positions[v1];
                const glm::vec3 b0{t0.x, base_of[v0], t0.z}, b1{t1.x, base_of[v1], t1.z};
                skirt_triangle(m, t0, b0, t1, side_out[side]);
                skirt_triangle(m, t1, b0, b1, side_out[side]);
            }
        }
    }
    return m;
}

} // namespace snow
