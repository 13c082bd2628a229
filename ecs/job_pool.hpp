/// @file job_pool.hpp
/// @brief A small fork-join pool. Work is cut into chunks whose bounds depend
/// only on the problem size and grain, never on the thread count, so any
/// per-chunk result combined in chunk order is identical for 1..N threads.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace snow {

class JobPool {
  public:
    /// chunk_fn(chunk_index, begin, end)
    using ChunkFn = std::function<void(std::size_t, std::size_t, std::size_t)>;

    /// threads >= 1; threads - 1 workers are started, the caller is the last.
    explicit JobPool(unsigned threads = 1);
    ~JobPool();
    JobPool(const JobPool&) = delete;
    JobPool& operator=(const JobPool&) = delete;

    [[nodiscard]] unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }

    /// Number of chunks parallel_for will use for n items at this grain.
    [[nodiscard]] static std::size_t chunk_count(std::size_t n, std::size_t grain) {
        return grain == 0 ? 0 : (n + grain - 1) / grain;
    }
    /// Runs fn over [0, n) in chunks of `grain` items; returns when all are done.
    void parallel_for(std::size_t n, std::size_t grain, const ChunkFn& fn);

  private:
    void worker_loop();
    void drain();

    std::vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const ChunkFn* job_ = nullptr;
    std::size_t n_ = 0;
    std::size_t grain_ = 1;
    std::size_t chunks_ = 0;
    std::atomic<std::size_t> next_{0};
    std::atomic<std::size_t> finished_{0};
    std::atomic<std::uint64_t> epoch_{0};
    bool stop_ = false;
};

} // namespace snow
