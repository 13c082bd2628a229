// Hard case 4: 100 000 heaviest flakes land on one cell in one tick ([WF §4, §6]
// saw smoothing blow up under concentrated landing). 10^8 units (500 m
// of snow on a 10 cm cell) must spread without any cell going negative (an
// unsigned underflow would show as a cell >= 2^31), above the total, or
// above the previous maximum, and with the mass exact on every tick.
#include "hard_case_util.hpp"

#include "systems/core/units.hpp"

namespace snow {
namespace {

/// n·h − Σ neighbours of cell (ix, iz), in levels (the Laplacian of [WF §3]).
std::int64_t laplacian(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz) {
    std::size_t nb[4];
    const std::uint32_t n = s.neighbours(ix, iz, nb);
    std::int64_t sum = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        sum += s.level(s.index(ix, iz)) - s.level(nb[k]);
    }
    return sum;
}

TEST(HardCasePileOnOneCell, HundredThousandFlakesOnOneCellSpreadExactly) {
    const std::uint32_t flakes = 100000;
    const std::uint64_t total = std::uint64_t{flakes} * max_flake_units;
    SimConfig cfg;
    cfg.seed = 4;
    cfg.bounds = {{-1.0f, -1.0f, -1.0f}, {2.6f, 2.0f, 2.6f}};
    cfg.max_flakes = flakes;
    Simulation sim(cfg);
    SurfaceDef d;
    d.size_x = d.size_z = 1.6f; // 16 × 16 cells
    d.cell = 0.1f;
    d.spills = false;
    const SurfaceId e = sim.add_surface(d);
    // All just above the centre of cell (8, 8), falling at 1 m/s: every one
    // crosses the snow top in the first tick.
    for (std::uint32_t n = 0; n < flakes; ++n) {
        hard::place_flake(sim, {0.85f, 0.005f, 0.85f}, {0.0f, -1.0f, 0.0f}, 9.81f, max_flake_units);
    }
    const SnowSurface& s = hard::surface(sim, e);
    sim.tick();
    ASSERT_TRUE(hard::healthy(sim));
    ASSERT_EQ(sim.counters().landed, flakes);
    hard::CellStats st = hard::cell_stats(s);
    ASSERT_EQ(st.sum, total);
    std::uint32_t prev_max = st.max;
    int ticks = 1;
    for (; ticks < 2000 && !s.dirty_empty(); ++ticks) {
        sim.tick();
        ASSERT_TRUE(hard::healthy(sim));
        st = hard::cell_stats(s);
        ASSERT_EQ(st.wrapped, 0u) << "tick " << ticks;
        ASSERT_EQ(st.sum, total) << "tick " << ticks;
        // Smoothing is a convex update: no new maximum, ever
        // (docs/design.md "Numerical stability").
        ASSERT_LE(st.max, prev_max) << "tick " << ticks;
        prev_max = st.max;
    }
    EXPECT_TRUE(s.dirty_empty()) << "still smoothing after " << ticks << " ticks";
    // Spread into a low cone over most of the surface (only the far corners stay bare).
    EXPECT_GE(st.nonzero, s.cell_count() * 3 / 4);
    EXPECT_LT(st.max, total / 50);
    // At rest the cap of [WF §3] holds everywhere.
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            EXPECT_LE(laplacian(s, ix, iz), s.laplacian_limit_units) << ix << "," << iz;
        }
    }
    RecordProperty("ticks_to_rest", ticks);
    RecordProperty("max_cell_at_rest", static_cast<int>(st.max));
}

} // namespace
} // namespace snow
