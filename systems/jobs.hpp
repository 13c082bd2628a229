/// @file jobs.hpp
/// @brief Access to the world's job pool from systems.
#pragma once

#include "ecs/job_pool.hpp"
#include "ecs/world.hpp"

#include <algorithm>

namespace snow {

/// World resource wrapping the pool owned by the Simulation (may be null: serial).
struct Jobs {
    JobPool* pool = nullptr;
};

/// Flakes per chunk: fixed, so chunk bounds never depend on thread count.
inline constexpr std::size_t flake_grain = 16384;

/// Runs fn(chunk, begin, end) over [0, n) in chunks of `grain`, on the world's
/// pool if it has one, else serially; the chunks are the same either way.
inline void for_chunks(World& w, std::size_t n, std::size_t grain, const JobPool::ChunkFn& fn) {
    const Jobs* jobs = w.try_resource<Jobs>();
    if (jobs != nullptr && jobs->pool != nullptr) {
        jobs->pool->parallel_for(n, grain, fn);
        return;
    }
    const std::size_t chunks = JobPool::chunk_count(n, grain);
    for (std::size_t c = 0; c < chunks; ++c) {
        fn(c, c * grain, std::min(n, (c + 1) * grain));
    }
}

} // namespace snow
