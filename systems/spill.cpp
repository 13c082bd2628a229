// spill: [WF §3], "if too much snow accumulates on the edge of a height
// field, snow is emitted into the scene". Excess over the edge limit leaves a
// border cell as new flakes just outside the surface; they fall through the
// normal pipeline onto whatever lies below (a porch roof, the ground). A
// cover's edges are also inside it: where its base drops by more than its
// drop limit (eaves, a statue's shoulder, a table edge).
#include "systems/shed.hpp"
#include "systems/snow_cover.hpp"
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"

#include <algorithm>

namespace snow {

namespace {

/// Sheds the excess of cell (ix, iz) over the edge limit as clumps starting
/// at `at`; stops, keeping the rest on the edge, when the pool is full.
void shed(SnowSurface& s, std::uint32_t ix, std::uint32_t iz, FlakePool& pool, const ClumpStart& at,
          SimCounters& counters) {
    const std::size_t i = s.index(ix, iz);
    // Fresh snow lies on top: each unit shed lowers the edge by a level.
    const auto over = static_cast<std::uint32_t>(s.depth_levels(i) - s.edge_limit_units);
    const std::uint32_t gone = shed_units(pool, over, at);
    s.snow[i] -= gone;
    s.fit_compaction(i);
    counters.spilled_units += gone;
    if (gone != 0) {
        s.mark_dirty(ix, iz); // redistribution refills the edge from inside
    }
}

/// Border cells in index order: first row, the two ends of middle rows, last
/// row; each sheds outward across every border it touches.
void spill_border(SnowSurface& s, FlakePool& pool, float k_over_m, SimCounters& counters) {
    const std::uint32_t limit = s.edge_limit_units;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        const bool full_row = iz == 0 || iz + 1 == s.nz;
        const std::uint32_t step = full_row ? 1 : std::max(s.nx - 1, 1u);
        for (std::uint32_t ix = 0; ix < s.nx; ix += step) {
            if (s.depth_levels(s.index(ix, iz)) > limit) {
                const double ox = ix == 0 ? -1.0 : (ix + 1 == s.nx ? 1.0 : 0.0);
                const double oz = iz == 0 ? -1.0 : (iz + 1 == s.nz ? 1.0 : 0.0);
                shed(s, ix, iz, pool, clump_beyond(s, ix, iz, ox, oz, k_over_m), counters);
            }
        }
    }
}

/// A cover's drop cells, ascending: each sheds across its drop edge.
void spill_drops(SnowSurface& s, const SnowCover& cover, FlakePool& pool, float k_over_m,
                 SimCounters& counters) {
    static constexpr double off_x[4] = {-1.0, 1.0, 0.0, 0.0};
    static constexpr double off_z[4] = {0.0, 0.0, -1.0, 1.0};
    for (std::size_t k = 0; k < cover.edge_cells.size(); ++k) {
        const std::uint32_t c = cover.edge_cells[k];
        if (s.depth_levels(c) > s.edge_limit_units) {
            const std::uint8_t side = cover.edge_side[k];
            const auto ix = static_cast<std::uint32_t>(c % s.nx);
            const auto iz = static_cast<std::uint32_t>(c / s.nx);
            shed(s, ix, iz, pool, clump_beyond(s, ix, iz, off_x[side], off_z[side], k_over_m),
                 counters);
        }
    }
}

} // namespace

void spill_system(World& w) {
    auto& pool = w.resource<FlakePool>();
    auto& counters = w.resource<SimCounters>();
    const float k_over_m = clump_drag(w);
    const auto* covers = w.find_pool<SnowCover>();
    auto& surfaces = w.pool<SnowSurface>();
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        SnowSurface& s = surfaces.components()[i];
        if (s.spills) {
            spill_border(s, pool, k_over_m, counters);
        }
        if (const SnowCover* cover = covers ? covers->find(surfaces.entities()[i]) : nullptr) {
            spill_drops(s, *cover, pool, k_over_m, counters);
        }
    }
}

} // namespace snow
