// spill: seed 002 §3, "if too much snow accumulates on the edge of a height
// field, snow is emitted into the scene". Excess over the edge limit leaves a
// border cell as new flakes just outside the surface; they fall through the
// normal pipeline onto whatever lies below (a porch roof, the ground).
#include "systems/emitter.hpp"
#include "systems/flake_pool.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"
#include "systems/units.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// Diameter (m) of a spilled clump, for rendering.
constexpr float spill_flake_size = 0.01f;

struct SpillFlake {
    float x, y, z;  ///< where new flakes appear
    float k_over_m; ///< drag of new flakes
};

/// Sheds the excess of border cell (ix, iz) as flakes of at most
/// max_flake_units each. Stops, keeping the rest on the edge, when the pool is full.
void shed(SnowSurface& s, std::uint32_t ix, std::uint32_t iz, FlakePool& pool,
          const SpillFlake& proto, SimCounters& counters) {
    std::uint32_t& cell = s.snow[s.index(ix, iz)];
    const std::uint32_t before = cell;
    std::uint32_t left = cell - s.edge_limit_units;
    while (left > 0) {
        std::uint32_t slot = 0;
        if (!pool.acquire(slot)) {
            break;
        }
        const std::uint32_t m = std::min(left, max_flake_units);
        pool.px[slot] = proto.x;
        pool.py[slot] = proto.y;
        pool.pz[slot] = proto.z;
        pool.vx[slot] = pool.vy[slot] = pool.vz[slot] = 0.0f;
        pool.k_over_m[slot] = proto.k_over_m;
        pool.size[slot] = spill_flake_size;
        pool.mass_units[slot] = m; // settled -> airborne: the ledger total is unchanged
        cell -= m;
        left -= m;
        counters.spilled_units += m;
    }
    if (cell != before) {
        s.mark_dirty(ix, iz); // redistribution refills the edge from inside
    }
}

/// Centre of cell (ix, iz) moved one cell outward across each border it
/// touches: half a cell beyond the edge, so the flake is off this surface.
SpillFlake spill_point(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz, float k_over_m) {
    const double ox = ix == 0 ? -1.0 : (ix + 1 == s.nx ? 1.0 : 0.0);
    const double oz = iz == 0 ? -1.0 : (iz + 1 == s.nz ? 1.0 : 0.0);
    const double cell = s.cell;
    return {static_cast<float>(s.x0 + (ix + 0.5 + ox) * cell), s.top_y(s.index(ix, iz)),
            static_cast<float>(s.z0 + (iz + 0.5 + oz) * cell), k_over_m};
}

} // namespace

void spill_system(World& w) {
    auto& pool = w.resource<FlakePool>();
    auto& counters = w.resource<SimCounters>();
    // Drag from the emitter's mean fall speed (terminal speed g·m/k), else 1 m/s.
    const float g = std::abs(w.resource<SimConfig>().gravity.y);
    float fall = 1.0f;
    if (const auto* emitters = w.find_pool<Emitter>(); emitters && emitters->size() > 0) {
        const Emitter& e = emitters->components().front();
        fall = 0.5f * (e.fall_speed_min + e.fall_speed_max);
    }
    const float k_over_m = g / fall;

    for (SnowSurface& s : w.pool<SnowSurface>().components()) {
        if (!s.spills) {
            continue;
        }
        const std::uint32_t limit = s.edge_limit_units;
        // Border cells in index order: first row, the two ends of middle rows, last row.
        for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
            const bool full_row = iz == 0 || iz + 1 == s.nz;
            const std::uint32_t step = full_row ? 1 : std::max(s.nx - 1, 1u);
            for (std::uint32_t ix = 0; ix < s.nx; ix += step) {
                if (s.snow[s.index(ix, iz)] > limit) {
                    shed(s, ix, iz, pool, spill_point(s, ix, iz, k_over_m), counters);
                }
            }
        }
    }
}

} // namespace snow
