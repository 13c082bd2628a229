/// @file detail_bars.hpp
/// @brief The bars issue #32 sets the snow's detail normals and glints, held
/// by the sunny test scene and by village_effects alike (docs/rendering.md).
#pragma once

#include "tests/render/snow_image_measures.hpp"

#include <gtest/gtest.h>

namespace snow::test {

/// Lit snow varies half as much again as without detail; at most 1% of snow
/// pixels clip; 1–20 glints per 100×100 px of lit snow, 98% of which survive
/// a 0.1° turn; turning sparkle or detail normals off changes the image.
inline void expect_detail_bars(const DetailLook& d) {
    EXPECT_GE(d.look.lit_luma_stddev, 1.5 * d.plain_stddev);
    EXPECT_LE(d.look.clipped_share, 0.01);
    EXPECT_GE(d.per_100px, 1.0);
    EXPECT_LE(d.per_100px, 20.0);
    EXPECT_GE(d.persisting, 0.98);
    EXPECT_GT(d.sparkle_change, 0.02);
    EXPECT_GT(d.detail_change, 1.0);
}

} // namespace snow::test
