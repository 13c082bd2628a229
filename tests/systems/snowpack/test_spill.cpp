// spill: [WF §3], snow over an edge limit is emitted into the scene and
// falls onto the surfaces below; mass moves from settled to airborne exactly.
#include "systems/api/simulation_internals.hpp"
#include "systems/core/units.hpp"
#include "systems/flakes/snowfall.hpp"
#include "tests/support/rect_surface.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace snow {
namespace {

/// A spill test's surface: its edge limit 0.01 m (edge_limit_units: 1500
/// units at 10 cm cells and the default air temperature's 75 kg/m³).
SurfaceDef rect(float x0, float z0, float sx, float sz, float y, bool spills) {
    SurfaceDef d = test::rect_surface(x0, z0, sx, sz, y, spills);
    d.edge_limit = 0.01f;
    return d;
}

/// A house (box with a roof surface at y = 1), a porch roof at y = 0.5 along
/// its -x side, and the ground.
struct House {
    Simulation sim;
    SurfaceId ground, roof, porch;
    House(bool roof_spills, std::uint32_t max_flakes = 512)
        : sim([&] {
              SimConfig c;
              c.bounds = {{-4.0f, -1.0f, -4.0f}, {4.0f, 6.0f, 4.0f}};
              c.max_flakes = max_flakes;
              return c;
          }()) {
        ground = sim.add_surface(rect(-3.0f, -3.0f, 6.0f, 6.0f, 0.0f, false));
        const ColliderId box = sim.add_box({{-1.0f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}});
        roof = sim.add_surface(rect(-1.0f, -1.0f, 2.0f, 2.0f, 1.0f, roof_spills), box);
        porch = sim.add_surface(rect(-2.0f, -1.0f, 1.0f, 2.0f, 0.5f, false));
    }
    [[nodiscard]] const SnowSurface& s(SurfaceId e) const { return snow_surface(sim, e); }
    /// Settled snow put on a roof cell.
    void load(SurfaceId e, std::uint32_t ix, std::uint32_t iz, std::uint32_t units) {
        sim.add_settled_snow(e, ix, iz, units);
    }
};

TEST(Spill, EdgeExcessFallsOntoTheSurfaceBelow) {
    House h(true);
    h.load(h.roof, 0, 10, 60000); // on the roof's -x edge, above the porch
    for (int t = 0; t < 600; ++t) {
        h.sim.tick();
        ASSERT_TRUE(h.sim.mass().balanced()) << "tick " << t;
    }
    const std::uint64_t spilled = h.sim.counters().spilled_units;
    EXPECT_GT(spilled, 0u);
    EXPECT_EQ(flake_pool(h.sim).alive, 0u); // everything that fell has landed
    EXPECT_EQ(h.s(h.porch).settled_units(), spilled);
    EXPECT_EQ(h.s(h.ground).settled_units(), 0u);
    EXPECT_EQ(h.s(h.roof).settled_units() + spilled, 60000u);
    EXPECT_EQ(h.sim.mass().removed, 0u);
    // Every edge cell of the roof is back within its limit.
    const SnowSurface& r = h.s(h.roof);
    for (std::uint32_t i = 0; i < r.nz; ++i) {
        EXPECT_LE(r.snow[r.index(0, i)], r.edge_limit_units);
        EXPECT_LE(r.snow[r.index(r.nx - 1, i)], r.edge_limit_units);
        EXPECT_LE(r.snow[r.index(i, 0)], r.edge_limit_units);
        EXPECT_LE(r.snow[r.index(i, r.nz - 1)], r.edge_limit_units);
    }
}

TEST(Spill, NonSpillingSurfaceKeepsItsEdgeSnow) {
    House h(false);
    h.load(h.roof, 0, 10, 60000);
    h.sim.run(300);
    EXPECT_EQ(h.sim.counters().spilled_units, 0u);
    EXPECT_EQ(flake_pool(h.sim).alive, 0u);
    EXPECT_EQ(h.s(h.roof).settled_units(), 60000u);
    EXPECT_GT(h.s(h.roof).snow[h.s(h.roof).index(0, 10)], h.s(h.roof).edge_limit_units);
    EXPECT_TRUE(h.sim.mass().balanced());
}

TEST(Spill, FlakesAppearHalfACellOutsideAtTheSnowTop) {
    House h(true);
    Emitter em;
    em.rate = 0.0f;
    em.crystal = CrystalType::rimed_aggregate;
    h.sim.add_emitter(em);
    const SnowSurface& r = h.s(h.roof);
    // A corner: it sheds diagonally outward.
    h.load(h.roof, r.nx - 1, 0, r.edge_limit_units + 2500);
    const float top = r.top_y(r.index(r.nx - 1, 0));
    spill_system(InternalAccess::world(h.sim));
    const FlakePool& f = flake_pool(h.sim);
    ASSERT_EQ(f.alive, 3u); // 2500 units: 1000 + 1000 + 500
    std::uint32_t units = 0;
    for (std::uint32_t i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(f.px[i], 1.05f);
        EXPECT_FLOAT_EQ(f.pz[i], -1.05f);
        EXPECT_FLOAT_EQ(f.py[i], top);
        EXPECT_EQ(f.vy[i], 0.0f);
        // g over the emitter's mean fall speed
        EXPECT_FLOAT_EQ(f.k_over_m[i], 9.81f / static_cast<float>(spectrum_means(em).fall_speed));
        EXPECT_LE(f.mass_units[i], max_flake_units);
        units += f.mass_units[i];
    }
    EXPECT_EQ(units, 2500u);
    EXPECT_EQ(r.snow[r.index(r.nx - 1, 0)], r.edge_limit_units);
    EXPECT_EQ(h.sim.counters().spilled_units, 2500u);
    EXPECT_TRUE(h.sim.mass().balanced());
}

TEST(Spill, FullPoolLeavesTheSnowOnTheEdge) {
    House h(true, 2);
    const SnowSurface& r = h.s(h.roof);
    h.load(h.roof, 5, 0, r.edge_limit_units + 5000);
    spill_system(InternalAccess::world(h.sim));
    EXPECT_EQ(flake_pool(h.sim).alive, 2u);
    EXPECT_EQ(h.sim.counters().spilled_units, 2000u);
    EXPECT_EQ(r.snow[r.index(5, 0)], r.edge_limit_units + 3000u);
    EXPECT_TRUE(h.sim.mass().balanced());
}

} // namespace
} // namespace snow
