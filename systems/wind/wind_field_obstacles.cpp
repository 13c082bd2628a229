// wind field obstacles: the grid cells colliders fill. Boxes cover the cells
// between their faces rounded to the nearest cell face, spheres the cells
// whose centres they contain, meshes the cells their triangles pass through
// (a shell: air cannot cross it). A collider thinner than a cell still fills
// one, so a fence blocks the wind. The ground surfaces fill the columns under
// them, and air that no open side reaches (inside a closed building) is
// filled too (docs/wind_field.md "Obstacles").
#include "systems/geometry/colliders.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/fence_resistance.hpp"
#include "systems/wind/wind_field_solver.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// Cells [lo, hi) along one axis.
struct CellRange {
    std::int32_t lo = 0, hi = 0;
};

/// The cells that world interval [a, b] covers along an axis of n cells:
/// its ends rounded to the nearest face, or the one cell holding its middle
/// when that rounds to nothing; clipped to the grid.
CellRange cover(double a, double b, double origin, double inv_cell, std::int32_t n) {
    const double ga = (a - origin) * inv_cell, gb = (b - origin) * inv_cell;
    double lo = std::floor(ga + 0.5), hi = std::floor(gb + 0.5);
    if (hi <= lo) {
        lo = std::floor(0.5 * (ga + gb));
        hi = lo + 1.0;
    }
    const double top = n;
    return {static_cast<std::int32_t>(std::clamp(lo, 0.0, top)),
            static_cast<std::int32_t>(std::clamp(hi, 0.0, top))};
}

/// Grid cell (cell coordinates) holding world point p; false outside.
bool cell_of(const WindField& f, const glm::vec3& p, std::int32_t (&cell)[3]) {
    for (int a = 0; a < 3; ++a) {
        const double g = (static_cast<double>(p[a]) - f.origin[a]) * f.inv_cell[a];
        if (!(g >= 0.0 && g < static_cast<double>(f.n[a]))) {
            return false;
        }
        cell[a] = static_cast<std::int32_t>(g);
    }
    return true;
}

struct Marker {
    const WindField& f;
    Vector<std::uint8_t>& solid;
    Vector<float>& resistance;
    /// Triangle samples left: 64 per field cell bounds the work of any mesh
    /// (bounded work, docs/reliability.md). Meshes that would need more (a
    /// fuzz finding: 16 384 kilometre-wide triangles took minutes) mark what
    /// their first samples reach, in mesh order.
    std::uint64_t samples_left = 64 * std::uint64_t{f.n[0]} * f.n[1] * f.n[2];
    /// Triangle samples lie closer together than half the smallest cell edge.
    float spacing = 0.5f / std::max({f.inv_cell.x, f.inv_cell.y, f.inv_cell.z});
    /// Most steps along a triangle's longest edge: about the field's diagonal.
    float max_steps =
        2.0f * std::sqrt(static_cast<float>(f.n[0] * f.n[0] + f.n[1] * f.n[1] + f.n[2] * f.n[2])) +
        2.0f;

    /// Index in the centre lattice (ghosts included) of grid cell (i, j, k).
    [[nodiscard]] std::size_t at(std::int32_t i, std::int32_t j, std::int32_t k) const {
        return static_cast<std::size_t>(f.centre.index(i + 1, j + 1, k + 1));
    }
    void mark(std::int32_t i, std::int32_t j, std::int32_t k) { solid[at(i, j, k)] = 1; }
    [[nodiscard]] CellRange range(int a, float lo, float hi) const {
        return cover(lo, hi, f.origin[a], f.inv_cell[a], static_cast<std::int32_t>(f.n[a]));
    }

    /// A solid box fills its cells; a porous one (a fence) lets air through
    /// them against its pressure loss.
    void box(const BoxCollider& c) {
        const Aabb& b = c.box;
        const auto loss =
            static_cast<float>(c.porosity > 0.0f ? fence_pressure_loss(c.porosity) : 0.0);
        const CellRange x = range(0, b.min.x, b.max.x), y = range(1, b.min.y, b.max.y),
                        z = range(2, b.min.z, b.max.z);
        for (std::int32_t k = z.lo; k < z.hi; ++k) {
            for (std::int32_t j = y.lo; j < y.hi; ++j) {
                for (std::int32_t i = x.lo; i < x.hi; ++i) {
                    if (loss > 0.0f) {
                        resistance[at(i, j, k)] = std::max(resistance[at(i, j, k)], loss);
                    } else {
                        mark(i, j, k);
                    }
                }
            }
        }
    }

    void sphere(const SphereCollider& s) {
        const CellRange x = range(0, s.center.x - s.radius, s.center.x + s.radius);
        const CellRange y = range(1, s.center.y - s.radius, s.center.y + s.radius);
        const CellRange z = range(2, s.center.z - s.radius, s.center.z + s.radius);
        const double r2 = static_cast<double>(s.radius) * s.radius;
        const auto centre = [&](int a, std::int32_t i) {
            return f.origin[a] + (i + 0.5) / f.inv_cell[a] - s.center[a];
        };
        for (std::int32_t k = z.lo; k < z.hi; ++k) {
            for (std::int32_t j = y.lo; j < y.hi; ++j) {
                for (std::int32_t i = x.lo; i < x.hi; ++i) {
                    const double dx = centre(0, i), dy = centre(1, j), dz = centre(2, k);
                    if (dx * dx + dy * dy + dz * dz <= r2) {
                        mark(i, j, k);
                    }
                }
            }
        }
        std::int32_t c[3];
        if (cell_of(f, s.center, c)) {
            mark(c[0], c[1], c[2]); // a sphere smaller than a cell still blocks one
        }
    }

    /// Points on the triangle closer together than half the smallest cell
    /// edge: consecutive points fall in the same or touching cells, so the
    /// marked cells form a surface air cannot pass between. A triangle with
    /// an edge longer than the field's diagonal is split at its edges'
    /// midpoints, and parts whose box misses the field are dropped, so the
    /// work stays near the field's size whatever the triangle's (a fuzz
    /// finding: kilometre-sized triangles took minutes).
    void triangle(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, int depth = 0) {
        constexpr int max_depth = 160; // halvings from the largest float to any cell
        if (samples_left == 0) {
            return;
        }
        for (int a = 0; a < 3; ++a) {
            const double lo = std::min({p0[a], p1[a], p2[a]}), hi = std::max({p0[a], p1[a], p2[a]});
            const double cell = 1.0 / f.inv_cell[a];
            if (hi < f.origin[a] - cell || lo > f.origin[a] + (f.n[a] + 1) * cell) {
                return;
            }
        }
        const glm::vec3 e1 = p1 - p0, e2 = p2 - p0, e3 = p2 - p1;
        const auto length = [](const glm::vec3& e) {
            return std::sqrt(e.x * e.x + e.y * e.y + e.z * e.z);
        };
        const float steps = std::ceil(std::max({length(e1), length(e2), length(e3)}) / spacing);
        if (!(steps <= max_steps) && depth < max_depth) {
            // Halves first: the sum of two large coordinates may overflow.
            const glm::vec3 m01 = 0.5f * p0 + 0.5f * p1, m02 = 0.5f * p0 + 0.5f * p2,
                            m12 = 0.5f * p1 + 0.5f * p2;
            triangle(p0, m01, m02, depth + 1);
            triangle(m01, p1, m12, depth + 1);
            triangle(m02, m12, p2, depth + 1);
            triangle(m01, m12, m02, depth + 1);
            return;
        }
        // Clamped as a float: inf or NaN converted to an integer is undefined.
        const std::int32_t n =
            steps >= 1.0f ? static_cast<std::int32_t>(std::min(steps, max_steps)) : 1;
        const std::uint64_t samples = (std::uint64_t(n) + 1) * (std::uint64_t(n) + 2) / 2;
        if (samples > samples_left) {
            samples_left = 0;
            return;
        }
        samples_left -= samples;
        for (std::int32_t a = 0; a <= n; ++a) {
            for (std::int32_t b = 0; a + b <= n; ++b) {
                const float s = static_cast<float>(a) / n, t = static_cast<float>(b) / n;
                std::int32_t c[3];
                if (cell_of(f, p0 + s * e1 + t * e2, c)) {
                    mark(c[0], c[1], c[2]);
                }
            }
        }
    }
};

/// Fills each column under a ground surface with the ground_columns() the
/// solver holds.
void fill_ground(const WindField& f, WindFieldSolver& s) {
    const auto nx = static_cast<std::int32_t>(f.n[0]), nz = static_cast<std::int32_t>(f.n[2]);
    for (std::int32_t k = 0; k < nz; ++k) {
        for (std::int32_t i = 0; i < nx; ++i) {
            for (std::int32_t j = 0; j < s.ground_cells[static_cast<std::size_t>(k * nx + i)];
                 ++j) {
                s.solid[static_cast<std::size_t>(f.centre.index(i + 1, j + 1, k + 1))] = 1;
            }
        }
    }
}

/// Turns air that no open side (x, z unless walls, or the top) reaches through air into
/// solid: inside a closed mesh building, or walls standing on the ground all
/// round. There the projection could never clear the gust shift it is given
/// (docs/wind_field.md "The solver"), and no wind belongs.
void fill_enclosed(const WindField& f, WindFieldSolver& s) {
    constexpr std::uint8_t air = 0, reached = 2;
    const Lattice& c = f.centre;
    Vector<std::uint8_t>& m = s.solid;
    const auto is_ghost = [&](std::int32_t i, std::int32_t j, std::int32_t k) {
        return i == 0 || j == 0 || k == 0 || i == c.dim[0] - 1 || j == c.dim[1] - 1 ||
               k == c.dim[2] - 1;
    };
    s.reach.clear();
    for (std::int32_t k = 0; k < c.dim[2]; ++k) {
        for (std::int32_t j = 0; j < c.dim[1]; ++j) {
            for (std::int32_t i = 0; i < c.dim[0]; ++i) {
                const std::int32_t q = c.index(i, j, k);
                if (is_ghost(i, j, k)) {
                    m[static_cast<std::size_t>(q)] = reached; // never entered, air again below
                } else if (m[static_cast<std::size_t>(q)] == air &&
                           (i == 1 || i == c.dim[0] - 2 || j == c.dim[1] - 2 ||
                            (!f.def.tunnel && (k == 1 || k == c.dim[2] - 2)))) {
                    m[static_cast<std::size_t>(q)] = reached;
                    s.reach.push_back(q);
                }
            }
        }
    }
    while (!s.reach.empty()) {
        const std::int32_t q = s.reach.back();
        s.reach.pop_back();
        for (int a = 0; a < 3; ++a) {
            for (const std::int32_t r : {q - c.stride(a), q + c.stride(a)}) {
                if (m[static_cast<std::size_t>(r)] == air) {
                    m[static_cast<std::size_t>(r)] = reached;
                    s.reach.push_back(r);
                }
            }
        }
    }
    for (auto& cell : m) {
        cell = cell == reached ? 0 : 1;
    }
}

} // namespace

void ground_columns(const World& w, const WindField& f, Vector<std::int32_t>& filled) {
    const auto nx = static_cast<std::int32_t>(f.n[0]), ny = static_cast<std::int32_t>(f.n[1]),
               nz = static_cast<std::int32_t>(f.n[2]);
    filled.assign(static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz), 0);
    w.each<SnowSurface, SurfaceOf>([&](Entity, const SnowSurface& g, const SurfaceOf& of) {
        if (!of.owner.is_null()) {
            return;
        }
        for (std::int32_t k = 0; k < nz; ++k) {
            for (std::int32_t i = 0; i < nx; ++i) {
                const float x = f.origin.x + (static_cast<float>(i) + 0.5f) / f.inv_cell.x;
                const float z = f.origin.z + (static_cast<float>(k) + 0.5f) / f.inv_cell.z;
                std::uint32_t ix = 0, iz = 0;
                if (!g.cell_at(x, z, ix, iz) || g.is_void(g.index(ix, iz))) {
                    continue;
                }
                const double top = g.top_y(g.index(ix, iz));
                const double cells = std::floor((top - f.origin.y) * f.inv_cell.y + 0.5);
                auto& column = filled[static_cast<std::size_t>(k * nx + i)];
                column =
                    std::max(column, static_cast<std::int32_t>(std::clamp(cells, 0.0, 1.0 * ny)));
            }
        }
    });
}

bool ground_moved(const World& w, const WindField& f, WindFieldSolver& s) {
    ground_columns(w, f, s.ground_now);
    return s.ground_now != s.ground_cells;
}

void mark_obstacles(const World& w, const WindField& f, WindFieldSolver& s) {
    s.solid.assign(f.centre.size(), 0);
    s.resistance.assign(f.centre.size(), 0.0f);
    Marker m{f, s.solid, s.resistance};
    w.each<BoxCollider>([&](Entity, const BoxCollider& b) { m.box(b); });
    w.each<SphereCollider>([&](Entity, const SphereCollider& s) { m.sphere(s); });
    w.each<MeshCollider>([&](Entity, const MeshCollider& mesh) {
        for (std::size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
            m.triangle(mesh.triangles[t], mesh.triangles[t + 1], mesh.triangles[t + 2]);
        }
    });
    ground_columns(w, f, s.ground_cells);
    fill_ground(f, s);
    fill_enclosed(f, s);
}

} // namespace snow
