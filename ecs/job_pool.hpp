/// @file job_pool.hpp
/// @brief The built-in TaskSystem: a small fork-join pool, the default when
/// the host gives none. It runs tasks by index; who runs which never changes
/// a result (the caller cuts the work, <snow/task_system.hpp>).
#pragma once

#include "ecs/host_memory.hpp"

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <thread>

#include <snow/task_system.hpp>

namespace snow {

class JobPool final : public TaskSystem, public HostAllocated {
  public:
    /// threads >= 1; threads - 1 workers are started, the caller is the last.
    explicit JobPool(unsigned threads = 1);
    ~JobPool() override;
    JobPool(const JobPool&) = delete;
    JobPool& operator=(const JobPool&) = delete;

    [[nodiscard]] unsigned concurrency() const override {
        return static_cast<unsigned>(workers_.size()) + 1;
    }
    void parallel_for(std::size_t count, TaskFn task) override;

  private:
    void worker_loop();
    void drain();

    /// The std::thread objects live in the host's memory; the state the C++
    /// library allocates to start each thread does not (<snow/allocator.hpp>).
    Vector<std::thread> workers_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::condition_variable done_;
    const TaskFn* job_ = nullptr;
    std::size_t count_ = 0;
    std::atomic<std::size_t> next_{0};
    std::atomic<std::size_t> finished_{0};
    std::atomic<std::uint64_t> epoch_{0};
    bool stop_ = false;
};

} // namespace snow
