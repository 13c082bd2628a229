// Porous fences: a box collider with a porosity lets the air through against
// a pressure loss [Wil85] [Idel], so the wind slows behind it less than
// behind a solid one, and over hours of drifting it grows a lee drift
// towards Tabler's [Tab80] (docs/wind_field.md "Porous fences").
#include "systems/api/simulation_internals.hpp"
#include "systems/wind/fence_resistance.hpp"
#include "tests/scenes/fence_drift.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace snow {
namespace {

FenceDriftResult blow_at(float porosity) {
    FenceDrift run;
    run.porosity = porosity;
    run.seconds = 20.0f;
    return fence_drift(run);
}

TEST(WindFence, PressureLossFollowsIdelchiksLaw) {
    EXPECT_NEAR(fence_pressure_loss(0.5), 4.37, 0.01);
    EXPECT_GT(fence_pressure_loss(0.2), fence_pressure_loss(0.5)) << "denser: more loss";
    EXPECT_NEAR(fence_pressure_loss(1.0), 0.0, 1e-12) << "all open: none";
}

TEST(WindFence, AirBleedsThroughAPorousFenceAndSlowsBehindIt) {
    const FenceDriftResult none = blow_at(1.0f), porous = blow_at(0.5f), solid = blow_at(0.0f);
    EXPECT_NEAR(none.lee_wind_over_free, 1.0, 0.02) << "no fence: the free wind";
    // 2–6 H behind a 50% fence half a height up: slowed, but forward (the
    // bleed flow), and faster than behind a solid fence's eddy.
    EXPECT_GT(porous.lee_wind_over_free, 0.15);
    EXPECT_LT(porous.lee_wind_over_free, 0.6);
    EXPECT_GT(porous.lee_wind_over_free, solid.lee_wind_over_free + 0.1);
    for (const FenceDriftResult* r : {&none, &porous, &solid}) {
        EXPECT_TRUE(r->balanced) << "the ledger holds every tick";
        EXPECT_GT(r->fetch_loss, 0.02) << "the wind carries the fetch's snow";
    }
    // With no fence the snow the fetch lost passes on (the drifts a fence
    // grows take hours: ALeeDriftGrows... below).
    EXPECT_NEAR(none.lee_gain + none.windward_gain, 0.0, 1e-9);
}

TEST(WindFence, ALeeDriftGrowsBehindAPorousFenceInAFastForward) {
    // 83 and 167 hours of drifting.
    FenceDrift run = towards_equilibrium(120.0f);
    run.shape_at = {60.0f, 120.0f};
    const FenceDriftResult r = fence_drift(run);
    ASSERT_EQ(r.shapes.size(), 2u);
    const DriftShape &early = r.shapes[0], &late = r.shapes[1];
    EXPECT_TRUE(r.balanced);
    EXPECT_GT(late.lee_length, early.lee_length) << "the lee drift grows downwind";
    EXPECT_GT(late.lee_depth, early.lee_depth) << "and deeper";
    EXPECT_GT(late.lee_length, 20.0) << "H: Tabler's reach 30 H";
    EXPECT_GT(late.lee_depth, 0.15) << "H";
    EXPECT_GT(r.lee_gain, 3.0 * r.windward_gain) << "a 50% fence stores its snow in its lee";
}

TEST(WindFence, BadPorosityIsNamedAndNothingIsAdded) {
    Simulation sim{SimConfig{}};
    const std::uint64_t before = sim.state_hash();
    for (const float bad : {-0.1f, 1.0f, std::nanf("")}) {
        try {
            (void)sim.add_box({{0.0f, 0.0f, 0.0f}, {0.1f, 1.0f, 1.0f}}, bad);
            ADD_FAILURE() << "accepted porosity " << bad;
        } catch (const SimulationError& e) {
            EXPECT_EQ(e.field(), "box.porosity") << e.what();
        }
    }
    EXPECT_EQ(sim.state_hash(), before) << "nothing was added";
}

TEST(WindFence, APorousBoxHashesItsPorosityAndASolidOneAsBefore) {
    const auto hash_with = [](float porosity) {
        Simulation sim{SimConfig{}};
        (void)sim.add_box({{0.0f, 0.0f, 0.0f}, {0.1f, 1.0f, 1.0f}}, porosity);
        return sim.state_hash();
    };
    const auto solid_hash = [] {
        Simulation sim{SimConfig{}};
        (void)sim.add_box({{0.0f, 0.0f, 0.0f}, {0.1f, 1.0f, 1.0f}});
        return sim.state_hash();
    }();
    EXPECT_EQ(hash_with(0.0f), solid_hash);
    EXPECT_NE(hash_with(0.5f), solid_hash);
    EXPECT_NE(hash_with(0.5f), hash_with(0.4f));
}

} // namespace
} // namespace snow
