// wind field: stable fluids [STAM] on a MAC grid. Per step: semi-Lagrangian
// advection of each face velocity (trace back along the cell-centre
// velocity, read trilinearly), then projection: the divergence, a fixed
// number of red-black SOR sweeps on the pressure Poisson equation (warm
// started from the last step), and the gradient subtracted. A fixed count and
// a colour order that no thread count changes keep results bit-identical.
//
// Boundaries: the floor is a wall (no flow through it, air slides along it);
// sides the global wind blows in through hold the wind on their faces and in
// their ghosts (pressure: no flux through them); a tunnel's z sides are walls
// as the floor is; all other sides and the top are open (pressure 0,
// velocity extrapolated). Faces touching a solid cell
// hold zero velocity, so air inside and along obstacles is still: the
// semi-Lagrangian trace reads that stillness into the cells behind them.
#include "systems/wind/wind_field_solver.hpp"

#include <algorithm>
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
/// Walls the air slides along: the floor, a tunnel's z sides.
bool wall_low(std::uint8_t sides, int axis) {
    return axis == 1 || (axis == 2 && (sides & walls_z) != 0);
}
bool wall_high(std::uint8_t sides, int axis) {
    return axis == 2 && (sides & walls_z) != 0;
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
void fill_ghosts(Vector<float>& d, const Lattice& l, float inflow, std::uint8_t sides) {
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

/// The ground is a wall the air slides along, as the floor is: the faces
/// along it in its top cells (between two columns the ground fills to the
/// same height) hold the air's above them, as the floor's ghosts do, so
/// diffusion and advection feel no drag there. A slower wind near the
/// ground would need a law (docs/wind_field.md "The ground").
void slide_over_ground(const WindField& f, const WindFieldSolver& s, int a, Vector<float>& v) {
    if (a == 1) {
        return;
    }
    const Lattice& l = f.face[a];
    const auto nx = static_cast<std::int32_t>(f.n[0]), nz = static_cast<std::int32_t>(f.n[2]);
    const auto filled = [&](std::int32_t i, std::int32_t k) {
        const bool in = i >= 0 && k >= 0 && i < nx && k < nz;
        return in ? s.ground_cells[static_cast<std::size_t>(k * nx + i)] : -1;
    };
    const std::int32_t up = l.stride(1);
    const std::int32_t faces = a == 0 ? nx + 1 : nz + 1, across = a == 0 ? nz : nx;
    for (std::int32_t c = 0; c < across; ++c) {
        for (std::int32_t e = 0; e < faces; ++e) {
            // The face's two columns along a (one of them off the grid at its ends).
            const std::int32_t lo = a == 0 ? filled(e - 1, c) : filled(c, e - 1);
            const std::int32_t hi = a == 0 ? filled(e, c) : filled(c, e);
            const std::int32_t h = lo < 0 ? hi : (hi < 0 ? lo : (lo == hi ? lo : 0));
            if (h > 0) {
                const std::int32_t q = a == 0 ? l.index(e, h, c + 1) : l.index(c + 1, h, e);
                v[static_cast<std::size_t>(q)] = v[static_cast<std::size_t>(q + up)];
            }
        }
    }
}

/// Inflow faces hold the wind, wall faces zero, faces at obstacles zero.
void enforce(WindField& f, const WindFieldSolver& s, const glm::vec3& inflow, std::uint8_t sides) {
    for (int a = 0; a < 3; ++a) {
        Vector<float>& v = f.velocity[a];
        const Lattice& l = f.face[a];
        const std::int32_t top = l.dim[a] - 1;
        if (wall_low(sides, a)) {
            each_in_plane(l, a, 0, [&](std::int32_t i) { v[i] = 0.0f; });
        }
        if (wall_high(sides, a)) {
            each_in_plane(l, a, top, [&](std::int32_t i) { v[i] = 0.0f; });
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

/// Reads of one advection: the face lattice, the centre velocities it traces
/// along, and the scale from m/s to cells per step. Plain values, so the
/// row loops that hold one vectorise.
struct Tracer {
    Lattice l;
    const float* cu;
    const float* cv;
    const float* cw;
    std::int32_t up;  ///< the centre lattice's stride along the face axis
    float kx, ky, kz; ///< dt / cell edge per axis
    float nx, ny, nz; ///< cells per axis

    /// Where face `i` of row (j, k), whose first centre cell below is
    /// `below`, traces back to [STAM §3.2]: back along the mean of the two
    /// cell-centre velocities beside it.
    [[gnu::always_inline]] LatticePoint at(std::int32_t i, std::int32_t j, std::int32_t k,
                                           std::int32_t below) const {
        const std::int32_t lo = below + i, hi = lo + up;
        const float x = static_cast<float>(i) - l.shift[0];
        const float y = static_cast<float>(j) - l.shift[1];
        const float z = static_cast<float>(k) - l.shift[2];
        const float bx = clamp_value(x - kx * (0.5f * (cu[lo] + cu[hi])), 0.0f, nx);
        const float by = clamp_value(y - ky * (0.5f * (cv[lo] + cv[hi])), 0.0f, ny);
        const float bz = clamp_value(z - kz * (0.5f * (cw[lo] + cw[hi])), 0.0f, nz);
        return locate(l, bx, by, bz);
    }
};

/// The lerp between two of three values: (a, b) when `back`, else (b, c);
/// the arithmetic of trilinear_corners.
[[gnu::always_inline]] inline float lerp_pick(float a, float b, float c, bool back, float t) {
    const float lo = back ? a : b, hi = back ? b : c;
    return lo + t * (hi - lo);
}

/// The lerp along x on one line of the source: between samples i − 1 and i
/// when `back`, else i and i + 1.
[[gnu::always_inline]] inline float lerp_line(const float* line, std::int32_t i, bool back,
                                              float t) {
    return lerp_pick(line[i - 1], line[i], line[i + 1], back, t);
}

/// Faces the advection reads in one vector loop: an AVX-512 register of
/// floats, two of AVX2.
constexpr std::int32_t advect_chunk = 16;

/// New values of component `a` at its faces: each face traces back along the
/// mean of the two cell-centre velocities beside it and reads the old
/// component there [STAM §3.2]. A trace shorter than a cell ends in a cell
/// whose corners lie among the 3 × 3 × 3 samples around the face, so the
/// read is done from contiguous loads of the nine lines around the row,
/// picking each lerp's ends by the trace's direction: the same corners and
/// the same arithmetic as trilinear(), without its gathers, which were half
/// a step (docs/wind_field.md "Cost"). A chunk holding a longer trace, rows
/// shorter than a chunk, and the first and last face of a face-axis row
/// (whose x neighbours lie outside it) are read by trilinear().
void advect(const WindField& f, int a, const Vector<float>& src, Vector<float>& dst, float dt) {
    const Lattice& c = f.centre;
    const Tracer tr{f.face[a],
                    f.at_centre[0].data(),
                    f.at_centre[1].data(),
                    f.at_centre[2].data(),
                    c.stride(a),
                    dt * f.inv_cell.x,
                    dt * f.inv_cell.y,
                    dt * f.inv_cell.z,
                    static_cast<float>(f.n[0]),
                    static_cast<float>(f.n[1]),
                    static_cast<float>(f.n[2])};
    const Lattice& l = tr.l;
    const float* s = src.data();
    float* d = dst.data();
    const std::int32_t i0 = first(l, 0), i1 = end(l, 0);
    // Along x the contiguous reads need samples i - 1 and i + 1 in the row.
    const std::int32_t v0 = std::max(i0, 1), v1 = std::min(i1, l.dim[0] - 1);
    const bool chunked = v1 - v0 >= advect_chunk;
    each_row(l, [&](std::int32_t row, std::int32_t j, std::int32_t k) {
        const std::int32_t below = c.index(0, j, k);
        float* out = d + row;
        const auto by_trilinear = [&](std::int32_t i) {
            out[i] = trilinear(s, l, tr.at(i, j, k, below));
        };
        if (!chunked) {
            for (std::int32_t i = i0; i < i1; ++i) {
                by_trilinear(i);
            }
            return;
        }
        // The nine lines at y, z ± 1, kept in the lattice: a clamped line is
        // never picked (the clamped trace cannot reach past the lattice).
        const auto line = [&](std::int32_t dy, std::int32_t dz) {
            const std::int32_t y = std::clamp(j + dy, 0, l.dim[1] - 1);
            const std::int32_t z = std::clamp(k + dz, 0, l.dim[2] - 1);
            return s + l.index(0, y, z);
        };
        const float *mm = line(-1, -1), *cm = line(0, -1), *pm = line(1, -1);
        const float *mc = line(-1, 0), *cc = line(0, 0), *pc = line(1, 0);
        const float *mp = line(-1, 1), *cp = line(0, 1), *pp = line(1, 1);
        // Chunks of a fixed length vectorise with no scalar remainder; the
        // last one ends at v1 and may redo faces of the one before (the same
        // values: each face is a function of the old field alone).
        for (std::int32_t from = v0; from < v1; from += advect_chunk) {
            const std::int32_t at = std::min(from, v1 - advect_chunk);
            std::int32_t far = 0;            // 32-bit, as the floats: one vector width
                                             // src, dst and the centre arrays are distinct.
#if defined(__GNUC__) && !defined(__clang__) // Clang has no ivdep; it vectorises without
#pragma GCC ivdep
#endif
            for (std::int32_t n = 0; n < advect_chunk; ++n) {
                const std::int32_t i = at + n;
                const LatticePoint t = tr.at(i, j, k, below);
                // The lower corner is one back (offset −1) or at the face (0).
                const std::int32_t dx = t.i - i, dy = t.j - j, dz = t.k - k;
                const bool bx = dx != 0, by = dy != 0, bz = dz != 0;
                const float tx = t.tx, ty = t.ty, tz = t.tz;
                const float ym = lerp_pick(lerp_line(mm, i, bx, tx), lerp_line(cm, i, bx, tx),
                                           lerp_line(pm, i, bx, tx), by, ty);
                const float yc = lerp_pick(lerp_line(mc, i, bx, tx), lerp_line(cc, i, bx, tx),
                                           lerp_line(pc, i, bx, tx), by, ty);
                const float yp = lerp_pick(lerp_line(mp, i, bx, tx), lerp_line(cp, i, bx, tx),
                                           lerp_line(pp, i, bx, tx), by, ty);
                out[i] = lerp_pick(ym, yc, yp, bz, tz);
                // Reached by the picks: offsets -1 or 0 on every axis.
                const auto off = static_cast<std::uint32_t>(dx + 1) |
                                 static_cast<std::uint32_t>(dy + 1) |
                                 static_cast<std::uint32_t>(dz + 1);
                far |= off > 1u ? 1 : 0;
            }
            if (far != 0) { // rare: a trace of a cell or more
                for (std::int32_t i = at; i < at + advect_chunk; ++i) {
                    by_trilinear(i);
                }
            }
        }
        for (const std::int32_t i : {i0, i1 - 1}) {
            if (i < v0 || i >= v1) {
                by_trilinear(i);
            }
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
void diffuse(const WindField& f, int a, Vector<float>& v, Vector<float>& tmp, const Mixing& m) {
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
void divergence(const WindField& f, Vector<float>& out) {
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

/// Cell (i, j, k) of the centre lattice at P = i + px·j + px·py·k, px and
/// py the lattice's first two dims rounded up to odd: P's parity is then the
/// cell's colour (i + j + k) & 1, and a colour is one dense array at P / 2
/// (ColourSplit in wind_field_solver.hpp). A neighbour P + d of a cell of
/// colour c sits in the other colour's array at P / 2 + ((c + d) >> 1).
std::int32_t odd_up(std::int32_t n) {
    return n | 1;
}

/// Elements of each colour's arrays in the ColourSplit of lattice `c`.
std::size_t colour_size(const Lattice& c) {
    return static_cast<std::size_t>((odd_up(c.dim[0]) * odd_up(c.dim[1]) * c.dim[2] + 1) / 2);
}

/// Row pieces of the split: a row's cells 1, 3, 5, … are `odd_i` of one
/// colour array and its cells 2, 4, 6, … `even_i` of the other, both
/// contiguous there. Separate restrict pointers let both copies vectorise.
void deinterleave(const float* __restrict row, float* __restrict odd_i, float* __restrict even_i,
                  std::int32_t pairs) {
    for (std::int32_t t = 0; t < pairs; ++t) {
        odd_i[t] = row[1 + 2 * t];
        even_i[t] = row[2 + 2 * t];
    }
}
void interleave(float* __restrict row, const float* __restrict odd_i,
                const float* __restrict even_i, std::int32_t pairs) {
    for (std::int32_t t = 0; t < pairs; ++t) {
        row[1 + 2 * t] = odd_i[t];
        row[2 + 2 * t] = even_i[t];
    }
}

/// Copies the updated cells of `full` (centre lattice) into the two colour
/// arrays of `split`, or back with `to_full`; cells outside stay as they are.
/// Cell i of a row has P = base + i, in colour (base + i) & 1 at (base + i) / 2.
void split_copy(const Lattice& c, const ColourSplit& split, Vector<float>& full,
                Vector<float> (&colours)[2], bool to_full) {
    const std::int32_t cells = c.dim[0] - 2, pairs = cells / 2;
    const bool odd_count = (cells & 1) != 0; // then cell `cells` ends the row alone
    for (std::int32_t k = 1; k < c.dim[2] - 1; ++k) {
        for (std::int32_t j = 1; j < c.dim[1] - 1; ++j) {
            const std::int32_t base = split.px * j + split.plane * k;
            float* row = full.data() + c.index(0, j, k);
            float* odd_i = colours[(base + 1) & 1].data() + ((base + 1) >> 1);
            float* even_i = colours[base & 1].data() + ((base + 2) >> 1);
            if (to_full) {
                interleave(row, odd_i, even_i, pairs);
                if (odd_count) {
                    row[cells] = odd_i[pairs];
                }
            } else {
                deinterleave(row, odd_i, even_i, pairs);
                if (odd_count) {
                    odd_i[pairs] = row[cells];
                }
            }
        }
    }
}

/// One colour's red-black SOR update over [begin, end) of its array; every
/// neighbour is in the other colour's array. In the run lie ghosts, padding
/// and solid cells with φ = rhs = inv = 0: φ + ω·(0·(…) − 0) stays +0 there
/// (a sum of +0 and −0 is +0), so they need no mask.
void sweep_colour(float* __restrict p, const float* __restrict other, const float* __restrict rhs,
                  const float* __restrict inv, std::int32_t begin, std::int32_t end_at,
                  const std::int32_t (&nb)[6], float cx, float cy, float cz) {
    for (std::int32_t m = begin; m < end_at; ++m) {
        const float sum = cx * (other[m + nb[0]] + other[m + nb[1]]) +
                          cy * (other[m + nb[2]] + other[m + nb[3]]) +
                          cz * (other[m + nb[4]] + other[m + nb[5]]);
        p[m] = p[m] + sor_omega * (inv[m] * (sum - rhs[m]) - p[m]);
    }
}

/// Red-black SOR on Σ c_a (φ_nb − φ) = div over the open cells. Solid cells
/// and ghosts hold φ = 0; a neighbour with no flux through the face between
/// (solid, floor, inflow side) is left out of inv_diag, so its 0 adds nothing.
/// Each sweep updates colour 1 (odd i + j + k), then colour 0, each colour
/// reading only the other: the same arithmetic per cell as a strided sweep
/// in the lattice, on dense arrays with no lanes of the other colour. (The
/// six arrays fit in L2 at 64×16×64; sweeps pipelined along z were slower.)
void pressure_sweeps(WindField& f, WindFieldSolver& s, std::uint32_t sweeps) {
    const Lattice& c = f.centre;
    ColourSplit& split = s.split;
    split_copy(c, split, f.pressure, split.pressure, false);
    split_copy(c, split, s.divergence, split.rhs, false);
    const float cx = f.inv_cell.x * f.inv_cell.x, cy = f.inv_cell.y * f.inv_cell.y,
                cz = f.inv_cell.z * f.inv_cell.z;
    // Each colour runs from its first cell at or after (1, 1, 1) to its last
    // at or before the last updated cell (n_x, n_y, n_z).
    const std::int32_t first_cell = split.px + split.plane + 1;
    const std::int32_t last_cell =
        (c.dim[0] - 2) + split.px * (c.dim[1] - 2) + split.plane * (c.dim[2] - 2);
    const std::int32_t step[3] = {1, split.px, split.plane};
    for (std::uint32_t sweep = 0; sweep < sweeps; ++sweep) {
        for (const int colour : {1, 0}) {
            std::int32_t nb[6];
            for (int a = 0; a < 3; ++a) {
                nb[2 * a] = (colour - step[a]) >> 1;
                nb[2 * a + 1] = (colour + step[a]) >> 1;
            }
            const std::int32_t begin = (first_cell + ((first_cell + colour) & 1)) >> 1;
            const std::int32_t end_at = ((last_cell - ((last_cell + colour) & 1)) >> 1) + 1;
            sweep_colour(split.pressure[colour].data(), split.pressure[1 - colour].data(),
                         split.rhs[colour].data(), split.inv_diag[colour].data(), begin, end_at, nb,
                         cx, cy, cz);
        }
    }
    split_copy(c, split, f.pressure, split.pressure, true);
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
void centre_velocity(WindField& f, const WindFieldSolver& s, const glm::vec3& inflow,
                     std::uint8_t sides) {
    const Lattice& c = f.centre;
    const std::int32_t i1 = end(c, 0);
    const auto nx = static_cast<std::int32_t>(f.n[0]), nz = static_cast<std::int32_t>(f.n[2]);
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
        // The ground is a wall the air slides along, as the floor is: its top
        // cell reads as the air above it, as the floor's ghosts do. A slower
        // wind near the ground would need a law (docs/wind_field.md).
        for (std::int32_t k = 0; k < nz; ++k) {
            for (std::int32_t i = 0; i < nx; ++i) {
                const std::int32_t filled = s.ground_cells[static_cast<std::size_t>(k * nx + i)];
                if (filled > 0) {
                    const std::int32_t q = c.index(i + 1, filled, k + 1);
                    out[q] = out[q + c.stride(1)];
                }
            }
        }
    }
    pack_centre(f);
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
                // Past the last cells: a wall or an inflow side (no flux) or
                // open air (φ = 0, counted).
                const bool lo_wall = pos == 1 && (wall_low(sides, a) || inflow_low(sides, a));
                const bool hi_wall =
                    pos == c.dim[a] - 2 && (wall_high(sides, a) || inflow_high(sides, a));
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
    ColourSplit& split = s.split;
    split.px = odd_up(c.dim[0]);
    split.plane = split.px * odd_up(c.dim[1]);
    const std::size_t size = colour_size(c);
    for (int colour = 0; colour < 2; ++colour) {
        split.pressure[colour].assign(size, 0.0f);
        split.rhs[colour].assign(size, 0.0f);
        split.inv_diag[colour].assign(size, 0.0f);
    }
    split_copy(c, split, s.inv_diag, split.inv_diag, false);
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
        for (Vector<float>* v : {&f.velocity[a], &f.at_centre[a]}) {
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

/// The porous cells' momentum sink, du/dt = −drag·|u|·u [Wil85], taken
/// implicitly over dt (u / (1 + drag·|u|·dt)): it slows the air, never turns it.
void resist(WindField& f, const WindFieldSolver& s, float dt) {
    for (const int a : {0, 2}) {
        for (std::size_t q = 0; q < s.porous_faces[a].size(); ++q) {
            float& u = f.velocity[a][static_cast<std::size_t>(s.porous_faces[a][q])];
            u = u / (1.0f + s.porous_drag[a][q] * std::abs(u) * dt);
        }
    }
}

} // namespace

std::uint8_t field_sides(const glm::vec3& wind, bool tunnel) {
    std::uint8_t s = 0;
    s |= wind.x > 0.0f ? inflow_x_min : 0;
    s |= wind.x < 0.0f ? inflow_x_max : 0;
    if (tunnel) {
        return s | walls_z;
    }
    s |= wind.z > 0.0f ? inflow_z_min : 0;
    s |= wind.z < 0.0f ? inflow_z_max : 0;
    return s;
}

void reserve_solver(const WindField& f, WindFieldSolver& s) {
    const std::size_t cells = f.centre.size();
    s.solid.reserve(cells);
    s.resistance.reserve(cells);
    s.reach.reserve(cells); // a cell is pushed at most once
    s.ground_cells.reserve(std::size_t{f.n[0]} * f.n[2]);
    s.ground_now.reserve(std::size_t{f.n[0]} * f.n[2]);
    s.inv_diag.reserve(cells);
    s.divergence.reserve(cells);
    for (int a = 0; a < 3; ++a) {
        s.closed[a].reserve(f.face[a].size()); // at most every face
        s.porous_faces[a].reserve(a == 1 ? 0 : f.face[a].size());
        s.porous_drag[a].reserve(a == 1 ? 0 : f.face[a].size());
        s.advected[a].reserve(f.face[a].size());
    }
    for (int colour = 0; colour < 2; ++colour) {
        for (auto* v :
             {&s.split.pressure[colour], &s.split.rhs[colour], &s.split.inv_diag[colour]}) {
            v->reserve(colour_size(f.centre));
        }
    }
}

void apply_obstacles(WindField& f, WindFieldSolver& s) {
    const Lattice& c = f.centre;
    for (int a = 0; a < 3; ++a) {
        const Lattice& l = f.face[a];
        s.closed[a].clear();
        s.porous_faces[a].clear();
        s.porous_drag[a].clear();
        s.advected[a].assign(l.size(), 0.0f);
        const std::int32_t up = c.stride(a);
        const float per_cell = 0.25f * f.inv_cell[a];
        for (std::int32_t k = 0; k < l.dim[2]; ++k) {
            for (std::int32_t j = 0; j < l.dim[1]; ++j) {
                const std::int32_t row = l.index(0, j, k), below = c.index(0, j, k);
                for (std::int32_t i = 0; i < l.dim[0]; ++i) {
                    const bool shut = s.solid[below + i] != 0 || s.solid[below + i + up] != 0;
                    const float loss = s.resistance[below + i] + s.resistance[below + i + up];
                    if (shut) {
                        s.closed[a].push_back(row + i);
                        f.velocity[a][static_cast<std::size_t>(row + i)] = 0.0f;
                    } else if (loss > 0.0f && a != 1) {
                        s.porous_faces[a].push_back(row + i);
                        s.porous_drag[a].push_back(loss * per_cell);
                    }
                }
            }
        }
    }
    // As every step leaves them: a restore rebuilds the solver and must
    // keep the saved bits.
    for (const int a : {0, 2}) {
        slide_over_ground(f, s, a, f.velocity[a]);
    }
    s.divergence.assign(c.size(), 0.0f);
    s.diag_sides = 0xff; // rebuilt at the next step
}

void step_wind_field(WindField& f, WindFieldSolver& s, const glm::vec3& wind, float dt) {
    // A tunnel's walls let no wind in across them.
    const glm::vec3 inflow = f.def.tunnel ? glm::vec3(wind.x, wind.y, 0.0f) : wind;
    const std::uint8_t sides = field_sides(inflow, f.def.tunnel);
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
            slide_over_ground(f, s, a, f.velocity[a]);
            diffuse(f, a, f.velocity[a], s.advected[a], mix);
        }
        resist(f, s, dt);
        enforce(f, s, inflow, sides);
        project(f, s, inflow, sides, f.def.pressure_iterations);
    }
    for (int a = 0; a < 3; ++a) {
        fill_ghosts(f.velocity[a], f.face[a], inflow[a], sides);
        slide_over_ground(f, s, a, f.velocity[a]); // the next advection reads them
    }
    centre_velocity(f, s, inflow, sides);
    f.inflow = inflow;
    ++f.steps;
}

double wind_field_divergence(const WindField& f, const WindFieldSolver& s) {
    Vector<float> d(f.centre.size(), 0.0f);
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
