// The flake pass (integrate, collide and deposit per block of slots) against
// the three stages run one after another over the whole pool.
#include "systems/api/simulation_internals.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/mass_ledger.hpp"
#include "systems/flakes/flake_stages.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/share_work.hpp"

#include <gtest/gtest.h>

namespace snow {
namespace {

// The stormy yard has every kind of collider and surface (boxes, a sphere,
// mesh tops through the sky map, a cover, moving bodies, a wind field): after
// its storm has filled the air, one flake pass and the three stages in turn
// must leave the same state, tick after tick, on 1 and on 2 threads.
TEST(FlakePass, SameAsStagesOneAtATime) {
    for (const unsigned threads : {1u, 2u}) {
        SCOPED_TRACE(threads);
        auto fused = make_stormy_yard(threads);
        auto staged = make_stormy_yard(threads);
        test::share_work_at_any_size(*fused);
        test::share_work_at_any_size(*staged);
        for (int t = 0; t < 240; ++t) {
            fused->tick();
            staged->tick();
        }
        ASSERT_GT(flake_pool(*fused).alive, 1000u) << "the air must hold flakes to compare";
        const std::uint32_t alive_before = flake_pool(*fused).alive;
        int shared = 0;
        for (int t = 0; t < 30; ++t) {
            flake_pass_system(InternalAccess::world(*fused));
            shared += deposit_prefilter_sparse(InternalAccess::world(*fused)) ? 1 : 0;
            World& w = InternalAccess::world(*staged);
            integrate_system(w);
            collide_system(w);
            deposit_system(w);
            ASSERT_EQ(fused->state_hash(), staged->state_hash()) << "pass " << t;
        }
        EXPECT_LT(flake_pool(*fused).alive, alive_before) << "flakes landed or left meanwhile";
        EXPECT_GT(shared, 0) << "the shared prefilter must have run";
        EXPECT_TRUE(fused->mass().balanced());
    }
}

// A flake that collide removes is not landed as well: falling through a
// ground whose bare top is the bounds' floor, it leaves by the floor (collide
// runs first) and its units are counted once.
TEST(FlakePass, AFlakeCollideRemovesDoesNotLand) {
    SimConfig c;
    c.seed = 3;
    c.bounds = {{-2.0f, 0.0f, -2.0f}, {2.0f, 4.0f, 2.0f}};
    c.max_flakes = 8;
    Simulation sim(c);
    SurfaceDef ground;
    ground.x0 = ground.z0 = -1.0f;
    ground.size_x = ground.size_z = 2.0f;
    ground.cell = 0.1f;
    (void)sim.add_surface(ground);
    FlakeSpec f;
    f.position = {0.05f, 0.01f, 0.05f};
    f.velocity = {0.0f, -3.0f, 0.0f};
    ASSERT_TRUE(sim.place_flake(f).has_value());
    sim.tick();
    const MassReport m = sim.mass();
    EXPECT_TRUE(m.balanced());
    EXPECT_EQ(m.removed, 1u);
    EXPECT_EQ(m.settled, 0u);
    EXPECT_EQ(flake_pool(sim).alive, 0u);
}

} // namespace
} // namespace snow
