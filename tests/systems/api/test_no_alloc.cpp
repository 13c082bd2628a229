// No allocation inside a tick (issue #8), from the first: the global
// operator new is replaced by one that counts calls while `counting_new` is set;
// ticks of a scene in which every system runs and does real work (flakes
// spawn, land, roll, smooth, spill, hit the sphere, and the sky map refreshes
// as the wind turns) must make none, on 1 and on 2 threads. The Simulation
// readies each system's buffers when the scene is built (prepare_* in
// systems/api/systems.hpp). tests/alloc checks the same through the host's
// allocator on the village.
#include "systems/api/simulation_internals.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/counted_new.hpp"
#include "tests/support/share_work.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace snow {
namespace {

using test::counting_new;
using test::new_calls;

/// Puts snow over the edge limit along one border of every spilling surface
/// (as an embedder might), so the next tick spills.
void overload_edges(Simulation& sim) {
    std::vector<Entity> spilling;
    world_of(sim).each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        if (s.spills) {
            spilling.push_back(e);
        }
    });
    for (const Entity e : spilling) {
        const SnowSurface& s = snow_surface(sim, e);
        const bool cover = world_of(sim).has<SnowCover>(e);
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const std::uint32_t units = 2 * s.edge_limit_units + 5000;
            if (cover) {
                sim.add_settled_snow(id_of<CoverId>(e), ix, 0, units);
            } else {
                sim.add_settled_snow(id_of<SurfaceId>(e), ix, 0, units);
            }
        }
    }
}

/// The stormy yard (every system does real work, the sky map refreshes as
/// the wind turns) with its roof edges over their limit, so it spills at once.
std::unique_ptr<Simulation> busy_scene(unsigned threads) {
    auto sim = make_stormy_yard(threads);
    test::share_work_at_any_size(*sim); // the pool's hand-off must not allocate either
    overload_edges(*sim);
    return sim;
}

TEST(NoAllocation, TicksWithEverySystemAllocateNothingFromTheFirst) {
    constexpr std::uint64_t ticks = 360;
    for (const unsigned threads : {1u, 2u}) {
        auto sim = busy_scene(threads);
        const SimCounters before = sim->counters();
        std::vector<std::uint64_t> calls;
        for (const SystemStats& s : schedule_of(*sim).stats()) {
            calls.push_back(s.calls);
        }
        new_calls = 0;
        counting_new = true;
        sim->run(ticks);
        counting_new = false;
        EXPECT_EQ(new_calls.load(), 0u) << threads << " thread(s)";

        // Every system ran in the counted ticks, and did work.
        const auto& stats = schedule_of(*sim).stats();
        for (std::size_t i = 0; i < stats.size(); ++i) {
            EXPECT_EQ(stats[i].calls, calls[i] + ticks) << stats[i].name;
        }
        const SimCounters& after = sim->counters();
        EXPECT_GT(after.landed, before.landed);
        EXPECT_GT(after.rolled, before.rolled);
        EXPECT_GT(after.smoothing_iterations, before.smoothing_iterations);
        EXPECT_GT(after.spilled_units, before.spilled_units);
        EXPECT_GT(after.occlusion_refreshes, before.occlusion_refreshes);
        EXPECT_GT(after.carved_units, before.carved_units);
        EXPECT_GT(sim->mass().removed, 0u);
        EXPECT_TRUE(sim->mass().balanced());
    }
}

TEST(NoAllocation, CounterSeesAllocations) {
    // The instrument works: a vector growing under counting is seen.
    new_calls = 0;
    counting_new = true;
    std::vector<int> v;
    v.resize(1000);
    counting_new = false;
    EXPECT_GE(new_calls.load(), 1u);
}

} // namespace
} // namespace snow
