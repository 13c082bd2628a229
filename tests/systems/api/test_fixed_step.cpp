// FixedStep: host frames of any length become whole ticks; the remainder
// carries over, a stall's backlog beyond the cap is dropped.
#include <snow/snow.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>

namespace snow {
namespace {

constexpr double nan_v = std::numeric_limits<double>::quiet_NaN();
constexpr double inf_v = std::numeric_limits<double>::infinity();

TEST(FixedStep, FramesFasterThanTheTickCarryTheRemainder) {
    FixedStep step(1.0 / 60.0);
    std::uint64_t ticks = 0;
    for (int frame = 0; frame < 144 * 5; ++frame) {
        const std::uint32_t due = step.advance(1.0 / 144.0);
        EXPECT_LE(due, 1u) << "frame " << frame;
        ticks += due;
        EXPECT_GE(step.remainder(), 0.0);
        EXPECT_LT(step.remainder(), step.dt());
    }
    EXPECT_NEAR(static_cast<double>(ticks), 300.0, 1.0); // 5 s at 60 Hz
}

TEST(FixedStep, SlowFramesRunSeveralTicksAndAStallIsCapped) {
    FixedStep step(0.01, 4);
    EXPECT_EQ(step.advance(0.035), 3u);
    EXPECT_NEAR(step.remainder(), 0.005, 1e-12);
    EXPECT_EQ(step.advance(0.005), 1u);
    EXPECT_EQ(step.advance(10.0), 4u) << "a 10 s stall runs the cap, not 1000 ticks";
    EXPECT_EQ(step.remainder(), 0.0) << "the backlog is dropped";
    EXPECT_EQ(step.advance(0.0), 0u);
}

TEST(FixedStep, BadValuesAreRejectedNamingTheField) {
    for (const double dt : {0.0, -1.0, nan_v, inf_v}) {
        try {
            FixedStep step(dt);
            ADD_FAILURE() << "dt " << dt << " accepted";
        } catch (const SimulationError& e) {
            EXPECT_EQ(e.field(), "fixed_step.dt") << e.what();
        }
    }
    EXPECT_THROW(FixedStep(0.01, 0), SimulationError);
    FixedStep step(0.01);
    ASSERT_EQ(step.advance(0.015), 1u);
    for (const double seconds : {-0.01, nan_v, inf_v}) {
        try {
            (void)step.advance(seconds);
            ADD_FAILURE() << "seconds " << seconds << " accepted";
        } catch (const Error& e) {
            EXPECT_EQ(e.field(), "fixed_step.advance(seconds)") << e.what();
        }
    }
    EXPECT_NEAR(step.remainder(), 0.005, 1e-12) << "a rejected frame changes nothing";
}

} // namespace
} // namespace snow
