// Hard case 5: the smallest and a very large snow surface. A 1 × 1-cell
// surface has no neighbours to smooth into and is all edge; a 2048 × 2048
// surface (4.2 M cells) must only work where snow changed: after a local
// landing the dirty rectangle stays small and snow stays near the landing.
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"

#include "systems/core/units.hpp"

#include <string>
#include <vector>

namespace snow {
namespace {

TEST(HardCaseSurfaceSize, OneCellSurfaceLandsKeepsAndSpillsExactly) {
    SimConfig cfg;
    cfg.seed = 51;
    cfg.bounds = {{-2.0f, -1.0f, -2.0f}, {2.0f, 3.0f, 2.0f}};
    cfg.max_flakes = 256;
    Simulation sim(cfg);
    SurfaceDef g;
    g.x0 = g.z0 = -2.0f;
    g.size_x = g.size_z = 4.0f;
    g.cell = 0.1f;
    g.spills = false;
    const SurfaceId ground = sim.add_surface(g);
    // A 10 cm pillar whose top is one cell: every cell is an edge cell.
    const Aabb pillar{{-0.05f, 0.0f, -0.05f}, {0.05f, 1.0f, 0.05f}};
    const ColliderId post = sim.add_box(pillar);
    SurfaceDef top;
    top.x0 = top.z0 = -0.05f;
    top.size_x = top.size_z = 0.1f;
    top.cell = 0.1f;
    top.base_y = pillar.max.y;
    top.edge_limit = 0.001f; // 200 units of this cell
    const SurfaceId cap = sim.add_surface(top, post);
    // A 1 × 1 ground-like surface with no spill: snow can only pile up in place.
    SurfaceDef lone;
    lone.x0 = lone.z0 = 1.0f;
    lone.size_x = lone.size_z = 0.1f;
    lone.cell = 0.1f;
    lone.base_y = 0.5f;
    lone.spills = false;
    const SurfaceId lone_e = sim.add_surface(lone);
    // (References into the surface pool only after the last add_surface.)
    const SnowSurface& one = hard::surface(sim, cap);
    ASSERT_EQ(one.nx, 1u);
    ASSERT_EQ(one.nz, 1u);
    for (int n = 0; n < 60; ++n) {
        hard::place_flake(sim, {0.0f, 1.2f, 0.0f}, {0.0f, -1.0f, 0.0f}, 9.81f, 100);
        hard::place_flake(sim, {1.05f, 0.7f, 1.05f}, {0.0f, -1.0f, 0.0f}, 9.81f, 100);
    }
    for (int t = 0; t < 600; ++t) {
        sim.tick();
        ASSERT_TRUE(hard::healthy(sim));
        ASSERT_LE(hard::cell_stats(one).max, 6000u);
    }
    EXPECT_EQ(flake_pool(sim).alive, 0u);
    EXPECT_EQ(world_of(sim).resource<MassLedger>().removed(), 0u);
    // The pillar keeps at most its edge limit; the rest spilled onto the ground.
    EXPECT_LE(hard::cell_stats(one).sum, one.edge_limit_units);
    EXPECT_GT(hard::cell_stats(one).sum, 0u);
    EXPECT_EQ(sim.counters().spilled_units + hard::cell_stats(one).sum, 6000u);
    EXPECT_EQ(hard::cell_stats(hard::surface(sim, ground)).sum, sim.counters().spilled_units);
    // The lone cell holds everything that fell on it: nowhere to smooth or spill to.
    EXPECT_EQ(hard::cell_stats(hard::surface(sim, lone_e)).sum, 6000u);
    EXPECT_TRUE(hard::surface(sim, lone_e).dirty_empty());
}

/// Width and depth (cells) of a surface's dirty rectangle, 0 when empty.
std::uint32_t dirty_extent(const SnowSurface& s) {
    return s.dirty_empty() ? 0u : std::max(s.dirty_x1 - s.dirty_x0, s.dirty_z1 - s.dirty_z0) + 1;
}

/// A cell landed on in the large-surface test.
struct Spot {
    std::uint32_t ix, iz;
};

/// Cells holding snow farther than `radius` cells (per axis) from every spot.
std::size_t far_snow(const SnowSurface& s, const std::vector<Spot>& spots, std::uint32_t radius) {
    auto dist = [](std::uint32_t a, std::uint32_t b) { return a > b ? a - b : b - a; };
    std::size_t far = 0;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            if (s.snow[s.index(ix, iz)] == 0) {
                continue;
            }
            bool near = false;
            for (const Spot& p : spots) {
                near = near || (dist(ix, p.ix) <= radius && dist(iz, p.iz) <= radius);
            }
            far += near ? 0 : 1;
        }
    }
    return far;
}

TEST(HardCaseSurfaceSize, HugeSurfaceWorksOnlyWhereSnowLanded) {
    const std::uint32_t side = 2048;
    const float cell = 0.01f; // 20.48 m; one unit is 0.5 mm here, the cap 4 units
    SimConfig cfg;
    cfg.seed = 52;
    cfg.bounds = {{-1.0f, -1.0f, -1.0f}, {21.5f, 3.0f, 21.5f}};
    cfg.max_flakes = 1024;
    Simulation sim(cfg);
    SurfaceDef d;
    d.size_x = d.size_z = cell * side;
    d.cell = cell;
    d.spills = false;
    const SurfaceId e = sim.add_surface(d);
    const SnowSurface& s = hard::surface(sim, e);
    ASSERT_EQ(s.nx, side);
    ASSERT_EQ(s.nz, side);
    // Local landings: the centre cell, then the first and the last corner cell.
    std::vector<Spot> done;
    const std::uint32_t flakes_per_spot = 300;
    const std::uint64_t units_per_spot = std::uint64_t{flakes_per_spot} * max_flake_units;
    std::uint64_t landed_units = 0;
    for (const Spot spot : {Spot{side / 2, side / 2}, Spot{0, 0}, Spot{side - 1, side - 1}}) {
        SCOPED_TRACE(::testing::Message() << "landing at cell " << spot.ix << "," << spot.iz);
        const std::uint64_t iterations_before = sim.counters().smoothing_iterations;
        for (std::uint32_t n = 0; n < flakes_per_spot; ++n) {
            hard::place_flake(sim, {(spot.ix + 0.5f) * cell, 0.01f, (spot.iz + 0.5f) * cell},
                              {0.0f, -1.0f, 0.0f}, 9.81f, max_flake_units);
        }
        landed_units += units_per_spot;
        int t = 0;
        for (; t < 400 && (t == 0 || !s.dirty_empty()); ++t) {
            sim.tick();
            // Work stays local: the rectangle redistribution walks never grows past the pile.
            ASSERT_LE(dirty_extent(s), 128u) << "tick " << t;
        }
        EXPECT_TRUE(s.dirty_empty()) << "still smoothing after " << t << " ticks";
        ASSERT_TRUE(hard::healthy(sim));
        EXPECT_EQ(hard::cell_stats(s).sum, landed_units);
        done.push_back(spot);
        EXPECT_EQ(far_snow(s, done, 64), 0u);
        RecordProperty("ticks_to_rest_" + std::to_string(spot.ix), t);
        RecordProperty("iterations_" + std::to_string(spot.ix),
                       static_cast<int>(sim.counters().smoothing_iterations - iterations_before));
    }
    // Two piles at opposite corners in the same ticks: the dirty rectangle
    // spans the surface, but the work is tracked per 8×8 tile, so what waits
    // for redistribution stays the two piles' tiles (a 128-cell square each
    // is 256 tiles), never the surface's 65 536.
    const Spot a{5, 5}, b{side - 6, side - 6};
    for (std::uint32_t n = 0; n < flakes_per_spot; ++n) {
        for (const Spot spot : {a, b}) {
            hard::place_flake(sim, {(spot.ix + 0.5f) * cell, 0.01f, (spot.iz + 0.5f) * cell},
                              {0.0f, -1.0f, 0.0f}, 9.81f, max_flake_units);
        }
    }
    landed_units += 2 * units_per_spot;
    std::size_t most_tiles = 0;
    int t = 0;
    for (; t < 400 && (t == 0 || !s.dirty_empty()); ++t) {
        sim.tick();
        most_tiles = std::max(most_tiles, s.dirty_tiles.size());
        ASSERT_LE(s.dirty_tiles.size(), 2u * 256u) << "tick " << t;
    }
    EXPECT_TRUE(s.dirty_empty()) << "still smoothing after " << t << " ticks";
    EXPECT_GT(most_tiles, 0u);
    EXPECT_EQ(hard::cell_stats(s).sum, landed_units);
    done.push_back(a);
    done.push_back(b);
    EXPECT_EQ(far_snow(s, done, 64), 0u);
    RecordProperty("two_corners_ticks_to_rest", t);
    RecordProperty("two_corners_most_dirty_tiles", static_cast<int>(most_tiles));
}

} // namespace
} // namespace snow
