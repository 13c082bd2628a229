// for_chunks (systems/core/jobs.hpp): work below Jobs::min_items stays on the
// calling thread, and the chunks are the same whether the pool takes them
// or not, so the results are too.
#include "ecs/job_pool.hpp"
#include "systems/core/jobs.hpp"

#include <gtest/gtest.h>

#include <thread>
#include <utility>
#include <vector>

namespace snow {
namespace {

struct ChunkRun {
    std::vector<std::pair<std::size_t, std::size_t>> bounds;
    std::vector<std::thread::id> thread;
};

ChunkRun run_chunks(World& w, std::size_t n) {
    ChunkRun r;
    r.bounds.resize(chunk_count(n, flake_grain));
    r.thread.resize(r.bounds.size());
    for_chunks(w, n, flake_grain, [&](std::size_t c, std::size_t b, std::size_t e) {
        r.bounds[c] = {b, e};
        r.thread[c] = std::this_thread::get_id();
    });
    return r;
}

TEST(Jobs, WorkBelowTheThresholdStaysOnTheCallingThreadInTheSameChunks) {
    JobPool pool(2);
    World w;
    w.set_resource<Jobs>(Jobs{&pool});
    const std::size_t n = parallel_min_items - 1; // several chunks, yet too little to share
    const ChunkRun kept = run_chunks(w, n);
    ASSERT_GT(kept.bounds.size(), 2u);
    for (std::size_t c = 0; c < kept.bounds.size(); ++c) {
        EXPECT_EQ(kept.thread[c], std::this_thread::get_id()) << "chunk " << c;
        EXPECT_EQ(kept.bounds[c].first, c * flake_grain);
        EXPECT_EQ(kept.bounds[c].second, std::min(n, (c + 1) * flake_grain));
    }
    w.resource<Jobs>().min_items = 0; // the pool takes them now: the same chunks
    EXPECT_EQ(run_chunks(w, n).bounds, kept.bounds);
}

} // namespace
} // namespace snow
