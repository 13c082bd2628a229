// The facade is the only writer: world() is read only, and the calls that
// change a running simulation (emitter rate, fog, moving boxes, hand-placed
// flakes and snow) take effect, keep the mass books exact and reject bad input.
#include "systems/api/simulation_internals.hpp"
#include "systems/geometry/colliders.hpp"

#include <snow/snow.hpp>

#include <gtest/gtest.h>

#include <type_traits>
#include <utility>

namespace snow {
namespace {

template <typename S>
concept ExposesItsWorld = requires(S& s) {
    s.world();
};
static_assert(!ExposesItsWorld<Simulation>, "the World stays behind the facade");

SimConfig small_box() {
    SimConfig c;
    c.seed = 5;
    c.bounds = {{-2.0f, -0.5f, -2.0f}, {2.0f, 4.0f, 2.0f}};
    c.max_flakes = 8;
    return c;
}

TEST(Facade, EmitterRateChangesTheSnowfall) {
    SimConfig c = small_box();
    c.max_flakes = 20000;
    Simulation sim(c);
    Emitter e;
    e.rate = 0.0f;
    const EmitterId emitter = sim.add_emitter(e);
    sim.run(30);
    EXPECT_EQ(sim.mass().spawned, 0u);
    sim.set_emitter_rate(emitter, 3000.0f);
    EXPECT_EQ(world_of(sim).get<Emitter>(entity_of(emitter)).rate, 3000.0f);
    sim.run(30);
    EXPECT_GT(flake_pool(sim).alive, 500u);
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(Facade, MovedBoxDeflectsFlakesWhereItNowIs) {
    Simulation sim(small_box());
    const ColliderId box = sim.add_box({{-1.0f, 0.0f, -1.0f}, {-0.5f, 1.0f, 1.0f}});
    const std::uint64_t solids = world_of(sim).resource<SourceVersions>().solids;
    const Aabb moved{{0.5f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}};
    sim.move_box(box, moved);
    EXPECT_EQ(world_of(sim).get<BoxCollider>(entity_of(box)).box.min, moved.min);
    EXPECT_GT(world_of(sim).resource<SourceVersions>().solids, solids);
    // A flake moving fast along +x enters the box's new place this tick: it
    // ends on the face it came through.
    const auto slot = sim.place_flake({{0.45f, 0.5f, 0.0f}, {30.0f, 0.0f, 0.0f}});
    ASSERT_TRUE(slot.has_value());
    sim.tick();
    ASSERT_TRUE(flake_pool(sim).is_alive(*slot));
    EXPECT_EQ(flake_pool(sim).px[*slot], moved.min.x);
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(Facade, PlacedFlakesAreBookedAndAFullPoolSaysSo) {
    Simulation sim(small_box());
    for (std::uint32_t i = 0; i < 8; ++i) {
        FlakeSpec f;
        f.position = {0.0f, 3.0f, 0.0f};
        f.mass_units = 10 + i;
        EXPECT_EQ(sim.place_flake(f), i);
    }
    EXPECT_FALSE(sim.place_flake(FlakeSpec{}).has_value()) << "the pool holds 8";
    EXPECT_EQ(sim.mass().spawned, 8u * 10u + 28u);
    EXPECT_EQ(sim.mass().airborne, sim.mass().spawned);
    EXPECT_EQ(flake_pool(sim).alive, 8u);
}

TEST(Facade, SettledSnowIsBookedAndSmoothed) {
    Simulation sim(small_box());
    SurfaceDef d;
    d.x0 = d.z0 = -1.0f;
    d.size_x = d.size_z = 2.0f;
    d.spills = false;
    const SurfaceId ground = sim.add_surface(d);
    sim.add_settled_snow(ground, 20, 20, 500000); // one tall column
    const SnowSurface& s = snow_surface(sim, ground);
    EXPECT_EQ(s.snow[s.index(20, 20)], 500000u);
    EXPECT_FALSE(s.dirty_empty());
    EXPECT_EQ(sim.mass().settled, 500000u);
    EXPECT_TRUE(sim.mass().balanced());
    sim.run(5);
    EXPECT_LT(s.snow[s.index(20, 20)], 500000u) << "redistribution spreads the column";
    EXPECT_EQ(sim.mass().settled, 500000u);
}

} // namespace
} // namespace snow
