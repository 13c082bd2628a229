/// @file wind_field.hpp
/// @brief A coarse wind field over the bounds that obstacles shape: stable
/// fluids [STAM] on a staggered (MAC) grid, the global Wind as inflow on the
/// upwind sides. Declared by a scene or absent; absent means no field, no
/// cost, and flakes feel the global wind alone. See docs/wind_field.md.
#pragma once

#include "ecs/host_memory.hpp"
#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"
#include "systems/flakes/held_wind.hpp"
#include "systems/geometry/geometry.hpp"
#include "systems/wind/wind_transport.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include <snow/defs.hpp>

namespace snow {

/// One array of the staggered grid and how to read it. Storage is x fastest;
/// an axis the samples sit at cell centres of has one ghost layer on each
/// side (dim = n + 2, shift 0.5), an axis they sit on the faces of has none
/// (dim = n + 1, shift 0). A point at cell coordinate g (world / cell size,
/// from the bounds' min corner, in [0, n]) is at lattice coordinate g + shift.
struct Lattice {
    std::int32_t dim[3] = {0, 0, 0};
    float shift[3] = {0.0f, 0.0f, 0.0f};
    std::int32_t last[3] = {0, 0, 0}; ///< largest lower corner of a trilinear read

    /// The array of samples at the faces normal to `face_axis` (0, 1, 2), or
    /// at the cell centres for face_axis = 3, of an n[0] × n[1] × n[2] grid.
    [[nodiscard]] static Lattice make(const std::uint32_t (&n)[3], int face_axis);
    [[nodiscard]] std::int32_t index(std::int32_t i, std::int32_t j, std::int32_t k) const {
        return i + dim[0] * (j + dim[1] * k);
    }
    [[nodiscard]] std::int32_t stride(int axis) const {
        return axis == 0 ? 1 : (axis == 1 ? dim[0] : dim[0] * dim[1]);
    }
    [[nodiscard]] std::size_t size() const {
        return static_cast<std::size_t>(dim[0]) * static_cast<std::size_t>(dim[1]) *
               static_cast<std::size_t>(dim[2]);
    }
};

/// v limited to [lo, hi] by value, without branches (std::clamp, on
/// references, keeps GCC from vectorising the loops it is in); NaN gives lo,
/// so no read leaves the grid.
inline float clamp_value(float v, float lo, float hi) {
    return std::min(std::max(lo, v), hi);
}

/// The lower corner and weights of a trilinear read; g is in cell
/// coordinates, already clamped to [0, n] on each axis.
struct LatticePoint {
    std::int32_t base;    ///< index of the lower corner
    std::int32_t i, j, k; ///< the lower corner
    float tx, ty, tz;
};

inline LatticePoint locate(const Lattice& l, float gx, float gy, float gz) {
    const float lx = gx + l.shift[0], ly = gy + l.shift[1], lz = gz + l.shift[2];
    // Non-negative, so truncation is floor; the last corner keeps i + 1 inside.
    const std::int32_t i = std::min(static_cast<std::int32_t>(lx), l.last[0]);
    const std::int32_t j = std::min(static_cast<std::int32_t>(ly), l.last[1]);
    const std::int32_t k = std::min(static_cast<std::int32_t>(lz), l.last[2]);
    return {
        l.index(i, j, k),          i, j, k, lx - static_cast<float>(i), ly - static_cast<float>(j),
        lz - static_cast<float>(k)};
}

/// Samples b and b + 1 of d, read as one 8-byte load: in a vectorised loop
/// that is one 64-bit gather lane instead of two 32-bit ones.
inline void pair_at(const float* d, std::int32_t b, float& lo, float& hi) {
    std::uint64_t v;
    std::memcpy(&v, d + b, sizeof v);
    lo = std::bit_cast<float>(static_cast<std::uint32_t>(v));
    hi = std::bit_cast<float>(static_cast<std::uint32_t>(v >> 32));
}

/// Trilinear between the 8 corner values of p's cell: (a0, a1) along x at
/// the low y and z, (b0, b1) at y + 1, (c0, c1) at z + 1, (e0, e1) at both.
inline float trilinear_corners(float a0, float a1, float b0, float b1, float c0, float c1, float e0,
                               float e1, const LatticePoint& p) {
    const float x00 = a0 + p.tx * (a1 - a0);
    const float x10 = b0 + p.tx * (b1 - b0);
    const float x01 = c0 + p.tx * (c1 - c0);
    const float x11 = e0 + p.tx * (e1 - e0);
    const float y0 = x00 + p.ty * (x10 - x00);
    const float y1 = x01 + p.ty * (x11 - x01);
    return y0 + p.tz * (y1 - y0);
}

inline float trilinear(const float* d, const Lattice& l, const LatticePoint& p) {
    const std::int32_t sy = l.dim[0], sz = l.dim[0] * l.dim[1];
    float a0, a1, b0, b1, c0, c1, e0, e1;
    pair_at(d, p.base, a0, a1);
    pair_at(d, p.base + sy, b0, b1);
    pair_at(d, p.base + sz, c0, c1);
    pair_at(d, p.base + sy + sz, e0, e1);
    return trilinear_corners(a0, a1, b0, b1, c0, c1, e0, e1, p);
}

/// A cell-centre velocity as its readers see it: u, v, w as held steps
/// (held_wind.hpp) in bits 0–15, 16–31 and 32–47 of one word, so that one
/// 8-byte read gives all three components of a corner and a trilinear read
/// touches 4 cache lines, not 12 (docs/wind_field.md "Sampling").
inline std::uint64_t pack_wind(float u, float v, float w) {
    const auto bits = [](float c) {
        return std::uint64_t{static_cast<std::uint16_t>(hold_wind_component(c))};
    };
    return bits(u) | (bits(v) << 16) | (bits(w) << 32);
}

/// Component a (0, 1, 2) of a packed velocity, in held steps.
inline float packed_steps(std::uint64_t p, int a) {
    return static_cast<float>(static_cast<std::int16_t>(static_cast<std::uint16_t>(p >> (16 * a))));
}

/// Trilinear between the corners c[0..7] (x fastest, then y, then z) of
/// component a, in held steps.
inline float trilinear_steps(const std::uint64_t (&c)[8], int a, const LatticePoint& p) {
    return trilinear_corners(packed_steps(c[0], a), packed_steps(c[1], a), packed_steps(c[2], a),
                             packed_steps(c[3], a), packed_steps(c[4], a), packed_steps(c[5], a),
                             packed_steps(c[6], a), packed_steps(c[7], a), p);
}

/// Reads the packed cell-centre velocities of a field: plain values and
/// pointers, so a flake loop holding one by value vectorises.
struct WindSampler {
    const std::uint64_t* c; ///< WindField::packed_centre
    Lattice centre;
    glm::vec3 origin;   ///< bounds.min
    glm::vec3 inv_cell; ///< 1 / cell edge (1/m)
    glm::vec3 cells;    ///< cells per axis, as floats

    /// Where a read at world point (x, y, z) falls in the centre lattice;
    /// points outside the bounds are clamped onto the nearest boundary.
    [[gnu::always_inline]] LatticePoint point(float x, float y, float z) const {
        const float gx = clamp_value((x - origin.x) * inv_cell.x, 0.0f, cells.x);
        const float gy = clamp_value((y - origin.y) * inv_cell.y, 0.0f, cells.y);
        const float gz = clamp_value((z - origin.z) * inv_cell.z, 0.0f, cells.z);
        return locate(centre, gx, gy, gz);
    }

    /// Wind at world point (x, y, z) in held steps, trilinear between cell
    /// centres; points outside the bounds read the nearest boundary value.
    /// Scalars out and always inlined, so flake loops vectorise.
    [[gnu::always_inline]] void steps_at(float x, float y, float z, float& wx, float& wy,
                                         float& wz) const {
        const LatticePoint p = point(x, y, z);
        const std::int32_t sy = centre.dim[0], sz = centre.dim[0] * centre.dim[1];
        const std::uint64_t corner[8] = {
            c[p.base],      c[p.base + 1],      c[p.base + sy],      c[p.base + sy + 1],
            c[p.base + sz], c[p.base + sz + 1], c[p.base + sy + sz], c[p.base + sy + sz + 1]};
        wx = trilinear_steps(corner, 0, p);
        wy = trilinear_steps(corner, 1, p);
        wz = trilinear_steps(corner, 2, p);
    }

    /// The same in m/s (exact: the step is a power of two).
    [[gnu::always_inline]] void at(float x, float y, float z, float& wx, float& wy,
                                   float& wz) const {
        steps_at(x, y, z, wx, wy, wz);
        wx *= 1.0f / held_wind_steps_per_mps;
        wy *= 1.0f / held_wind_steps_per_mps;
        wz *= 1.0f / held_wind_steps_per_mps;
    }
};

/// World resource: the field. Face velocities and pressure are simulation
/// state (hashed, saved); the cell-centre velocities are derived from them
/// after every step and are what flakes sample.
struct WindField {
    WindFieldDef def;
    std::uint32_t n[3] = {0, 0, 0}; ///< cells per axis
    glm::vec3 origin{0.0f};         ///< bounds.min
    glm::vec3 inv_cell{0.0f};       ///< 1 / cell edge per axis (1/m)
    Lattice face[3];                ///< lattices of u, v, w
    Lattice centre;                 ///< lattice of pressure and cell-centre velocity

    // -- state --
    Vector<float> velocity[3];                 ///< u, v, w on their faces (m/s)
    Vector<float> pressure;                    ///< last projection's potential (warm start)
    glm::vec3 inflow{0.0f};                    ///< the global wind of the last step (m/s)
    std::uint32_t wait = 0;                    ///< ticks until the next step
    std::uint64_t steps = 0;                   ///< solver steps taken (0: not yet initialised)
    std::optional<WindTransportDef> transport; ///< snow the wind moves; absent: none

    // -- derived after each step --
    Vector<float> at_centre[3];          ///< cell-centre velocity, ghosts included (the solver's)
    Vector<std::uint64_t> packed_centre; ///< the same packed (pack_wind): what readers read

    /// What flakes read the field through (valid until the next step).
    [[nodiscard]] WindSampler sampler() const;
    /// Wind (m/s) at world point (x, y, z); see WindSampler::at.
    [[nodiscard]] glm::vec3 at(float x, float y, float z) const {
        glm::vec3 w;
        sampler().at(x, y, z, w.x, w.y, w.z);
        return w;
    }
};

inline WindSampler WindField::sampler() const {
    return {packed_centre.data(),
            centre,
            origin,
            inv_cell,
            {static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2])}};
}

/// A still field of `def`'s size over `bounds` (def already validated); it
/// takes the global wind at its first step.
[[nodiscard]] WindField make_wind_field(const WindFieldDef& def, const Aabb& bounds);

class ByteWriter;
class ByteReader;
/// The field's snapshot record: its def, then its state and the cell-centre
/// velocities (packed_centre is packed again on load).
void save_state(ByteWriter& out, const WindField& f);
/// Reads the def that starts a record of save_state.
void load_def(ByteReader& in, WindFieldDef& def);
/// Reads the rest of the record into `f`, made from that def (validated) by
/// make_wind_field; throws SimulationError naming what is wrong.
void load_state(ByteReader& in, WindField& f);
class StateHasher;
/// Its settings and grid and its state (velocities, the pressure the next
/// projection starts from, inflow, step clock); not what derives from them
/// (cell-centre velocities, the solver).
void hash_state(StateHasher& h, const WindField& f);

/// Packs at_centre into packed_centre: after every step, and after anything
/// else that writes at_centre.
void pack_centre(WindField& f);

/// `wind.field.*`; the total cell count is checked by validate().
inline constexpr FieldRule<WindFieldDef> wind_field_fields[] = {
    {"cells[0]", &WindFieldDef::cells_x, at_least(1)},
    {"cells[1]", &WindFieldDef::cells_y, at_least(1)},
    {"cells[2]", &WindFieldDef::cells_z, at_least(1)},
    {"update_every", &WindFieldDef::update_every, between(1, max_wind_field_update_every)},
    {"sample_every", &WindFieldDef::sample_every, between(1, max_wind_field_sample_every)},
    {"pressure_iterations", &WindFieldDef::pressure_iterations,
     between(1, max_pressure_iterations)},
    {"eddy_viscosity", &WindFieldDef::eddy_viscosity, between(0, max_eddy_viscosity)},
    {"tunnel", &WindFieldDef::tunnel},
};

[[nodiscard]] Invalid validate(const WindFieldDef& d);

} // namespace snow
