#include "systems/api/simulation_internals.hpp"
#include "systems/core/units.hpp"
#include "systems/flakes/snowfall.hpp"
#include "tests/support/box_world.hpp"

#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <cmath>

namespace snow {
namespace {

TEST(Spawn, RateOnAverageAndPoolLimitHolds) {
    Simulation sim(test::box_world(100000));
    Emitter e;
    e.rate = 600.0f; // 10 per tick at 60 Hz
    sim.add_emitter(e);
    sim.tick(); // spawn runs before integrate: 1 tick of spawning
    sim.run(59);
    // Nothing lands or leaves in one second from 10 m up at <= 1.5 m/s.
    EXPECT_NEAR(static_cast<double>(flake_pool(sim).alive), 600.0, 3.0);

    Simulation small(test::box_world(50));
    small.add_emitter(e);
    small.run(100);
    EXPECT_EQ(flake_pool(small).alive, 50u);
    EXPECT_EQ(flake_pool(small).max_alive, 50u);
    EXPECT_TRUE(small.mass().balanced());
}

TEST(Spawn, StillAirFlakesComeFromTheTopWithDrawnProperties) {
    Simulation sim(test::box_world(10000));
    Emitter e;
    e.rate = 60000.0f;
    e.snowfall_kg_m2_h = 300.0f; // ~14 units a parcel: rounding releases few
    sim.add_emitter(e);
    sim.tick();
    const FlakePool& f = flake_pool(sim);
    ASSERT_GT(f.alive, 500u);
    for (std::uint32_t i = 0; i < f.capacity(); ++i) {
        if (!f.is_alive(i)) {
            continue;
        }
        EXPECT_GT(f.py[i], 9.9f); // top face, moved down by one tick at most
        EXPECT_GE(f.mass_units[i], 1u);
        EXPECT_LE(f.mass_units[i], max_flake_units);
        EXPECT_GE(f.size[i], e.size_min);
        EXPECT_LE(f.size[i], e.size_max);
        const float fall = 9.81f / f.k_over_m[i];
        EXPECT_NEAR(fall, fall_speed(e.crystal, f.size[i]), 1e-5f); // the size's [LH74] speed
    }
}

TEST(Spawn, WindFeedsTheUpwindSide) {
    Simulation sim(test::box_world(20000));
    Wind wind;
    wind.base = wind.current = {8.0f, 0.0f, 0.0f};
    wind.walk = 0.0f;
    sim.set_wind(wind);
    Emitter e;
    e.rate = 60000.0f;
    sim.add_emitter(e);
    sim.tick();
    const FlakePool& f = flake_pool(sim);
    std::uint32_t upwind = 0, downwind = 0;
    for (std::uint32_t i = 0; i < f.capacity(); ++i) {
        // Side-born flakes are below the top face; top-born ones drift a little.
        if (f.is_alive(i) && f.py[i] < 9.8f) {
            upwind += f.px[i] < -4.8f ? 1 : 0;
            downwind += f.px[i] > 4.8f ? 1 : 0;
        }
    }
    EXPECT_GT(upwind, 100u);
    EXPECT_EQ(downwind, 0u);
}

TEST(Wind, RandomWalkStaysBounded) {
    Simulation sim(test::box_world(16));
    Wind w;
    w.base = w.current = {3.0f, 0.0f, 1.0f};
    w.walk = 5.0f; // a wild walk, still bounded
    w.max_deviation = 0.75f;
    sim.set_wind(w);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (int t = 0; t < 5000; ++t) {
        sim.tick();
        const glm::vec3 c = world_of(sim).resource<Wind>().current;
        const glm::vec3 d = c - w.base;
        ASSERT_LE(std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z), 0.75f + 1e-5f);
        lo = glm::min(lo, c);
        hi = glm::max(hi, c);
    }
    EXPECT_GT(hi.x - lo.x, 0.5f); // it does move
}

TEST(Wind, GustsRiseAboveTheWalk) {
    Simulation sim(test::box_world(16));
    Wind w;
    w.base = w.current = {2.0f, 0.0f, 0.0f};
    w.walk = 0.0f;
    w.gust_strength = 10.0f;
    w.gust_rate = 0.5f;
    sim.set_wind(w);
    float peak = 0.0f;
    for (int t = 0; t < 1200; ++t) {
        sim.tick();
        peak = std::max(peak, world_of(sim).resource<Wind>().current.x);
    }
    EXPECT_GT(peak, 9.0f);
    EXPECT_LE(peak, 12.0f + 1e-4f);
}

TEST(Wind, NoWindResourceNoWindSystem) {
    Simulation sim(test::box_world(16));
    sim.run(3);
    EXPECT_FALSE(schedule_of(sim).would_run("wind", world_of(sim)));
    for (const auto& s : schedule_of(sim).stats()) {
        if (s.name == "wind" || s.name == "spawn") {
            EXPECT_EQ(s.calls, 0u);
        }
    }
}

TEST(SimulationApi, BadInputIsRejectedAndStateUnchanged) {
    Simulation sim(test::box_world(100));
    Emitter e;
    sim.add_emitter(e);
    sim.run(10);
    const std::uint64_t before = sim.state_hash();
    Emitter bad = e;
    bad.rate = std::nanf("");
    EXPECT_THROW(sim.add_emitter(bad), SimulationError);
    bad = e;
    bad.size_mean = -1.0f;
    EXPECT_THROW(sim.add_emitter(bad), SimulationError);
    Wind w;
    w.base.x = INFINITY;
    EXPECT_THROW(sim.set_wind(w), SimulationError);
    EXPECT_THROW(sim.add_sphere({0, 0, 0}, -1.0f), SimulationError);
    EXPECT_THROW(sim.add_box({{1, 1, 1}, {0, 0, 0}}), SimulationError);
    EXPECT_THROW(sim.add_mesh_collider({{0, 0, 0}, {1, 0, 0}}), SimulationError);
    SurfaceDef s;
    s.cell = 0.0f;
    EXPECT_THROW(sim.add_surface(s), SimulationError);
    EXPECT_THROW(sim.remove(BodyId{}), SimulationError);
    EXPECT_EQ(sim.state_hash(), before);
    SimConfig c;
    c.dt = -0.1f;
    EXPECT_THROW(Simulation{c}, SimulationError);
    c.dt = std::nanf("");
    EXPECT_THROW(Simulation{c}, SimulationError);
    c = SimConfig{};
    c.threads = 0;
    EXPECT_THROW(Simulation{c}, SimulationError);
    try {
        Emitter named = e;
        named.size_min = -2.0f;
        sim.add_emitter(named);
        FAIL();
    } catch (const SimulationError& err) {
        EXPECT_NE(std::string(err.what()).find("emitter.size_min"), std::string::npos);
    }
}

} // namespace
} // namespace snow
