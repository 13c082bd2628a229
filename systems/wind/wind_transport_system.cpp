// wind_transport: snow the wind moves (saltation). On each tick the wind
// field steps, the field's wind read `height` above each cell's snow top
// gives a friction velocity by the log law and, where it passes the
// threshold of the cell's snow (by its density), a saltation flux per metre
// of width [PG90] (saltation.hpp): what the wind can move. The flux crosses
// the cell's downwind x and z faces: it carries what arrives from upwind and
// closes a share 1 − e^(−cell/L) of its gap to what the wind can move, L the
// adjustment length [Kob72]: it takes up snow of the cell where it falls
// short, and lays its surplus down where the air slows (or turns). So
// erosion and deposition follow the flux's divergence, the flux is the same
// at any cell size or depth (the shares compose to the same exponential),
// and it crosses the surface's end (an eave, a drop, a void column) as
// clumps that fly on with the air [WF §6 names this as missing: "a strong
// wind cannot blow snow off of an object"].
//
// Each field step sweeps every row along x, upwind cells first, then every
// column along z (the order of the axes alternates from step to step), in
// whole units; a face's share of a unit is rounded up or down by a
// counter-based draw, so rounding neither loses nor favours small cells.
// Units only move, the ledger total holds. The field is read once a step at
// each tile corner and blended to the cells; tiles whose corners all see
// less than half the wind that moves fresh snow are calm, and only tiles
// under field columns where the air anywhere reaches that speed are read at
// all: the cost follows the windy area, not the surface's size.
#include "ecs/rng.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/units.hpp"
#include "systems/snowpack/shed.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/saltation.hpp"
#include "systems/wind/wind_field.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace snow {

namespace {

/// Most units one face passes in one step: keeps every carry far from
/// overflowing a cell's count (5 kg a face a step, beyond any gale).
constexpr std::uint32_t max_face_units = 1u << 20;

/// World resource: the field's windy columns, a surface's windy tiles and
/// the carries of a z sweep (room for the largest: prepare_wind_transport).
struct TransportScratch {
    Vector<float> column_speed;     ///< per (i, k) of the centre lattice: max u² + w² (steps²)
    Vector<std::uint8_t> windy;     ///< per lower corner (k · dim x + i): reads there may be windy
    Vector<std::uint8_t> windy_row; ///< per k: some corner of it is windy
    /// Per tile of the surface being swept: 0 where calm, else the blows()
    /// bits of the directions its corners' wind takes.
    Vector<std::uint8_t> tile_windy;
    /// Per tile corner ((tiles_x + 1) per row): the horizontal wind (u, w)
    /// read there, and whether it was read this step.
    Vector<glm::vec2> corner_wind;
    Vector<std::uint8_t> corner_read;
    Vector<std::uint32_t> carry; ///< per column of the surface: units arriving along z
};

/// What one field step's sweeps share.
struct Step {
    explicit Step(WindSampler a) : air(a) {}
    WindSampler air;
    const WindTransportDef* def = nullptr;
    double per_wind = 0.0;        ///< u*/U at the read height (log law)
    double air_kg_m3 = 0.0;       ///< density of the air
    double g = 0.0;               ///< gravity (m/s²)
    double fresh = 0.0;           ///< density of fresh snow (kg/m³): the lowest a cell holds
    double fresh_threshold = 0.0; ///< u*t of fresh snow: nothing drifts below it
    /// Units a face passes per kg/(m·s) of flux: cell · seconds / unit.
    double units_per_flux = 0.0;
    /// Levels a unit the wind lays down is packed by: 1 − fresh / wind-packed density.
    double wind_packing = 0.0;
    RngKey
        key; ///< slot: a sweep line or a cell (draw_at); draw: surface, rounding, axis, direction
    /// Share of the gap between the flux and what the wind can move that one
    /// cell closes: 1 − e^(−cell / adjustment length).
    double adjust = 1.0;
    std::uint32_t draw = 0; ///< this surface's first draw index
    float k_over_m = 1.0f;  ///< drag of clumps
};

/// Index meaning "across the edge": the units leave as clumps.
constexpr std::size_t off_surface = static_cast<std::size_t>(-1);
/// Index meaning "against a wall": the edge is closed by a base that stands
/// above the snow (a cover's step up onto a solid); the units stay.
constexpr std::size_t wall = off_surface - 1;

/// The cell downwind of (ix, iz) by (dx, dz) (one of them 0), `wall`, or
/// off_surface when the snow cannot stay on the surface that way: off the
/// grid, across a closed edge down (a drop), or onto a void column.
std::size_t downwind(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz, int dx, int dz) {
    const std::uint8_t shut = s.closed.empty() ? 0 : s.closed[s.index(ix, iz)];
    const std::uint8_t bit = dx < 0 ? 1u : dx > 0 ? 2u : dz < 0 ? 4u : 8u;
    const bool on_grid = (dx >= 0 || ix > 0) && (dx <= 0 || ix + 1 < s.nx) && (dz >= 0 || iz > 0) &&
                         (dz <= 0 || iz + 1 < s.nz);
    if (!on_grid) {
        return off_surface;
    }
    const std::size_t j = s.index(ix + dx, iz + dz);
    if (s.is_void(j)) {
        return off_surface;
    }
    if ((shut & bit) != 0) {
        return s.base_level[j] > s.level(s.index(ix, iz)) ? wall : off_surface;
    }
    return j;
}

/// Side of a tile in cells.
constexpr std::uint32_t tile_side = 1u << dirty_tile_shift;

/// The cell boundary of tile corner k along an axis of n cells.
std::uint32_t corner_cell(std::uint32_t k, std::uint32_t n) {
    return std::min(k * tile_side, n);
}

/// Horizontal wind (u, w) at tile corner (kx, kz) of `s`, `height` above the
/// snow top of the cell at that corner: read once a step (the cost follows
/// the windy tiles, not their cells).
glm::vec2 corner_wind(const SnowSurface& s, const WindSampler& air, float height,
                      TransportScratch& scratch, std::uint32_t kx, std::uint32_t kz) {
    const std::size_t at = static_cast<std::size_t>(kz) * (s.tiles_x() + 1) + kx;
    if (scratch.corner_read[at] == 0) {
        const std::uint32_t bx = corner_cell(kx, s.nx), bz = corner_cell(kz, s.nz);
        const float top = s.top_y(s.index(std::min(bx, s.nx - 1), std::min(bz, s.nz - 1)));
        float u = 0.0f, v = 0.0f, w = 0.0f;
        air.at(s.x0 + static_cast<float>(bx) * s.cell, top + height,
               s.z0 + static_cast<float>(bz) * s.cell, u, v, w);
        scratch.corner_wind[at] = {u, w};
        scratch.corner_read[at] = 1;
    }
    return scratch.corner_wind[at];
}

/// Horizontal wind over cell (ix, iz) of a windy tile: its tile's corner
/// reads, blended bilinearly to the cell's centre. The field is trilinear
/// over cells larger than a tile, so the blend is close to a read at the
/// cell; only the read height follows the corner's snow, not the cell's.
glm::vec2 wind_over(const SnowSurface& s, const TransportScratch& scratch, std::uint32_t ix,
                    std::uint32_t iz) {
    const std::uint32_t kx = ix >> dirty_tile_shift, kz = iz >> dirty_tile_shift;
    const auto along = [](std::uint32_t i, std::uint32_t k, std::uint32_t n) {
        const std::uint32_t lo = corner_cell(k, n), hi = corner_cell(k + 1, n);
        return (static_cast<float>(i - lo) + 0.5f) / static_cast<float>(hi - lo);
    };
    const float fx = along(ix, kx, s.nx), fz = along(iz, kz, s.nz);
    const std::size_t row = s.tiles_x() + 1, at = kz * row + kx;
    const glm::vec2* c = scratch.corner_wind.data();
    const glm::vec2 low = c[at] + fx * (c[at + 1] - c[at]);
    const glm::vec2 high = c[at + row] + fx * (c[at + row + 1] - c[at + row]);
    return low + fz * (high - low);
}

/// One draw of this surface and step for `slot`: `what` 0 rounds a face's
/// flux, 1 the packing of what it lays, 2 a cell's step towards what the wind
/// can move; one per axis and direction (4 · 3 of the surface's 16 indices).
float draw_at(const Step& st, std::uint32_t slot, bool along_x, int dir, std::uint32_t what) {
    RngKey key = st.key;
    key.slot = slot;
    return rng_uniform(key, st.draw + 4 * what + (along_x ? 0u : 2u) + (dir > 0 ? 1u : 0u));
}

/// The draw that rounds the shares of cell (ix, iz) for its face `dir` (±1)
/// along x (`along_x`) or z; `what` 0: the flux across it, 1: the packing of
/// what it lays. One draw per line of the sweep and step: in an even wind
/// every cell of a line passes on the same whole units, so rounding alone
/// never lays snow down or takes it up.
float draw_for(const Step& st, std::uint32_t ix, std::uint32_t iz, bool along_x, int dir,
               std::uint32_t what) {
    return draw_at(st, along_x ? iz : ix, along_x, dir, what);
}

/// The draw that rounds cell i's step towards what the wind can move: one
/// per cell, so the flux along a line adjusts by the expected share.
float adjust_draw(const Step& st, std::size_t i, bool along_x, int dir) {
    return draw_at(st, static_cast<std::uint32_t>(i), along_x, dir, 2);
}

/// `share` rounded down, or up with the probability of its fraction.
std::uint32_t whole_units(double share, float draw) {
    const double whole = std::floor(share);
    return static_cast<std::uint32_t>(whole) + (static_cast<double>(draw) < share - whole ? 1 : 0);
}

/// The bit of SnowSurface tile flags (TransportScratch::tile_windy) saying
/// that some corner of the tile blows `dir` (±1) along x (`along_x`) or z.
constexpr std::uint8_t blows(bool along_x, int dir) {
    return static_cast<std::uint8_t>(1u << ((along_x ? 0u : 2u) + (dir > 0 ? 0u : 1u)));
}

/// What the flux can move this step across one face of a cell, in units.
struct FaceUnits {
    /// Of the grains that arrive from upwind: these bounce on over any bed,
    /// so the fresh snow's threshold holds for them [PG90].
    std::uint32_t carry = 0;
    /// In all, taking up the cell's own snow: its threshold, by its density.
    std::uint32_t take = 0;
};

/// What the flux moves this step across the face of cell (ix, iz) that lies
/// `dir` (±1) along x (`along_x`) or z: nothing unless the wind blows that
/// way fast enough to move fresh snow.
FaceUnits face_units(const SnowSurface& s, const Step& st, const TransportScratch& scratch,
                     std::uint32_t ix, std::uint32_t iz, bool along_x, int dir) {
    // A tile none of whose corners blows this way has no cell that does.
    if ((scratch.tile_windy[s.tile_of(ix, iz)] & blows(along_x, dir)) == 0) {
        return {};
    }
    const glm::vec2 wind = wind_over(s, scratch, ix, iz);
    const float u = wind.x, w = wind.y;
    const float along = along_x ? u : w;
    if (!(along * static_cast<float>(dir) > 0.0f)) {
        return {};
    }
    const double speed = std::sqrt(static_cast<double>(u) * u + static_cast<double>(w) * w);
    const double u_star = st.per_wind * speed;
    if (!(u_star > st.fresh_threshold)) {
        return {};
    }
    const double per_flux = st.units_per_flux * std::abs(static_cast<double>(along)) / speed;
    const float draw = draw_for(st, ix, iz, along_x, dir, 0);
    const auto units = [&](double threshold) {
        const double share = saltation_flux(u_star, threshold, st.air_kg_m3, st.g) * per_flux;
        return share < max_face_units ? whole_units(share, draw) : max_face_units;
    };
    const std::uint32_t fresh = units(st.fresh_threshold);
    const std::size_t i = s.index(ix, iz);
    // Snow nothing packed is fresh: its threshold is known without an exp.
    const std::uint32_t packed = s.compacted.empty() ? 0 : s.compacted[i];
    if (packed == 0) {
        return {fresh, fresh};
    }
    const double density =
        st.fresh * static_cast<double>(s.snow[i]) / static_cast<double>(s.snow[i] - packed);
    return {fresh, units(threshold_friction_velocity(density))};
}

/// Lays `units` the flux along (dx, dz) drops into cell (ix, iz), up to the cell's
/// limit, as wind-packed snow [CP10]: returns what did not fit.
std::uint32_t lay(SnowSurface& s, const Step& st, std::uint32_t ix, std::uint32_t iz, int dx,
                  int dz, std::uint32_t units) {
    const std::size_t i = s.index(ix, iz);
    const std::uint32_t laid = std::min(units, max_cell_units - s.snow[i]);
    if (laid == 0) {
        return units;
    }
    s.snow[i] += laid;
    s.mark_dirty(i);
    const std::uint32_t room =
        max_compaction(s.snow[i]) - (s.compacted.empty() ? 0 : s.compacted[i]);
    const double packing = static_cast<double>(laid) * st.wind_packing;
    s.compact(i, std::min(room, whole_units(packing, draw_for(st, ix, iz, dx != 0, dx + dz, 1))));
    return units - laid;
}

/// The flux's step through cell (ix, iz) along (dx, dz): `carry` arrives
/// from upwind; returns what leaves across the downwind face (0 where that
/// face leads off the surface: those units left as clumps, or, against a
/// wall or on a surface that never spills, stayed).
std::uint32_t pass_cell(SnowSurface& s, const Step& st, const TransportScratch& scratch,
                        FlakePool& pool, std::uint32_t ix, std::uint32_t iz, int dx, int dz,
                        std::uint32_t carry) {
    const std::size_t i = s.index(ix, iz);
    // Nothing arrives and nothing can leave: no snow, or no wind this way.
    if (carry == 0 && (s.snow[i] == 0 ||
                       (scratch.tile_windy[s.tile_of(ix, iz)] & blows(dx != 0, dx + dz)) == 0)) {
        return 0;
    }
    if (s.is_void(i)) {
        return 0; // nothing reaches a void column (downwind() stops short of it)
    }
    const std::size_t next = downwind(s, ix, iz, dx, dz);
    std::uint32_t out = 0;
    if (next < wall || (next == off_surface && s.spills)) {
        const FaceUnits can = face_units(s, st, scratch, ix, iz, dx != 0, dx + dz);
        // The flux closes its gap to what the wind can move by a share per
        // cell: it takes up the cell's snow where it is short, lays snow
        // down where it carries more.
        const auto step = [&](std::uint32_t gap) {
            return whole_units(static_cast<double>(gap) * st.adjust,
                               adjust_draw(st, i, dx != 0, dx + dz));
        };
        const std::uint32_t taken =
            carry < can.take && s.snow[i] > 0 ? std::min(step(can.take - carry), s.snow[i]) : 0;
        if (taken != 0) {
            s.snow[i] -= taken;
            s.fit_compaction(i);
            s.mark_dirty(i);
        }
        // What the wind cannot carry on is laid here; what does not fit goes on.
        // Where the wind moves nothing (below the threshold, or turned away)
        // the grains stop within their hops: all are laid. The sweeps rely
        // on it: the cell past the windy tiles passes nothing on.
        const std::uint32_t dropped =
            can.carry == 0 ? carry : (carry > can.carry ? step(carry - can.carry) : 0);
        out = carry - dropped + taken + lay(s, st, ix, iz, dx, dz, dropped);
    } else {
        // Against a wall or a closed end: only a full cell lets units on.
        out = lay(s, st, ix, iz, dx, dz, carry);
    }
    if (out == 0 || next != off_surface) {
        return out;
    }
    const std::uint32_t flown = shed_units(pool, out, clump_beyond(s, ix, iz, dx, dz, st.k_over_m));
    // A full pool keeps the rest here. None may be lost, so they stay even
    // past the cell's limit (a full pool at a full cell): at most the carry
    // over it, far inside the count's range.
    if (out != flown) {
        s.snow[i] += out - flown;
        s.mark_dirty(i);
    }
    return 0;
}

/// Sweeps every row of [x0, x1) × [z0, z1) along x, each way, upwind first.
void sweep_x(SnowSurface& s, const Step& st, const TransportScratch& scratch, FlakePool& pool,
             std::uint32_t x0, std::uint32_t x1, std::uint32_t z0, std::uint32_t z1) {
    for (std::uint32_t iz = z0; iz < z1; ++iz) {
        std::uint32_t carry = 0;
        for (std::uint32_t ix = x0; ix < x1; ++ix) {
            carry = pass_cell(s, st, scratch, pool, ix, iz, 1, 0, carry);
        }
        carry = 0;
        for (std::uint32_t ix = x1; ix-- > x0;) {
            carry = pass_cell(s, st, scratch, pool, ix, iz, -1, 0, carry);
        }
    }
}

/// Sweeps every column of [x0, x1) × [z0, z1) along z, each way, upwind
/// first, a row at a time (the carries are per column).
void sweep_z(SnowSurface& s, const Step& st, TransportScratch& scratch, FlakePool& pool,
             std::uint32_t x0, std::uint32_t x1, std::uint32_t z0, std::uint32_t z1) {
    Vector<std::uint32_t>& carry = scratch.carry;
    carry.assign(s.nx, 0);
    for (std::uint32_t iz = z0; iz < z1; ++iz) {
        for (std::uint32_t ix = x0; ix < x1; ++ix) {
            carry[ix] = pass_cell(s, st, scratch, pool, ix, iz, 0, 1, carry[ix]);
        }
    }
    carry.assign(s.nx, 0);
    for (std::uint32_t iz = z1; iz-- > z0;) {
        for (std::uint32_t ix = x0; ix < x1; ++ix) {
            carry[ix] = pass_cell(s, st, scratch, pool, ix, iz, 0, -1, carry[ix]);
        }
    }
}

/// The lower corners (i, k), in x and z, of the trilinear reads of the field
/// that may see a horizontal wind of half `calm` (m/s), at any height: a
/// read is a convex blend of its 8 corners, so it is no faster than the
/// fastest of them. Corners are read as held steps (held_wind.hpp), within
/// half a step of the cell-centre velocities scanned here: a step of margin
/// covers that and float rounding.
void windy_columns(const WindField& f, float calm, TransportScratch& scratch) {
    const Lattice& c = f.centre;
    const std::int32_t nx = c.dim[0], ny = c.dim[1], nz = c.dim[2];
    Vector<float>& top = scratch.column_speed;
    top.assign(static_cast<std::size_t>(nx) * static_cast<std::size_t>(nz), 0.0f);
    for (std::int32_t k = 0; k < nz; ++k) {
        float* __restrict row = top.data() + static_cast<std::ptrdiff_t>(k) * nx;
        for (std::int32_t j = 0; j < ny; ++j) {
            const float* __restrict u = f.at_centre[0].data() + c.index(0, j, k);
            const float* __restrict w = f.at_centre[2].data() + c.index(0, j, k);
            for (std::int32_t i = 0; i < nx; ++i) {
                row[i] = std::max(row[i], u[i] * u[i] + w[i] * w[i]);
            }
        }
    }
    const float half = std::max(0.0f, 0.5f * calm - 1.0f / held_wind_steps_per_mps);
    const float limit = half * half;
    scratch.windy.assign(top.size(), 0);
    scratch.windy_row.assign(static_cast<std::size_t>(nz), 0);
    for (std::int32_t k = 0; k + 1 < nz; ++k) {
        for (std::int32_t i = 0; i + 1 < nx; ++i) {
            const std::size_t at = static_cast<std::size_t>(k) * static_cast<std::size_t>(nx) +
                                   static_cast<std::size_t>(i);
            const float fastest = std::max({top[at], top[at + 1], top[at + nx], top[at + nx + 1]});
            // NaN is windy: such a read is left to the exact test.
            const std::uint8_t windy = fastest < limit ? 0 : 1;
            scratch.windy[at] = windy;
            scratch.windy_row[static_cast<std::size_t>(k)] |= windy;
        }
    }
}

/// Cells [x0, x1) × [z0, z1) holding every windy tile of a surface.
struct WindyBox {
    std::uint32_t x0, x1, z0, z1;
};

/// Marks the windy tiles of `s` (scratch.tile_windy) and returns their
/// bounding box, empty (x0 == x1) where all are calm. A tile whose centre's
/// field read would have a calm lower corner (windy_columns) is calm without
/// a read, and a row of tiles over a calm row of corners is skipped whole;
/// else its corners are read and it is windy where one of them sees half of
/// `calm` (m/s).
WindyBox windy_tiles(const SnowSurface& s, const WindField& f, const Step& st, float calm,
                     TransportScratch& scratch) {
    const auto dim_x = static_cast<std::size_t>(f.centre.dim[0]);
    scratch.tile_windy.assign(static_cast<std::size_t>(s.tiles_x()) * s.tiles_z(), 0);
    scratch.corner_wind.resize(static_cast<std::size_t>(s.tiles_x() + 1) * (s.tiles_z() + 1));
    scratch.corner_read.assign(scratch.corner_wind.size(), 0);
    WindyBox box{s.nx, 0, s.nz, 0};
    for (std::uint32_t tz = 0; tz < s.tiles_z(); ++tz) {
        const std::uint32_t z0 = tz * tile_side, z1 = std::min(z0 + tile_side, s.nz);
        const float z = s.z0 + 0.5f * static_cast<float>(z0 + z1) * s.cell;
        // The centre's lower field corner in x and z (its height does not move them).
        const auto k = static_cast<std::size_t>(st.air.point(f.origin.x, f.origin.y, z).k);
        if (scratch.windy_row[k] == 0) {
            continue;
        }
        for (std::uint32_t tx = 0; tx < s.tiles_x(); ++tx) {
            const std::uint32_t x0 = tx * tile_side, x1 = std::min(x0 + tile_side, s.nx);
            const float x = s.x0 + 0.5f * static_cast<float>(x0 + x1) * s.cell;
            const auto i = static_cast<std::size_t>(st.air.point(x, f.origin.y, z).i);
            if (scratch.windy[k * dim_x + i] == 0) {
                continue;
            }
            float fastest = 0.0f;
            std::uint8_t ways = 0;
            for (std::uint32_t c = 0; c < 4; ++c) {
                const glm::vec2 wind =
                    corner_wind(s, st.air, st.def->height, scratch, tx + (c & 1), tz + (c >> 1));
                fastest = std::max(fastest, wind.x * wind.x + wind.y * wind.y);
                ways |=
                    (wind.x > 0.0f ? blows(true, 1) : 0) | (wind.x < 0.0f ? blows(true, -1) : 0) |
                    (wind.y > 0.0f ? blows(false, 1) : 0) | (wind.y < 0.0f ? blows(false, -1) : 0);
            }
            if (!(fastest > 0.25f * calm * calm) || ways == 0) {
                continue;
            }
            scratch.tile_windy[static_cast<std::size_t>(tz) * s.tiles_x() + tx] = ways;
            box = {std::min(box.x0, x0), std::max(box.x1, x1), std::min(box.z0, z0),
                   std::max(box.z1, z1)};
        }
    }
    return box.x0 < box.x1 ? box : WindyBox{0, 0, 0, 0};
}

} // namespace

bool wind_transport_declared(const World& w) {
    const auto* f = w.try_resource<WindField>();
    return f != nullptr && f->transport.has_value();
}

void prepare_wind_transport(World& w) {
    if (!wind_transport_declared(w)) {
        return;
    }
    auto* scratch = w.try_resource<TransportScratch>();
    if (scratch == nullptr) {
        scratch = &w.set_resource<TransportScratch>();
    }
    const Lattice& c = w.resource<WindField>().centre;
    const auto columns = static_cast<std::size_t>(c.dim[0]) * static_cast<std::size_t>(c.dim[2]);
    scratch->column_speed.reserve(columns);
    scratch->windy.reserve(columns);
    scratch->windy_row.reserve(static_cast<std::size_t>(c.dim[2]));
    std::size_t tiles = 0, corners = 0, row = 0;
    w.each<SnowSurface>([&](Entity, const SnowSurface& s) {
        tiles = std::max(tiles, static_cast<std::size_t>(s.tiles_x()) * s.tiles_z());
        corners = std::max(corners, static_cast<std::size_t>(s.tiles_x() + 1) * (s.tiles_z() + 1));
        row = std::max(row, static_cast<std::size_t>(s.nx));
    });
    scratch->tile_windy.reserve(tiles);
    scratch->corner_wind.reserve(corners);
    scratch->corner_read.reserve(corners);
    scratch->carry.reserve(row);
}

void wind_transport_system(World& w) {
    const WindField& f = w.resource<WindField>();
    // Only on the ticks the field stepped (wind_field_system just set `wait`).
    if (f.steps == 0 || f.wait + 1 != f.def.update_every) {
        return;
    }
    const SimConfig& config = w.resource<SimConfig>();
    Step st(f.sampler());
    st.def = &*f.transport;
    st.per_wind = friction_per_wind(st.def->height, st.def->roughness);
    st.air_kg_m3 = air_density(config.air_temperature);
    st.g = std::abs(static_cast<double>(config.gravity.y));
    st.fresh = fresh_snow_density(config);
    st.fresh_threshold = threshold_friction_velocity(st.fresh);
    st.wind_packing = 1.0 - st.fresh / wind_packed_snow_density;
    st.key = {config.seed, f.steps, 0, random_stream::transport};
    st.k_over_m = clump_drag(w);
    const float seconds = config.dt * static_cast<float>(f.def.update_every) * st.def->fast_forward;
    // The wind (m/s at the read height) that moves fresh snow.
    const auto calm = static_cast<float>(st.fresh_threshold / st.per_wind);
    prepare_wind_transport(w);
    auto& scratch = w.resource<TransportScratch>();
    FlakePool& pool = w.resource<FlakePool>();
    windy_columns(f, calm, scratch);
    const bool x_first = f.steps % 2 == 0;
    w.each<SnowSurface>([&](Entity e, SnowSurface& s) {
        st.units_per_flux = static_cast<double>(s.cell) * seconds / unit_kg;
        st.draw = 16 * e.index();
        st.adjust = -std::expm1(-static_cast<double>(s.cell) /
                                static_cast<double>(st.def->adjustment_length));
        const WindyBox b = windy_tiles(s, f, st, calm, scratch);
        if (b.x0 == b.x1) {
            return;
        }
        // One cell beyond the windy tiles: where their flux is laid down.
        const std::uint32_t x0 = b.x0 - (b.x0 > 0 ? 1 : 0), x1 = std::min(b.x1 + 1, s.nx);
        const std::uint32_t z0 = b.z0 - (b.z0 > 0 ? 1 : 0), z1 = std::min(b.z1 + 1, s.nz);
        for (int axis = 0; axis < 2; ++axis) {
            if ((axis == 0) == x_first) {
                sweep_x(s, st, scratch, pool, x0, x1, z0, z1);
            } else {
                sweep_z(s, st, scratch, pool, x0, x1, z0, z1);
            }
        }
    });
}

} // namespace snow
