// The angle of repose of declared surfaces (issue #30, docs/validation.md): a
// pile poured at one point stands with flanks of loose dry snow, 37–53°
// ([NSA] in docs/references.md), whatever its size and the cell size.
#include "systems/core/units.hpp"
#include "tests/scenes/poured_pile.hpp"

#include <gtest/gtest.h>

namespace snow {
namespace {

constexpr std::uint64_t rest_ticks = 1200;

TEST(Repose, PouredPilesStandAtTheAngleOfLooseDrySnowAtAnySizeAndCell) {
    for (const double cell : {0.05, 0.1}) {
        // 1.5 kg and 15 kg: about 0.3 m and 0.6 m high at 45°.
        for (const std::uint64_t units : {std::uint64_t{300000}, std::uint64_t{3000000}}) {
            const double degrees = poured_pile_degrees(cell, units, rest_ticks);
            EXPECT_GE(degrees, 37.0) << units * unit_kg << " kg, cell " << cell;
            EXPECT_LE(degrees, 53.0) << units * unit_kg << " kg, cell " << cell;
        }
    }
}

TEST(Repose, ASurfacesOwnAngleSetsItsFlanks) {
    const double degrees = poured_pile_degrees(0.05, 3000000, rest_ticks, 30.0f);
    EXPECT_GE(degrees, 25.0);
    EXPECT_LE(degrees, 33.0);
}

} // namespace
} // namespace snow
