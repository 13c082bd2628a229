// [WF §4]: flakes that run into a box are moved to its nearest outside
// point and slide down, which builds a drift at the base of the windward side.
#include "systems/api/simulation_internals.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/units_in.hpp"

#include <gtest/gtest.h>

namespace snow {
namespace {

/// Settled units on the ground in the strip x0 <= x < x1, |z| < 1.5 (the garage's depth).
std::uint64_t strip_units(const Simulation& sim, SurfaceId ground, float x0, float x1) {
    return test::units_in(snow_surface(sim, ground), x0, -1.5f, x1, 1.5f);
}

TEST(Drift, WindwardBaseOfABoxGetsMoreSnowThanTheLeeSide) {
    YardOptions o;
    o.emitter_rate = 8000.0f;
    o.max_flakes = 60000;
    auto sim = make_yard(o); // garage x in [-1, 2], wind +2 m/s along +x
    Wind steady = world_of(*sim).resource<Wind>();
    steady.walk = 0.0f; // steady wind
    sim->set_wind(steady);
    SurfaceId ground;
    world_of(*sim).each<SnowSurface, SurfaceOf>(
        [&](Entity e, const SnowSurface&, const SurfaceOf& of) {
            if (of.owner.is_null()) {
                ground = id_of<SurfaceId>(e);
            }
        });
    sim->run(3000);
    const std::uint64_t windward = strip_units(*sim, ground, -1.5f, -0.9f);
    const std::uint64_t leeward = strip_units(*sim, ground, 1.9f, 2.5f);
    EXPECT_GT(windward, 2 * leeward) << "windward " << windward << ", leeward " << leeward;
    RecordProperty("windward_units", std::to_string(windward));
    RecordProperty("leeward_units", std::to_string(leeward));
    EXPECT_TRUE(sim->mass().balanced());
}

} // namespace
} // namespace snow
