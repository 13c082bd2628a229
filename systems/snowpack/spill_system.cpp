// spill: [WF §3], "if too much snow accumulates on the edge of a height
// field, snow is emitted into the scene". Excess over the edge limit leaves a
// border cell as new flakes just outside the surface; they fall through the
// normal pipeline onto whatever lies below (a porch roof, the ground). A
// cover's edges are also inside it: where its base drops by more than its
// drop limit (eaves, a statue's shoulder, a table edge). A tilted surface
// may also shed in slabs: a line of cells down its slope whose weight along
// the slope beats its friction and adhesion sheds all its snow as clumps just
// beyond its low edge, as roofs shed their snow onto whatever lies below the
// eave.
#include "systems/api/systems.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/units.hpp"
#include "systems/snowpack/shed.hpp"
#include "systems/snowpack/snow_cover.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <algorithm>
#include <cmath>

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

/// A sliding slab breaks into packed clumps that fall this fast (m/s) in
/// still air: far faster than flakes, so the wind hardly carries them off
/// what lies below the eave.
constexpr float slab_fall_speed = 5.0f;

/// Each line down the slope, in index order, whose weight along the slope
/// beats its hold (SnowSurface::slide_drive) slides off whole: its cells, low
/// edge first, shed all their units as clumps just beyond the low edge (what
/// the pool cannot take stays).
void slide_lines(SnowSurface& s, FlakePool& pool, float k_over_m, double gravity,
                 SimCounters& counters) {
    const std::uint32_t len = s.slide_along_x ? s.nx : s.nz;
    const std::uint32_t lines = s.slide_along_x ? s.nz : s.nx;
    const auto cell = [&](std::uint32_t line, std::uint32_t k) { // k = 0: the low edge
        const std::uint32_t a = s.slide_to_high ? len - 1 - k : k;
        return s.slide_along_x ? s.index(a, line) : s.index(line, a);
    };
    const double out = s.slide_to_high ? 1.0 : -1.0;
    // The most units a cell's plan area holds: adhesion over drive per kg/m².
    const double cell_area = static_cast<double>(s.cell) * s.cell;
    const double held_units = s.slide_adhesion / (gravity * s.slide_drive) * cell_area / unit_kg;
    for (std::uint32_t line = 0; line < lines; ++line) {
        std::uint64_t units = 0;
        for (std::uint32_t k = 0; k < len; ++k) {
            units += s.snow[cell(line, k)];
        }
        if (static_cast<double>(units) <= held_units * len) {
            continue;
        }
        const std::size_t low = cell(line, 0);
        const auto lx = static_cast<std::uint32_t>(low % s.nx);
        const auto lz = static_cast<std::uint32_t>(low / s.nx);
        const ClumpStart at = s.slide_along_x ? clump_beyond(s, lx, lz, out, 0.0, k_over_m)
                                              : clump_beyond(s, lx, lz, 0.0, out, k_over_m);
        for (std::uint32_t k = 0; k < len; ++k) {
            const std::size_t i = cell(line, k);
            const std::uint32_t had = s.snow[i];
            const std::uint32_t gone = shed_units(pool, had, at);
            s.snow[i] -= gone;
            s.fit_compaction(i);
            counters.spilled_units += gone;
            s.mark_dirty(i);
            if (gone < had) {
                return; // the pool is full: the rest slides when there is room
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
    const float gravity = std::abs(w.resource<SimConfig>().gravity.y);
    const float slab_k_over_m = gravity / slab_fall_speed;
    const auto* covers = w.find_pool<SnowCover>();
    auto& surfaces = w.pool<SnowSurface>();
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        SnowSurface& s = surfaces.components()[i];
        if (s.spills) {
            if (s.slide_drive > 0.0f) {
                slide_lines(s, pool, slab_k_over_m, gravity, counters);
            }
            spill_border(s, pool, k_over_m, counters);
        }
        if (const SnowCover* cover = covers ? covers->find(surfaces.entities()[i]) : nullptr) {
            spill_drops(s, *cover, pool, k_over_m, counters);
        }
    }
}

} // namespace snow
