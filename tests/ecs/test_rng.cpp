#include "ecs/rng.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

namespace snow {
namespace {

// Any ids: ecs/ gives streams no meaning.
constexpr std::uint32_t stream_a = 8;
constexpr std::uint32_t stream_b = 9;
constexpr std::uint32_t stream_c = 1000;

TEST(EcsRng, SameKeySameValueWhateverTheOrder) {
    std::vector<std::uint64_t> forward, backward;
    for (std::uint32_t s = 0; s < 100; ++s) {
        forward.push_back(rng_bits({7, 3, s, stream_a}));
    }
    for (std::uint32_t s = 100; s-- > 0;) {
        backward.push_back(rng_bits({7, 3, s, stream_a}));
    }
    std::reverse(backward.begin(), backward.end());
    EXPECT_EQ(forward, backward);
}

TEST(EcsRng, KeyFieldsAllMatter) {
    const RngKey base{1, 2, 3, stream_a};
    const auto v = rng_bits(base);
    EXPECT_NE(v, rng_bits({2, 2, 3, stream_a}));
    EXPECT_NE(v, rng_bits({1, 3, 3, stream_a}));
    EXPECT_NE(v, rng_bits({1, 2, 4, stream_a}));
    EXPECT_NE(v, rng_bits({1, 2, 3, stream_b}));
    EXPECT_NE(v, rng_bits(base, 1));
}

TEST(EcsRng, UniformIsInRangeAndRoughlyFlat) {
    std::array<int, 10> bins{};
    const int n = 100000;
    for (int i = 0; i < n; ++i) {
        const float u = rng_uniform({42, 0, static_cast<std::uint32_t>(i), stream_c});
        ASSERT_GE(u, 0.0f);
        ASSERT_LT(u, 1.0f);
        ++bins[static_cast<std::size_t>(u * 10.0f)];
    }
    // Chi-square with 9 degrees of freedom; 27.9 is the 0.1 % critical value.
    double chi2 = 0.0;
    for (const int b : bins) {
        const double d = b - n / 10.0;
        chi2 += d * d / (n / 10.0);
    }
    EXPECT_LT(chi2, 27.9);
}

TEST(EcsRng, BelowStaysBelow) {
    std::array<int, 3> hits{};
    for (std::uint32_t i = 0; i < 3000; ++i) {
        const auto r = rng_below({5, 1, i, stream_c}, 0, 3);
        ASSERT_LT(r, 3u);
        ++hits[r];
    }
    for (const int h : hits) {
        EXPECT_GT(h, 850);
    }
}

} // namespace
} // namespace snow
