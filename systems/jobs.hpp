/// @file jobs.hpp
/// @brief Access to the world's job pool from systems.
#pragma once

#include "ecs/job_pool.hpp"
#include "ecs/world.hpp"

#include <algorithm>

namespace snow {

/// Flakes per chunk: fixed, so chunk bounds never depend on thread count.
inline constexpr std::size_t flake_grain = 16384;

/// Items (flake slots) below which for_chunks keeps the work on the calling
/// thread: four chunks. A flake pass costs 1–4 ns per slot; since the pool's
/// threads poll before they sleep (job_pool.cpp), handing chunks to a second
/// core costs a few µs, and from four chunks on two threads are clearly
/// faster (BM_SimTick 100k 1.31×, 300k 1.79×); with one or two chunks the
/// gain is within noise (30k: 1.02×), so the work stays on one thread
/// (docs/performance.md).
inline constexpr std::size_t parallel_min_items = 4 * flake_grain;

/// World resource wrapping the pool owned by the Simulation (may be null: serial).
struct Jobs {
    JobPool* pool = nullptr;
    /// for_chunks hands work to the pool from this many items on; tests of
    /// small scenes set 0 so their second thread takes chunks too.
    std::size_t min_items = parallel_min_items;
};

/// Runs fn(chunk, begin, end) over [0, n) in chunks of `grain`, on the world's
/// pool if it has one and n is at least its min_items, else serially;
/// the chunks are the same either way, so are the results.
inline void for_chunks(World& w, std::size_t n, std::size_t grain, const JobPool::ChunkFn& fn) {
    const Jobs* jobs = w.try_resource<Jobs>();
    if (jobs != nullptr && jobs->pool != nullptr && n >= jobs->min_items) {
        jobs->pool->parallel_for(n, grain, fn);
        return;
    }
    const std::size_t chunks = JobPool::chunk_count(n, grain);
    for (std::size_t c = 0; c < chunks; ++c) {
        fn(c, c * grain, std::min(n, (c + 1) * grain));
    }
}

/// Runs task(0) .. task(count − 1), independent of each other, on the
/// world's pool when `items` (the work they share) is at least its
/// min_items, else one after another on this thread. (The pool's function
/// holds one reference, so nothing is allocated.)
template <typename Task>
void for_tasks(World& w, std::size_t count, std::size_t items, const Task& task) {
    const Jobs* jobs = w.try_resource<Jobs>();
    if (jobs != nullptr && jobs->pool != nullptr && items >= jobs->min_items) {
        const JobPool::ChunkFn fn = [&task](std::size_t t, std::size_t, std::size_t) { task(t); };
        jobs->pool->parallel_for(count, 1, fn);
        return;
    }
    for (std::size_t t = 0; t < count; ++t) {
        task(t);
    }
}

} // namespace snow
