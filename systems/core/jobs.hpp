/// @file jobs.hpp
/// @brief Handing a system's work to the simulation's TaskSystem.
#pragma once

#include "ecs/world.hpp"

#include <algorithm>
#include <cstddef>

#include <snow/task_system.hpp>

namespace snow {

/// Flakes per chunk: fixed, so chunk bounds never depend on thread count.
inline constexpr std::size_t flake_grain = 16384;

/// Items (flake slots) below which for_chunks keeps the work on the calling
/// thread: four chunks. Handing chunks to another core costs a few µs, more
/// than one or two chunks of a flake pass gain (docs/performance.md).
inline constexpr std::size_t parallel_min_items = 4 * flake_grain;

/// Number of chunks of `grain` items that cover n items.
[[nodiscard]] constexpr std::size_t chunk_count(std::size_t n, std::size_t grain) {
    return grain == 0 ? 0 : (n + grain - 1) / grain;
}

/// World resource: the task system the Simulation runs on (the host's or its
/// own pool; null: serial).
struct Jobs {
    TaskSystem* tasks = nullptr;
    /// Work is handed out from this many items on; tests of small scenes set
    /// 0 so other threads take chunks too.
    std::size_t min_items = parallel_min_items;

    [[nodiscard]] bool shares(std::size_t items) const {
        return tasks != nullptr && tasks->concurrency() > 1 && items >= min_items;
    }
};

/// Runs task(0) .. task(count − 1), independent of each other, on the
/// world's task system when `items` (the work they share) is at least its
/// min_items, else one after another on this thread.
template <typename Task>
void for_tasks(World& w, std::size_t count, std::size_t items, const Task& task) {
    const Jobs* jobs = w.try_resource<Jobs>();
    if (jobs != nullptr && jobs->shares(items)) {
        jobs->tasks->parallel_for(count, task);
        return;
    }
    for (std::size_t t = 0; t < count; ++t) {
        task(t);
    }
}

/// Runs fn(chunk, begin, end) over [0, n) in chunks of `grain`; the bounds
/// are snow's whoever runs a chunk, so are the results.
template <typename Fn>
void for_chunks(World& w, std::size_t n, std::size_t grain, const Fn& fn) {
    for_tasks(w, chunk_count(n, grain), n,
              [&fn, n, grain](std::size_t c) { fn(c, c * grain, std::min(n, (c + 1) * grain)); });
}

} // namespace snow
