// Determinism as Box2D and Jolt test it (docs/design.md "Determinism"): the
// same scene and seed give the same state hash run after run, and 1 and 2
// threads agree on every tick.
#include "systems/api/simulation_internals.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/share_work.hpp"

#include <gtest/gtest.h>

namespace snow {
namespace {

/// The busy yard, its chunks shared by the threads although it is small.
std::unique_ptr<Simulation> busy(unsigned threads) {
    auto sim = make_yard(busy_yard(threads));
    test::share_work_at_any_size(*sim);
    return sim;
}

TEST(Determinism, SameSeedSameHash) {
    auto a = busy(1);
    auto b = busy(1);
    a->run(300);
    b->run(300);
    EXPECT_EQ(a->state_hash(), b->state_hash());
    auto c = make_yard([] {
        YardOptions o = busy_yard(1);
        o.seed = 8;
        return o;
    }());
    c->run(300);
    EXPECT_NE(a->state_hash(), c->state_hash());
}

TEST(Determinism, OneAndTwoThreadsAgreeEveryTick) {
    auto one = busy(1);
    auto two = busy(2);
    for (int t = 0; t < 400; ++t) {
        one->tick();
        two->tick();
        ASSERT_EQ(one->state_hash(), two->state_hash()) << "tick " << t;
    }
    EXPECT_GT(one->counters().landed, 0u);
}

TEST(Determinism, PinnedHashHoldsInEveryBuild) {
    // Box2D's test_determinism habit: the hash after N ticks is a constant
    // here, so CI's Debug (ASan, scalar, SNOW_NATIVE off) and Release (-O3,
    // vectorised, -march=native) builds must agree with each other and with
    // the run that pinned it. Re-pin only with a reason in the commit message.
    // (Last re-pinned when snow got its density (issue #30 item 2): a level
    // is one unit at the fresh density of the air temperature [HP98], so
    // every unit height changed, and every surface keeps its compaction from
    // the start for settling [And76]; before, 0x745319f79cc88d3e, and before
    // flakes got sizes, 0x9cbe11bf6725c2f2.)
    constexpr std::uint64_t pinned = 0x69aca2a5e7de0ffbull;
    for (const unsigned threads : {1u, 2u}) {
        auto sim = busy(threads);
        sim->run(300);
        EXPECT_EQ(sim->state_hash(), pinned)
            << threads << " thread(s): got 0x" << std::hex << sim->state_hash();
    }
    // 2 threads that keep this small yard's passes on the calling thread
    // (for_chunks' default threshold): the same chunks, the same hash.
    auto unshared = make_yard(busy_yard(2));
    unshared->run(300);
    EXPECT_EQ(unshared->state_hash(), pinned) << "got 0x" << std::hex << unshared->state_hash();
}

TEST(Determinism, SaveRestoreReplaysExactly) {
    auto sim = busy(1);
    sim->run(100);
    const auto snap = save_snapshot(*sim);
    sim->run(150);
    const std::uint64_t first = sim->state_hash();
    restore_snapshot(*sim, *snap);
    sim->run(150);
    EXPECT_EQ(sim->state_hash(), first);
}

TEST(Determinism, MassBalancedEveryTick) {
    auto sim = busy(2);
    for (int t = 0; t < 600; ++t) {
        sim->tick();
        const MassReport m = sim->mass();
        ASSERT_TRUE(m.balanced()) << "tick " << t << ": " << m.spawned << " != " << m.airborne
                                  << " + " << m.settled << " + " << m.removed;
    }
    EXPECT_GT(sim->mass().settled, 0u);
    EXPECT_GT(sim->mass().removed, 0u);
    EXPECT_EQ(sim->nonfinite_count(), 0u);
}

} // namespace
} // namespace snow
