#include "ecs/job_pool.hpp"
#include "ecs/state_hash.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <vector>

namespace snow {
namespace {

std::vector<std::uint64_t> chunk_sums(unsigned threads, std::size_t n, std::size_t grain) {
    JobPool pool(threads);
    std::vector<std::uint64_t> sums((n + grain - 1) / grain, 0);
    pool.parallel_for(sums.size(), [&](std::size_t c) {
        for (std::size_t i = c * grain; i < std::min(n, (c + 1) * grain); ++i) {
            sums[c] += i * i;
        }
    });
    return sums;
}

TEST(EcsJobPool, ChunksIndependentOfThreadCount) {
    const auto one = chunk_sums(1, 100003, 1000);
    EXPECT_EQ(one.size(), 101u);
    EXPECT_EQ(one, chunk_sums(2, 100003, 1000));
    EXPECT_EQ(one, chunk_sums(4, 100003, 1000));
}

TEST(EcsJobPool, ReusedAcrossManyCalls) {
    JobPool pool(2);
    std::vector<int> hits(64, 0);
    for (int round = 0; round < 200; ++round) {
        pool.parallel_for(hits.size(), [&](std::size_t i) { ++hits[i]; });
    }
    for (const int h : hits) {
        EXPECT_EQ(h, 200);
    }
}

TEST(EcsStateHash, SensitiveToEveryBit) {
    StateHasher a, b;
    a.value(1.0f);
    b.value(std::nextafter(1.0f, 2.0f));
    EXPECT_NE(a.digest(), b.digest());
    StateHasher c, d;
    c.value(1.0f);
    d.value(1.0f);
    EXPECT_EQ(c.digest(), d.digest());
}

} // namespace
} // namespace snow
