// wind field: stable fluids [STAM] on a MAC grid. Per step: semi-Lagrangian
// advection of each face velocity (trace back along the cell-centre
// velocity, read trilinearly), then projection: the divergence, a fixed
// number of red-black SOR sweeps on the pressure Poisson equation (warm
// started from the last step), and the gradient subtracted. A fixed count and
// a colour order that no thread count changes keep results bit-identical.
//
// Boundaries: the floor is a wall (no flow through it, air slides along it);
// sides the global wind blows in through hold the wind on their faces and in
// their ghosts (pressure: no flux through them); all other sides and the top
// are open (pressure 0, velocity extrapolated). Faces touching a solid cell
// hold zero velocity, so air inside and along obstacles is still: the
// semi-Lagrangian trace reads that stillness into the cells behind them.
#include "systems/wind_field.hpp"

#include "systems/wind_field_solver.hpp"

#include <cmath>
#include <utility>

namespace snow {

namespace {

/// Sweeps a first step gives the projection of the uniform inflow: it
/// starts from nothing, later steps from the last pressure.
constexpr std::uint32_t initial_sweeps = 256;
/// Over-relaxation of the sweeps: converges the smooth error several times
/// faster than Gauss-Seidel (1.0) and stays clear of the 2.0 limit.
constexpr float sor_omega = 1.7f;
/// Most explicit diffusion parts one step takes (see mixing()).
constexpr std::uint32_t max_mixing_parts = 8;

/// First and last index of the samples a step updates along `axis`: all
/// faces along a face axis, the cells without ghosts along a centre axis.
std::int32_t first(const Lattice& l, int axis) {
    return l.shift[axis] > 0.0f ? 1 : 0;
}
std::int32_t end(const Lattice& l, int axis) {
    return l.dim[axis] - first(l, axis); // one past the last
}

/// Calls row(base, j, k) for every updated row of `l` (base = index(0, j, k)).
template <typename Row>
void each_row(const Lattice& l, Row&& row) {
    for (std::int32_t k = first(l, 2); k < end(l, 2); ++k) {
        for (std::int32_t j = first(l, 1); j < end(l, 1); ++j) {
            row(l.index(0, j, k), j, k);
        }
    }
}

bool inflow_low(std::uint8_t sides, int axis) {
    return axis == 0 ? (sides & inflow_x_min) != 0 : axis == 2 && (sides & inflow_z_min) != 0;
}
bool inflow_high(std::uint8_t sides, int axis) {
    return axis == 0 ? (sides & inflow_x_max) != 0 : axis == 2 && (sides & inflow_z_max) != 0;
}

/// Calls fn(index) for every sample of `l` whose index along `axis` is `at`.
template <typename Fn>
void each_in_plane(const Lattice& l, int axis, std::int32_t at, Fn&& fn) {
    const int a1 = axis == 0 ? 1 : 0, a2 = axis == 2 ? 1 : 2;
    const std::int32_t offset = at * l.stride(axis);
    for (std::int32_t q = 0; q < l.dim[a2]; ++q) {
        for (std::int32_t r = 0; r < l.dim[a1]; ++r) {
            fn(offset + r * l.stride(a1) + q * l.stride(a2));
        }
    }
}

/// Ghost layers of one velocity component (`inflow`: its global value):
/// the wind on inflow sides, the neighbouring sample elsewhere (open sides
/// extrapolate; the floor lets air slide).
void fill_ghosts(std::vector<float>& d, const Lattice& l, float inflow, std::uint8_t sides) {
    for (int axis = 0; axis < 3; ++axis) {
        if (first(l, axis) == 0) {
            continue; // a face axis has no ghosts
        }
        const std::int32_t s = l.stride(axis), top = l.dim[axis] - 1;
        const bool lo_in = inflow_low(sides, axis), hi_in = inflow_high(sides, axis);
        each_in_plane(l, axis, 0, [&](std::int32_t i) { d[i] = lo_in ? inflow : d[i + s]; });
        each_in_plane(l, axis, top, [&](std::int32_t i) { d[i] = hi_in ? inflow : d[i - s]; });
    }
}

/// Inflow faces hold the wind, floor faces zero, faces at obstacles zero.
void enforce(WindField& f, const WindFieldSolver& s, const glm::vec3& inflow, std::uint8_t sides) {
    for (int a = 0; a < 3; ++a) {
        std::vector<float>& v = f.velocity[a];
        const Lattice& l = f.face[a];
        const std::int32_t top = l.dim[a] - 1;
        if (a == 1) {
            each_in_plane(l, a, 0, [&](std::int32_t i) { v[i] = 0.0f; });
        }
        if (inflow_low(sides, a)) {
            each_in_plane(l, a, 0, [&](std::int32_t i) { v[i] = inflow[a]; });
        }
        if (inflow_high(sides, a)) {
            each_in_plane(l, a, top, [&](std::int32_t i) { v[i] = inflow[a]; });
        }
        for (const std::int32_t i : s.closed[a]) {
            v[static_cast<std::size_t>(i)] = 0.0f;
        }
    }
}

/// New values of component `a` at its faces: each face traces back along the
/// mean of the two cell-centre velocities beside it and reads the old
/// component there [STAM §3.2].
void advect(const WindField& f, int a, const std::vector<float>& src, std::vector<float>& dst,
            float dt) {
    const Lattice l = f.face[a]; // copies: no store in the loop can change them
    const Lattice& c = f.centre;
    const float* cu = f.at_centre[0].data();
    const float* cv = f.at_centre[1].data();
    const float* cw = f.at_centre[2].data();
    const float* s = src.data();
    float* d = dst.data();
    const std::int32_t up = c.stride(a);
    const float kx = dt * f.inv_cell.x, ky = dt * f.inv_cell.y, kz = dt * f.inv_cell.z;
    const float nx = static_cast<float>(f.n[0]), ny = static_cast<float>(f.n[1]),
                nz = static_cast<float>(f.n[2]);
    const std::int32_t i0 = first(l, 0), i1 = end(l, 0);
    const float sx = l.shift[0];
    each_row(l, [&](std::int32_t row, std::int32_t j, std::int32_t k) {
        const float y = static_cast<float>(j) - l.shift[1];
        const float z = static_cast<float>(k) - l.shift[2];
        // The centre cell below the face along a has this row's (j, k) and i.
        const std::int32_t below = c.index(0, j, k);
        // src, dst and the centre arrays are distinct: ivdep lets the reads
        // at the traced points become gathers.
#if defined(__GNUC__) && !defined(__clang__) // Clang has no ivdep; it vectorises without
#pragma GCC ivdep
#endif
        for (std::int32_t i = i0; i < i1; ++i) {
            const std::int32_t lo = below + i, hi = lo + up;
            const float x = static_cast<float>(i) - sx;
            const float bx = clamp_value(x - kx * (0.5f * (cu[lo] + cu[hi])), 0.0f, nx);
            const float by = clamp_value(y - ky * (0.5f * (cv[lo] + cv[hi])), 0.0f, ny);
            const float bz = clamp_value(z - kz * (0.5f * (cw[lo] + cw[hi])), 0.0f, nz);
            d[row + i] = trilinear(s, l, locate(l, bx, by, bz));
        }
    });
}

/// How one step mixes: explicit diffusion in `parts` equal parts of weight
/// ν·dt/parts/h² per axis.
struct Mixing {
    std::uint32_t parts = 0;
    float weight[3] = {0.0f, 0.0f, 0.0f};
};

/// Parts enough that each keeps the stencil's centre weight at least 0.1
/// (positive weights: stable, no new extremes); past max_mixing_parts the
/// viscosity is cut to what that many parts carry.
Mixing mixing(const WindField& f, float dt) {
    Mixing m;
    const float nu_dt = f.def.eddy_viscosity * dt;
    const glm::vec3 k = nu_dt * f.inv_cell * f.inv_cell; // ν·dt/h² per axis
    const float load = 2.0f * (k.x + k.y + k.z);         // 1 − centre weight of one full step
    if (!(load > 0.0f)) {
        return m;
    }
    const float wanted = std::ceil(load / 0.9f);
    m.parts = static_cast<std::uint32_t>(std::min(wanted, static_cast<float>(max_mixing_parts)));
    const float scale = wanted > static_cast<float>(m.parts) ? 0.9f / load : 1.0f / m.parts;
    for (int a = 0; a < 3; ++a) {
        m.weight[a] = k[a] * scale;
    }
    return m;
}

/// v += ν·dt·∇²v on the faces with a neighbour on every side (the rest are
/// reset or extrapolated anyway), in m.parts explicit parts [STAM §3.3 does
/// this implicitly; within the limit explicit is cheaper]. Each part writes
/// `tmp` from v, copies the faces it does not update and swaps the two.
void diffuse(const WindField& f, int a, std::vector<float>& v, std::vector<float>& tmp,
             const Mixing& m) {
    const Lattice l = f.face[a];
    const std::int32_t sy = l.stride(1), sz = l.stride(2);
    const float lx = m.weight[0], ly = m.weight[1], lz = m.weight[2];
    const float centre = 1.0f - 2.0f * (lx + ly + lz);
    const std::int32_t last_x = l.dim[0] - 1, last_y = l.dim[1] - 1, last_z = l.dim[2] - 1;
    // Index 1 .. dim - 2 on every axis: the inner faces along the face axis,
    // the cells between the ghosts along the others.
    for (std::uint32_t part = 0; part < m.parts; ++part) {
        const float* s = v.data();
        float* d = tmp.data();
        const auto keep = [&](std::int32_t from, std::int32_t count) {
            std::copy(s + from, s + from + count, d + from);
        };
        keep(0, sz);           // the first plane
        keep(last_z * sz, sz); // the last
        for (std::int32_t k = 1; k < last_z; ++k) {
            keep(l.index(0, 0, k), sy);      // its first row
            keep(l.index(0, last_y, k), sy); // its last
            for (std::int32_t j = 1; j < last_y; ++j) {
                const std::int32_t row = l.index(0, j, k);
                d[row] = s[row];
                d[row + last_x] = s[row + last_x];
                for (std::int32_t i = 1; i < last_x; ++i) {
                    const std::int32_t q = row + i;
                    d[q] = centre * s[q] + lx * (s[q - 1] + s[q + 1]) +
                           ly * (s[q - sy] + s[q + sy]) + lz * (s[q - sz] + s[q + sz]);
                }
            }
        }
        std::swap(v, tmp);
    }
}

/// ∇·u per open cell (1/s), from its six faces.
void divergence(const WindField& f, std::vector<float>& out) {
    const Lattice& c = f.centre;
    const float* u = f.velocity[0].data();
    const float* v = f.velocity[1].data();
    const float* w = f.velocity[2].data();
    const float ix = f.inv_cell.x, iy = f.inv_cell.y, iz = f.inv_cell.z;
    float* d = out.data();
    const std::int32_t i1 = end(c, 0);
    each_row(c, [&](std::int32_t row, std::int32_t j, std::int32_t k) {
        const std::int32_t ur = f.face[0].index(0, j, k);
        const std::int32_t vt = f.face[1].index(0, j, k), vb = f.face[1].index(0, j - 1, k);
        const std::int32_t wf = f.face[2].index(0, j, k), wb = f.face[2].index(0, j, k - 1);
        for (std::int32_t i = 1; i < i1; ++i) {
            d[row + i] = (u[ur + i] - u[ur + i - 1]) * ix + (v[vt + i] - v[vb + i]) * iy +
                         (w[wf + i] - w[wb + i]) * iz;
        }
    });
}

/// Red-black SOR on Σ c_a (φ_nb − φ) = div over the open cells. Solid cells
/// and ghosts hold φ = 0; a neighbour with no flux through the face between
/// (solid, floor, inflow side) is left out of inv_diag, so its 0 adds nothing.
struct Sweeper {
    const Lattice& c;
    float* p;
    const float* rhs;
    const float* inv;
    const std::vector<float>* omega_planes; ///< [2]
    float* out;                             ///< one plane
    float cx, cy, cz;

    /// One colour over plane k (padded index), as one contiguous run from
    /// its first open cell to its last (so it vectorises with few loop
    /// starts), into a plane buffer: ω in the lanes of the colour, 0 in the
    /// others and in the ghost columns the run crosses. Those compute
    /// φ + 0·(…) = φ, bit for bit (φ is never −0: it starts at +0, and x + y
    /// is −0 only when both are). The lanes of the colour read only the
    /// other colour, so this is the strided red-black update, exactly.
    void plane(std::int32_t k, std::int32_t colour) const {
        const std::int32_t sy = c.stride(1), sz = c.stride(2);
        const std::int32_t first_cell = c.index(1, 1, 0),
                           last_cell = c.index(c.dim[0] - 2, c.dim[1] - 2, 0);
        const std::int32_t base = k * sz;
        const float* omega = omega_planes[(k + colour) & 1].data();
        const float* at = p + base;
        const float* r = rhs + base;
        const float* d = inv + base;
        for (std::int32_t i = first_cell; i <= last_cell; ++i) {
            const float sum = cx * (at[i - 1] + at[i + 1]) + cy * (at[i - sy] + at[i + sy]) +
                              cz * (at[i - sz] + at[i + sz]);
            out[i] = at[i] + omega[i] * (d[i] * (sum - r[i]) - at[i]);
        }
        std::copy(out + first_cell, out + last_cell + 1, p + base + first_cell);
    }
};

/// `sweeps` red-black sweeps, pipelined along z so the pressure passes
/// through the cache once instead of twice per sweep: at front K, sweep s
/// updates colour 0 of plane K − 2s, then colour 1 of plane K − 2s − 1. Every
/// update then reads exactly the values the plain order (all of colour 0,
/// then all of colour 1, sweep after sweep) gives it: colour 0 of plane k
/// needs sweep s − 1's colour 1 on planes k ± 1 (done at this front or
/// before) and not yet sweep s's (done later); colour 1 of plane k needs
/// sweep s's colour 0 on planes k ± 1 (done at this front or before).
void pressure_sweeps(WindField& f, WindFieldSolver& s, std::uint32_t sweeps) {
    const Sweeper w{f.centre,
                    f.pressure.data(),
                    s.divergence.data(),
                    s.inv_diag.data(),
                    s.omega_planes,
                    s.plane.data(),
                    f.inv_cell.x * f.inv_cell.x,
                    f.inv_cell.y * f.inv_cell.y,
                    f.inv_cell.z * f.inv_cell.z};
    const auto depth = static_cast<std::int32_t>(sweeps);
    const std::int32_t planes = end(f.centre, 2); // planes 1 .. planes - 1
    for (std::int32_t front = 1; front < planes + 2 * depth; ++front) {
        for (std::int32_t sweep = 0; sweep < depth; ++sweep) {
            const std::int32_t k = front - 2 * sweep;
            if (k >= 1 && k < planes) {
                w.plane(k, 0);
            }
            if (k - 1 >= 1 && k - 1 < planes) {
                w.plane(k - 1, 1);
            }
        }
    }
}

/// u −= ∇φ on every face the sweeps' φ reaches (inflow and wall faces are
/// reset by enforce afterwards).
void subtract_gradient(WindField& f) {
    const Lattice& c = f.centre;
    const float* p = f.pressure.data();
    for (int a = 0; a < 3; ++a) {
        const Lattice& l = f.face[a];
        float* v = f.velocity[a].data();
        const std::int32_t up = c.stride(a), i0 = first(l, 0), i1 = end(l, 0);
        const float ih = f.inv_cell[a];
        each_row(l, [&](std::int32_t row, std::int32_t j, std::int32_t k) {
            const std::int32_t below = c.index(0, j, k);
            for (std::int32_t i = i0; i < i1; ++i) {
                v[row + i] -= (p[below + i + up] - p[below + i]) * ih;
            }
        });
    }
}

/// Cell-centre velocity: the mean of each cell's two faces per component.
void centre_velocity(WindField& f, const glm::vec3& inflow, std::uint8_t sides) {
    const Lattice& c = f.centre;
    const std::int32_t i1 = end(c, 0);
    for (int a = 0; a < 3; ++a) {
        const Lattice& l = f.face[a];
        const float* v = f.velocity[a].data();
        float* out = f.at_centre[a].data();
        const std::int32_t down = l.stride(a);
        each_row(c, [&](std::int32_t row, std::int32_t j, std::int32_t k) {
            const std::int32_t upper = l.index(0, j, k);
            for (std::int32_t i = 1; i < i1; ++i) {
                out[row + i] = 0.5f * (v[upper + i] + v[upper + i - down]);
            }
        });
        fill_ghosts(f.at_centre[a], c, inflow[a], sides);
    }
}

void build_inv_diag(const WindField& f, WindFieldSolver& s, std::uint8_t sides) {
    const Lattice& c = f.centre;
    s.inv_diag.assign(c.size(), 0.0f);
    const std::int32_t i1 = end(c, 0);
    each_row(c, [&](std::int32_t row, std::int32_t j, std::int32_t k) {
        const std::int32_t at[3] = {0, j, k};
        for (std::int32_t i = 1; i < i1; ++i) {
            const std::int32_t q = row + i;
            if (s.solid[q] != 0) {
                continue;
            }
            float sum = 0.0f;
            for (int a = 0; a < 3; ++a) {
                const std::int32_t pos = a == 0 ? i : at[a];
                const float coefficient = f.inv_cell[a] * f.inv_cell[a];
                // Below the first cell is the floor (a wall); past the others
                // an inflow side (no flux) or open air (φ = 0, counted).
                const bool lo_wall = pos == 1 && (a == 1 || inflow_low(sides, a));
                const bool hi_wall = pos == c.dim[a] - 2 && inflow_high(sides, a);
                if (!lo_wall && s.solid[q - c.stride(a)] == 0) {
                    sum += coefficient;
                }
                if (!hi_wall && s.solid[q + c.stride(a)] == 0) {
                    sum += coefficient;
                }
            }
            s.inv_diag[q] = sum > 0.0f ? 1.0f / sum : 0.0f;
        }
    });
    s.diag_sides = sides;
    // ω where (i + j + parity) is odd in the cells of a plane, 0 elsewhere.
    const std::size_t plane =
        static_cast<std::size_t>(c.dim[0]) * static_cast<std::size_t>(c.dim[1]);
    s.plane.assign(plane, 0.0f);
    for (int parity = 0; parity < 2; ++parity) {
        s.omega_planes[parity].assign(plane, 0.0f);
        for (std::int32_t j = 1; j < end(c, 1); ++j) {
            for (std::int32_t i = 1; i < end(c, 0); ++i) {
                const bool colour = ((i + j + parity) & 1) != 0;
                s.omega_planes[parity][static_cast<std::size_t>(c.index(i, j, 0))] =
                    colour ? sor_omega : 0.0f;
            }
        }
    }
}

/// Adds a change of the inflow to the whole field. Incompressible air
/// answers a change at the inflow at once everywhere, and a uniform change
/// has no divergence, so the sweeps are left only the obstacles' share of it
/// (without this, every gust would be a domain-wide error that a fixed
/// number of sweeps, which carry information a few cells each, cannot clear).
void shift(WindField& f, const glm::vec3& change) {
    for (int a = 0; a < 3; ++a) {
        // A copy: through the reference every store could change it, and
        // the loop would not vectorise.
        const float by = change[a];
        if (by == 0.0f) {
            continue;
        }
        for (std::vector<float>* v : {&f.velocity[a], &f.at_centre[a]}) {
            for (float& x : *v) {
                x += by;
            }
        }
    }
}

void project(WindField& f, WindFieldSolver& s, const glm::vec3& inflow, std::uint8_t sides,
             std::uint32_t sweeps) {
    divergence(f, s.divergence);
    pressure_sweeps(f, s, sweeps);
    subtract_gradient(f);
    enforce(f, s, inflow, sides);
}

} // namespace

Lattice Lattice::make(const std::uint32_t (&n)[3], int face_axis) {
    Lattice l;
    for (int a = 0; a < 3; ++a) {
        const auto cells = static_cast<std::int32_t>(n[a]);
        const bool on_faces = a == face_axis;
        l.dim[a] = on_faces ? cells + 1 : cells + 2;
        l.shift[a] = on_faces ? 0.0f : 0.5f;
        l.last[a] = on_faces ? cells - 1 : cells;
    }
    return l;
}

WindField make_wind_field(const WindFieldDef& def, const Aabb& bounds) {
    WindField f;
    f.def = def;
    f.n[0] = def.cells_x;
    f.n[1] = def.cells_y;
    f.n[2] = def.cells_z;
    f.origin = bounds.min;
    const glm::vec3 size = bounds.size();
    for (int a = 0; a < 3; ++a) {
        f.inv_cell[a] = static_cast<float>(f.n[a]) / size[a];
        f.face[a] = Lattice::make(f.n, a);
        f.velocity[a].assign(f.face[a].size(), 0.0f);
    }
    f.centre = Lattice::make(f.n, 3);
    f.pressure.assign(f.centre.size(), 0.0f);
    for (auto& c : f.at_centre) {
        c.assign(f.centre.size(), 0.0f);
    }
    return f;
}

std::uint8_t inflow_sides(const glm::vec3& wind) {
    std::uint8_t s = 0;
    s |= wind.x > 0.0f ? inflow_x_min : 0;
    s |= wind.x < 0.0f ? inflow_x_max : 0;
    s |= wind.z > 0.0f ? inflow_z_min : 0;
    s |= wind.z < 0.0f ? inflow_z_max : 0;
    return s;
}

void apply_obstacles(WindField& f, WindFieldSolver& s) {
    const Lattice& c = f.centre;
    for (int a = 0; a < 3; ++a) {
        const Lattice& l = f.face[a];
        s.closed[a].clear();
        s.advected[a].assign(l.size(), 0.0f);
        const std::int32_t up = c.stride(a);
        for (std::int32_t k = 0; k < l.dim[2]; ++k) {
            for (std::int32_t j = 0; j < l.dim[1]; ++j) {
                const std::int32_t row = l.index(0, j, k), below = c.index(0, j, k);
                for (std::int32_t i = 0; i < l.dim[0]; ++i) {
                    const bool shut = s.solid[below + i] != 0 || s.solid[below + i + up] != 0;
                    if (shut) {
                        s.closed[a].push_back(row + i);
                        f.velocity[a][static_cast<std::size_t>(row + i)] = 0.0f;
                    }
                }
            }
        }
    }
    s.divergence.assign(c.size(), 0.0f);
    s.diag_sides = 0xff; // rebuilt at the next step
}

void step_wind_field(WindField& f, WindFieldSolver& s, const glm::vec3& inflow, float dt) {
    const std::uint8_t sides = inflow_sides(inflow);
    if (s.diag_sides != sides) {
        build_inv_diag(f, s, sides);
    }
    if (f.steps == 0) {
        for (int a = 0; a < 3; ++a) {
            std::fill(f.velocity[a].begin(), f.velocity[a].end(), inflow[a]);
        }
        enforce(f, s, inflow, sides);
        project(f, s, inflow, sides, initial_sweeps);
    } else {
        shift(f, inflow - f.inflow);
        const Mixing mix = mixing(f, dt);
        for (int a = 0; a < 3; ++a) {
            advect(f, a, f.velocity[a], s.advected[a], dt);
            std::swap(f.velocity[a], s.advected[a]);
            fill_ghosts(f.velocity[a], f.face[a], inflow[a], sides); // diffusion reads them
            diffuse(f, a, f.velocity[a], s.advected[a], mix);
        }
        enforce(f, s, inflow, sides);
        project(f, s, inflow, sides, f.def.pressure_iterations);
    }
    for (int a = 0; a < 3; ++a) {
        fill_ghosts(f.velocity[a], f.face[a], inflow[a], sides);
    }
    centre_velocity(f, inflow, sides);
    f.inflow = inflow;
    ++f.steps;
}

double wind_field_divergence(const WindField& f, const WindFieldSolver& s) {
    std::vector<float> d(f.centre.size(), 0.0f);
    divergence(f, d);
    double sum = 0.0;
    std::size_t open = 0;
    each_row(f.centre, [&](std::int32_t row, std::int32_t, std::int32_t) {
        for (std::int32_t i = 1; i < end(f.centre, 0); ++i) {
            const auto q = static_cast<std::size_t>(row + i);
            if (s.solid[q] == 0) {
                sum += std::abs(static_cast<double>(d[q]));
                ++open;
            }
        }
    });
    return open > 0 ? sum / static_cast<double>(open) : 0.0;
}

} // namespace snow
