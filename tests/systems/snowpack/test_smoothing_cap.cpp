// SimConfig::smoothing_iterations caps the redistribution sub-iterations per
// surface per tick (a knob of the accuracy study, docs/accuracy.md). A pile
// still moving at the cap goes on next tick: the cap changes when snow
// settles, never where it ends up or how much there is.
#include "systems/api/simulation_internals.hpp"
#include "tests/support/settle.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace snow {
namespace {

struct Pile {
    Simulation sim;
    SurfaceId e;
    explicit Pile(std::uint32_t cap) : sim(config(cap)), e(sim.add_surface(square())) {
        sim.add_settled_snow(e, 16, 16, 2'000'000); // far over the Laplacian cap: many steps
    }
    static SimConfig config(std::uint32_t cap) {
        SimConfig c;
        c.smoothing_iterations = cap;
        return c;
    }
    static SurfaceDef square() {
        SurfaceDef d;
        d.size_x = d.size_z = 1.6f; // 32 × 32 cells of 0.05 m
        d.spills = false;
        return d;
    }
    [[nodiscard]] const SnowSurface& surface() const { return snow_surface(sim, e); }
    int settle(int max_calls) { return test::settle_surface(sim, e, max_calls); }
};

TEST(SmoothingCap, OneCallRunsAtMostTheCap) {
    for (const std::uint32_t cap : {1u, 4u, 64u}) {
        Pile p(cap);
        redistribute_system(InternalAccess::world(p.sim));
        EXPECT_EQ(p.sim.counters().smoothing_iterations, cap) << "cap " << cap;
        EXPECT_FALSE(p.surface().dirty_empty()) << "cap " << cap << ": the pile still moves";
        EXPECT_EQ(p.surface().settled_units(), 2'000'000u);
    }
}

TEST(SmoothingCap, SettlesToTheSameFieldWhateverTheCap) {
    Pile fine(64);
    Pile coarse(1);
    const int fine_calls = fine.settle(100000);
    const int coarse_calls = coarse.settle(100000);
    ASSERT_TRUE(fine.surface().dirty_empty());
    ASSERT_TRUE(coarse.surface().dirty_empty());
    EXPECT_GT(coarse_calls, fine_calls);
    EXPECT_EQ(coarse.surface().snow, fine.surface().snow);
}

TEST(SmoothingCap, ZeroOrHugeIsRejectedNamingTheField) {
    for (const std::uint32_t cap : {0u, 5000u}) {
        SimConfig c;
        c.smoothing_iterations = cap;
        try {
            Simulation sim(c);
            FAIL() << "cap " << cap << " accepted";
        } catch (const SimulationError& e) {
            EXPECT_NE(std::string(e.what()).find("simulation.smoothing_iterations"),
                      std::string::npos)
                << e.what();
        }
    }
}

} // namespace
} // namespace snow
