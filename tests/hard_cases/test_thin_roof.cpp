// Hard case 6: a roof 1 mm thick (a box 1 mm high with a snow surface on
// top) hit by flakes moving at 200 m/s, 3.3 m per tick at dt = 1/60. None
// may tunnel: every flake must end as snow on the roof, none on the ground
// below it, none removed. The flakes have ordinary drag (k/m = 9.81/s, 1 m/s
// terminal speed), so they slow down by ~15% during the tick that crosses the
// roof, and, for the stiff variant, by 86% (k·dt/m = 2, past explicit
// Euler's limit, where the exact update takes over).
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"

#include "ecs/rng.hpp"
#include "systems/core/random_streams.hpp"

#include <algorithm>

namespace snow {
namespace {

constexpr float roof_y0 = 1.0f;
constexpr float roof_y1 = 1.001f;

struct RoofRun {
    std::uint64_t flakes = 0;
    std::uint64_t on_roof = 0;   ///< units settled on the roof
    std::uint64_t on_ground = 0; ///< units settled on the ground below
    std::uint64_t removed = 0;
    std::uint32_t alive = 0;
    std::uint64_t below = 0; ///< units still airborne under the roof's top
};

/// Fires `n` flakes at the roof from up to 10 m above it, each aimed
/// to cross the roof's top inside its footprint, and runs until all are down.
/// `floor` is the bottom of the simulation bounds (the ground is at 0).
/// Without `solid` the roof is a bare surface with no box under it, so only
/// deposit's own crossing test can stop a flake; that test looks at the
/// column a flake ends in (README "Known limits"), so these flakes fall
/// straight down.
RoofRun fire_at_thin_roof(Integrator integ, float k_over_m, float floor, std::uint32_t n,
                          bool solid) {
    SimConfig cfg;
    cfg.seed = 6;
    cfg.integrator = integ;
    cfg.bounds = {{-8.0f, floor, -8.0f}, {8.0f, 12.0f, 8.0f}};
    cfg.max_flakes = n;
    Simulation sim(cfg);
    SurfaceDef g;
    g.x0 = g.z0 = -8.0f;
    g.size_x = g.size_z = 16.0f;
    g.cell = 0.25f;
    g.spills = false;
    const SurfaceId ground = sim.add_surface(g);
    SurfaceDef r;
    r.x0 = r.z0 = -1.0f;
    r.size_x = r.size_z = 2.0f;
    r.cell = 0.1f;
    r.base_y = roof_y1;
    r.spills = false; // every unit that lands stays where it can be counted
    const SurfaceId roof =
        solid ? sim.add_surface(r, sim.add_box({{-1.0f, roof_y0, -1.0f}, {1.0f, roof_y1, 1.0f}}))
              : sim.add_surface(r);
    // Drag alone would stop a flake within v0/c (1.7 m at c = 120/s): start
    // close enough that it is still fast when it reaches the roof.
    const float max_above = std::min(10.0f, 0.8f * 200.0f / k_over_m);
    for (std::uint32_t i = 0; i < n; ++i) {
        const RngKey k{cfg.seed, 0, i, random_stream::test};
        // Crossing point well inside the footprint, height above the roof, slant.
        const glm::vec3 cross{rng_range(k, 0, -0.8f, 0.8f), roof_y1, rng_range(k, 1, -0.8f, 0.8f)};
        const float above = rng_range(k, 2, 0.002f, max_above);
        const float slant = solid ? 40.0f : 0.0f;
        const glm::vec3 v{rng_range(k, 3, -slant, slant), -200.0f, rng_range(k, 4, -slant, slant)};
        const float s = above / 200.0f; // seconds to the roof at full speed
        hard::place_flake(sim, cross - v * s, v, k_over_m, 1 + i % 7);
    }
    RoofRun out;
    out.flakes = sim.mass().spawned;
    for (int t = 0; t < 900; ++t) { // 15 s: tunnelled stiff flakes fall at 8 cm/s
        sim.tick();
        EXPECT_TRUE(hard::healthy(sim));
    }
    out.on_roof = hard::cell_stats(hard::surface(sim, roof)).sum;
    out.on_ground = hard::cell_stats(hard::surface(sim, ground)).sum;
    out.removed = world_of(sim).resource<MassLedger>().removed();
    const FlakePool& f = flake_pool(sim);
    out.alive = f.alive;
    for (std::uint32_t i = 0; i < f.slot_end; ++i) {
        out.below += f.is_alive(i) && f.py[i] < roof_y1 ? f.mass_units[i] : 0;
    }
    return out;
}

/// Bounds floor far below the roof: nothing but the roof can stop a flake.
constexpr float deep_floor = -100.0f;

/// Fires 2000 flakes and expects every unit on the roof.
void expect_no_tunnelling(Integrator integ, float k_over_m, float floor = deep_floor,
                          bool solid = true) {
    const RoofRun r = fire_at_thin_roof(integ, k_over_m, floor, 2000, solid);
    EXPECT_EQ(r.alive, 0u);
    EXPECT_EQ(r.below, 0u) << "units still falling under the roof";
    EXPECT_EQ(r.on_roof, r.flakes) << "units that did not end on the roof";
    EXPECT_EQ(r.on_ground, 0u) << "units that tunnelled to the ground";
    EXPECT_EQ(r.removed, 0u) << "units removed (out of bounds below the roof)";
}

TEST(HardCaseThinRoof, NoTunnellingExplicitEuler) {
    expect_no_tunnelling(Integrator::explicit_euler, 9.81f);
}
TEST(HardCaseThinRoof, NoTunnellingSemiImplicitEuler) {
    expect_no_tunnelling(Integrator::semi_implicit_euler, 9.81f);
}
TEST(HardCaseThinRoof, NoTunnellingAutomatic) {
    expect_no_tunnelling(Integrator::automatic, 9.81f);
}
// The exponential and RK4 rules move a flake by its mean velocity over the
// tick: rebuilding the path's start as p − v_end·dt would put it up to
// ~0.25 m below the real one for these decelerating flakes, and a flake that
// began less than that above the roof would cross it unseen (the bug this
// suite found; collide and deposit now read the start integrate recorded,
// PathStarts, flake_stages.hpp).
TEST(HardCaseThinRoof, NoTunnellingExponential) {
    expect_no_tunnelling(Integrator::exponential, 9.81f);
}
TEST(HardCaseThinRoof, NoTunnellingRk4) {
    expect_no_tunnelling(Integrator::rk4, 9.81f);
}
TEST(HardCaseThinRoof, NoTunnellingStiffDragUnderTheExplicitGuard) {
    // k·dt/m = 2: explicit Euler hands these flakes to the exact update.
    expect_no_tunnelling(Integrator::explicit_euler, 120.0f);
}
// The bounds 1 m below the ground (the sample scenes use 0.5 m): a flake that
// crosses the roof and ends below the bounds in the same tick must be stopped
// by the roof, not removed as out of bounds (collide tests colliders first).
TEST(HardCaseThinRoof, NoTunnellingNearTheBoundsFloor) {
    expect_no_tunnelling(Integrator::explicit_euler, 9.81f, -1.0f);
}
// A surface with no box under it (an embedder's bare heightfield): deposit's
// crossing test alone must catch the path, from where the rule really moved it.
TEST(HardCaseThinRoof, NoTunnellingThroughASurfaceWithoutABox) {
    for (const Integrator integ : {Integrator::explicit_euler, Integrator::exponential,
                                   Integrator::rk4, Integrator::semi_implicit_euler}) {
        SCOPED_TRACE(std::string(integrator_name(integ)));
        expect_no_tunnelling(integ, 9.81f, deep_floor, false);
    }
}

} // namespace
} // namespace snow
