// wind_transport: snow the wind moves (saltation). On each tick the wind
// field steps, every cell with snow where the field's horizontal wind, read
// `height` above the snow top, exceeds `threshold` loses a fraction of its
// snow downwind: split between the x and z neighbours by the wind's
// components, or as clumps where the surface ends downwind (an eave, a
// void column, the border of a spilling surface). Below the threshold snow
// stays, so drifts grow where obstacles slow the air [WF §6 names this as
// missing: "a strong wind cannot blow snow off of an object"].
//
// Every move is computed from the snow as it was before any move of the
// step, then all are applied (sources first), so the order of cells never
// matters; units only move, the ledger total holds. Tiles whose centre sees
// less than half the threshold are skipped whole, and only tiles under field
// columns where the air anywhere reaches that speed are looked at: the cost
// follows the windy area, not the surface's size.
#include "systems/api/systems.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/snowpack/shed.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/wind_field.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace snow {

namespace {

/// Index meaning "across the edge": the units leave as clumps.
constexpr std::size_t off_surface = static_cast<std::size_t>(-1);

struct Move {
    std::size_t from;
    std::size_t to; ///< off_surface: clumps beyond the edge towards (dx, dz)
    std::uint32_t units;
    std::int8_t dx, dz;
};

/// World resource: the moves of one surface's step, the field's windy
/// columns and a surface's tiles to look at (room for the largest:
/// prepare_wind_transport).
struct TransportScratch {
    Vector<Move> moves;
    Vector<float> column_speed;     ///< per (i, k) of the centre lattice: max u² + w² (steps²)
    Vector<std::uint8_t> windy;     ///< per lower corner (k · dim x + i): reads there may be windy
    Vector<std::uint8_t> windy_row; ///< per k: some corner of it is windy
};

/// The cell downwind of (ix, iz) by (dx, dz) (one of them 0), or off_surface
/// when the snow cannot stay on the surface that way: off the grid, across a
/// closed edge (a drop), or onto a void column.
std::size_t downwind(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz, int dx, int dz) {
    const std::uint8_t shut = s.closed.empty() ? 0 : s.closed[s.index(ix, iz)];
    const std::uint8_t bit = dx < 0 ? 1u : dx > 0 ? 2u : dz < 0 ? 4u : 8u;
    const bool on_grid = (dx >= 0 || ix > 0) && (dx <= 0 || ix + 1 < s.nx) && (dz >= 0 || iz > 0) &&
                         (dz <= 0 || iz + 1 < s.nz);
    if (!on_grid || (shut & bit) != 0) {
        return off_surface;
    }
    const std::size_t j = s.index(ix + dx, iz + dz);
    return s.is_void(j) ? off_surface : j;
}

/// Horizontal wind at `height` above the snow top of cell (ix, iz).
void wind_over(const WindSampler& air, const SnowSurface& s, std::uint32_t ix, std::uint32_t iz,
               float height, float& u, float& w) {
    const float x = s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell;
    const float z = s.z0 + (static_cast<float>(iz) + 0.5f) * s.cell;
    float v = 0.0f;
    air.at(x, s.top_y(s.index(ix, iz)) + height, z, u, v, w);
}

/// The moves of cell (ix, iz) under wind (u, w), appended to `out`.
void plan_cell(const SnowSurface& s, const WindTransportDef& t, float seconds, std::uint32_t ix,
               std::uint32_t iz, float u, float w, Vector<Move>& out) {
    const std::size_t i = s.index(ix, iz);
    const float speed = std::sqrt(u * u + w * w);
    if (!(speed > t.threshold)) {
        return;
    }
    const float fraction = std::min(t.max_fraction, t.rate * (speed - t.threshold) * seconds);
    const auto units = static_cast<std::uint32_t>(static_cast<float>(s.snow[i]) * fraction);
    if (units == 0) {
        return;
    }
    const float along_x = std::abs(u) / (std::abs(u) + std::abs(w));
    const auto ux = static_cast<std::uint32_t>(std::lround(static_cast<float>(units) * along_x));
    const int dx = u < 0.0f ? -1 : 1, dz = w < 0.0f ? -1 : 1;
    const std::uint32_t parts[2] = {ux, units - ux};
    const int steps[2][2] = {{dx, 0}, {0, dz}};
    for (int k = 0; k < 2; ++k) {
        if (parts[k] == 0) {
            continue;
        }
        const std::size_t to = downwind(s, ix, iz, steps[k][0], steps[k][1]);
        if (to == off_surface && !s.spills) {
            continue; // a surface that never spills keeps its snow at the border
        }
        out.push_back({i, to, parts[k], static_cast<std::int8_t>(steps[k][0]),
                       static_cast<std::int8_t>(steps[k][1])});
    }
}

/// The lower corners (i, k), in x and z, of the trilinear reads of the field
/// that may see a horizontal wind of half the threshold, at any height: a
/// read is a convex blend of its 8 corners, so it is no faster than the
/// fastest of them. Corners are read as held steps (held_wind.hpp), within
/// half a step of the cell-centre velocities scanned here: a step of margin
/// covers that and float rounding.
void windy_columns(const WindField& f, float threshold, TransportScratch& scratch) {
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
    const float half = std::max(0.0f, 0.5f * threshold - 1.0f / held_wind_steps_per_mps);
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

/// Plans the moves of every windy tile of `s`, row by row. A tile whose
/// centre's field read has a calm lower corner (windy_columns) is calm
/// without the read, and a row of tiles over a calm row of corners is
/// skipped whole, so the cost follows the windy area.
void plan_surface(const SnowSurface& s, const WindField& f, const TransportScratch& scratch,
                  const WindTransportDef& t, float seconds, Vector<Move>& out) {
    const WindSampler air = f.sampler();
    const std::uint32_t side = 1u << dirty_tile_shift;
    const auto dim_x = static_cast<std::size_t>(f.centre.dim[0]);
    for (std::uint32_t tz = 0; tz < s.tiles_z(); ++tz) {
        const std::uint32_t z0 = tz * side, z1 = std::min(z0 + side, s.nz);
        const std::uint32_t cz = (z0 + z1) / 2; // the centre cell wind_over reads
        const float z = s.z0 + (static_cast<float>(cz) + 0.5f) * s.cell;
        // The read's lower corner in x and z (its height does not move them).
        const auto k = static_cast<std::size_t>(air.point(f.origin.x, f.origin.y, z).k);
        if (scratch.windy_row[k] == 0) {
            continue;
        }
        for (std::uint32_t tx = 0; tx < s.tiles_x(); ++tx) {
            const std::uint32_t x0 = tx * side, x1 = std::min(x0 + side, s.nx);
            const std::uint32_t cx = (x0 + x1) / 2;
            const float x = s.x0 + (static_cast<float>(cx) + 0.5f) * s.cell;
            const auto i = static_cast<std::size_t>(air.point(x, f.origin.y, z).i);
            if (scratch.windy[k * dim_x + i] == 0) {
                continue;
            }
            float u = 0.0f, w = 0.0f;
            wind_over(air, s, cx, cz, t.height, u, w);
            if (!(u * u + w * w > 0.25f * t.threshold * t.threshold)) {
                continue; // the tile is calm: no cell of it can drift
            }
            for (std::uint32_t iz = z0; iz < z1; ++iz) {
                for (std::uint32_t ix = x0; ix < x1; ++ix) {
                    if (s.snow[s.index(ix, iz)] != 0) {
                        wind_over(air, s, ix, iz, t.height, u, w);
                        plan_cell(s, t, seconds, ix, iz, u, w, out);
                    }
                }
            }
        }
    }
}

/// Sources first (each gives at most what it had), then destinations; what
/// cannot arrive (a full pool, a cell at its limit) goes back to its source.
void apply(SnowSurface& s, const Vector<Move>& moves, FlakePool& pool, float k_over_m) {
    for (const Move& m : moves) {
        s.snow[m.from] -= m.units;
        s.mark_dirty(m.from);
    }
    for (const Move& m : moves) {
        std::uint32_t arrived = 0;
        if (m.to == off_surface) {
            const auto ix = static_cast<std::uint32_t>(m.from % s.nx);
            const auto iz = static_cast<std::uint32_t>(m.from / s.nx);
            arrived = shed_units(pool, m.units, clump_beyond(s, ix, iz, m.dx, m.dz, k_over_m));
        } else {
            arrived = std::min(m.units, max_cell_units - s.snow[m.to]);
            s.snow[m.to] += arrived;
            s.mark_dirty(m.to);
        }
        s.snow[m.from] += m.units - arrived;
    }
    // Once every move arrived: a source keeps the compaction its units still hold.
    for (const Move& m : moves) {
        s.fit_compaction(m.from);
    }
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
    // At most two moves per cell (plan_cell) of the largest surface.
    std::size_t largest = 0;
    w.each<SnowSurface>(
        [&](Entity, const SnowSurface& s) { largest = std::max(largest, s.cell_count()); });
    scratch->moves.reserve(2 * largest);
}

void wind_transport_system(World& w) {
    const WindField& f = w.resource<WindField>();
    // Only on the ticks the field stepped (wind_field_system just set `wait`).
    if (f.steps == 0 || f.wait + 1 != f.def.update_every) {
        return;
    }
    const WindTransportDef& t = *f.transport;
    const float seconds = w.resource<SimConfig>().dt * static_cast<float>(f.def.update_every);
    prepare_wind_transport(w);
    auto* scratch = &w.resource<TransportScratch>();
    FlakePool& pool = w.resource<FlakePool>();
    const float k_over_m = clump_drag(w);
    windy_columns(f, t.threshold, *scratch);
    w.each<SnowSurface>([&](Entity, SnowSurface& s) {
        scratch->moves.clear();
        plan_surface(s, f, *scratch, t, seconds, scratch->moves);
        apply(s, scratch->moves, pool, k_over_m);
    });
}

} // namespace snow
