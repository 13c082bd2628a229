// Hard case 2: only the heaviest parcels (5 g = max_flake_units) with a long
// tick (dt = 0.25 s) in still air. The parcels are 1 mm graupel, which falls
// at 0.79 m/s, so c·dt = g·dt/v = 3.1: past explicit Euler's limit of 2. Flakes must stay finite,
// keep their exact mass and land. One landing is 2 cm of snow on a 5 cm ground cell, a Laplacian of
// 4000 units against the cap of 2500 [WF §3], so every landing is smoothed; the shed's roof spills
// clumps cut into <= 1000 units.
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"

#include "systems/core/units.hpp"

namespace snow {
namespace {

struct HeavyScene {
    std::unique_ptr<Simulation> sim;
    SurfaceId ground;
    SurfaceId roof;
};

/// 8 × 8 m still-air yard with a shed, emitting only 5 g parcels at dt = 0.25 s.
HeavyScene heavy_scene(Integrator integ) {
    SimConfig cfg;
    cfg.seed = 5;
    cfg.dt = 0.25f;
    cfg.integrator = integ;
    cfg.bounds = {{-4.0f, -0.5f, -4.0f}, {4.0f, 8.0f, 4.0f}};
    cfg.max_flakes = 4000;
    HeavyScene s{std::make_unique<Simulation>(cfg), {}, {}};
    SurfaceDef ground;
    ground.x0 = ground.z0 = -4.0f;
    ground.size_x = ground.size_z = 8.0f;
    ground.cell = 0.05f;
    ground.spills = false;
    s.ground = s.sim->add_surface(ground);
    const Aabb shed{{-1.0f, 0.0f, -1.0f}, {1.0f, 1.5f, 1.0f}};
    const ColliderId box = s.sim->add_box(shed);
    SurfaceDef roof;
    roof.x0 = roof.z0 = -1.0f;
    roof.size_x = roof.size_z = 2.0f;
    roof.cell = 0.1f;
    roof.base_y = shed.max.y;
    roof.edge_limit = 0.02f; // spills: shed clumps are cut into <= 1000-unit flakes
    s.roof = s.sim->add_surface(roof, box);
    Emitter e;
    e.rate = 200.0f;
    e.crystal = CrystalType::rimed_aggregate;
    e.size_min = e.size_max = 0.001f;
    e.snowfall_kg_m2_h = 3600.0f / 64.0f; // 1 kg/s over the 8 × 8 m yard: 5 g per parcel
    s.sim->add_emitter(e);
    return s;
}

TEST(HardCaseHeavyFlakes, FiveGramFlakesWithQuarterSecondTicksLandWithExactMass) {
    for (const Integrator integ :
         {Integrator::explicit_euler, Integrator::semi_implicit_euler, Integrator::exponential,
          Integrator::rk4, Integrator::automatic}) {
        SCOPED_TRACE(integrator_name(integ));
        HeavyScene s = heavy_scene(integ);
        Simulation& sim = *s.sim;
        const int ticks = hard::scaled(400, 160); // 100 s (40 s in sanitizer/Debug builds)
        for (int t = 0; t < ticks; ++t) {
            sim.tick();
            ASSERT_TRUE(hard::healthy(sim));
            const FlakePool& f = flake_pool(sim);
            for (std::uint32_t i = 0; i < f.slot_end; ++i) {
                ASSERT_LE(f.mass_units[i], max_flake_units) << "slot " << i;
            }
        }
        const auto& ledger = world_of(sim).resource<MassLedger>();
        // Every emitted flake weighs exactly 5 g: the books hold whole 1000-unit flakes.
        EXPECT_GT(ledger.spawned, 0u);
        EXPECT_EQ(ledger.spawned % max_flake_units, 0u);
        const hard::CellStats ground = hard::cell_stats(hard::surface(sim, s.ground));
        const hard::CellStats roof = hard::cell_stats(hard::surface(sim, s.roof));
        EXPECT_GT(sim.counters().landed, 1000u);
        EXPECT_GT(roof.sum, 0u);
        EXPECT_EQ(ground.wrapped + roof.wrapped, 0u);
        // Still air: every flake not in the air has landed; none left the yard.
        // (Guards against deposit missing flakes the snow grew over: see the next test.)
        EXPECT_EQ(ledger.removed(), 0u)
            << "units that fell through the ground: " << ledger.removed_bounds;
        EXPECT_EQ(ground.sum + roof.sum + sim.mass().airborne, ledger.spawned);
        const bool guarded = integ == Integrator::explicit_euler || integ == Integrator::rk4 ||
                             integ == Integrator::automatic;
        if (guarded) {
            EXPECT_GT(sim.counters().stiff_flake_ticks, 0u); // c·dt past the limit was noticed
        }
    }
}

TEST(HardCaseHeavyFlakes, FlakeInsideTheSnowLayerLandsEvenWhenItsTickEndsBelowTheBareTop) {
    // Found by the scene above: smoothing (or another flake's roll) raises a
    // cell's snow over a flake hovering just above it. On its next tick the
    // flake starts inside the snow layer; with dt = 0.25 s it moves 0.3 m and
    // ends below the bare top, and deposit.cpp's test (y_prev >= top − tol or
    // y >= bare − tol) accepts neither, so the flake falls through the ground
    // and leaves through the bounds floor. Here the flake is placed inside
    // 2.2 cm of snow directly.
    SimConfig cfg;
    cfg.dt = 0.25f;
    cfg.bounds = {{-1.0f, -0.5f, -1.0f}, {1.0f, 1.0f, 1.0f}};
    cfg.max_flakes = 4;
    Simulation sim(cfg);
    SurfaceDef d;
    d.x0 = d.z0 = -1.0f;
    d.size_x = d.size_z = 2.0f;
    d.cell = 0.05f;
    d.spills = false;
    const SurfaceId e = sim.add_surface(d);
    const SnowSurface& s = hard::surface(sim, e);
    std::uint32_t ix = 0, iz = 0;
    ASSERT_TRUE(s.cell_at(0.01f, 0.01f, ix, iz));
    const std::uint32_t depth_units = 1100; // 2.2 cm at 2e-5 m per unit
    sim.add_settled_snow(e, ix, iz, depth_units);
    // 0.8 cm above the bare top, 1.4 cm under the snow top, falling at 1.28 m/s.
    hard::place_flake(sim, {0.01f, 0.008f, 0.01f}, {0.0f, -1.28f, 0.0f}, 7.67f, max_flake_units);
    sim.run(2); // missed, it is at y = -0.31 after one tick and out of the bounds after two
    ASSERT_TRUE(hard::healthy(sim));
    EXPECT_EQ(world_of(sim).resource<MassLedger>().removed(), 0u) << "fell out of the bounds";
    EXPECT_EQ(sim.counters().landed, 1u);
    EXPECT_EQ(hard::cell_stats(s).sum, depth_units + max_flake_units);
}

} // namespace
} // namespace snow
