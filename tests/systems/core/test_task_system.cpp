// The host's threads (<snow/task_system.hpp>): snow's results do not depend
// on who runs its tasks or in what order, and with a host task system snow
// creates no thread of its own.
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/share_work.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

namespace snow {
namespace {

/// Runs every task on the calling thread, last index first, while claiming
/// four threads so snow hands it all the work it can share.
class ReverseOrder final : public TaskSystem {
  public:
    [[nodiscard]] unsigned concurrency() const override { return 4; }
    void parallel_for(std::size_t count, TaskFn task) override {
        for (std::size_t i = count; i-- > 0;) {
            task(i);
        }
        ++calls;
    }
    std::size_t calls = 0;
};

/// A host's pool of four threads, started before the simulation: each call
/// wakes them, they take task indices from a shared counter, and the caller
/// waits until all have run (the caller itself runs none).
class HostThreads final : public TaskSystem {
  public:
    HostThreads() {
        for (int t = 0; t < 4; ++t) {
            threads_.emplace_back([this] { serve(); });
        }
    }
    ~HostThreads() override {
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        for (auto& t : threads_) {
            t.join();
        }
    }
    HostThreads(const HostThreads&) = delete;
    HostThreads& operator=(const HostThreads&) = delete;

    [[nodiscard]] unsigned concurrency() const override { return 4; }
    void parallel_for(std::size_t count, TaskFn task) override {
        std::unique_lock lock(mutex_);
        task_ = &task;
        count_ = count;
        next_ = 0;
        done_ = 0;
        ++round_;
        wake_.notify_all();
        finished_.wait(lock, [&] { return done_ == count_; });
        task_ = nullptr;
    }

  private:
    void serve() {
        std::uint64_t seen = 0;
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stop_ || round_ != seen; });
            if (stop_) {
                return;
            }
            seen = round_;
            while (next_ < count_) {
                const std::size_t i = next_++;
                const TaskFn* task = task_;
                lock.unlock();
                (*task)(i);
                lock.lock();
                if (++done_ == count_) {
                    finished_.notify_all();
                }
            }
        }
    }

    std::vector<std::thread> threads_;
    std::mutex mutex_;
    std::condition_variable wake_, finished_;
    const TaskFn* task_ = nullptr;
    std::size_t count_ = 0, next_ = 0, done_ = 0;
    std::uint64_t round_ = 0;
    bool stop_ = false;
};

std::size_t process_threads() {
    const auto tasks = std::filesystem::directory_iterator("/proc/self/task");
    return static_cast<std::size_t>(std::distance(begin(tasks), end(tasks)));
}

/// The stormy yard (every kind of state) for `ticks`, its work shared at any
/// size, on the built-in pool (`tasks` null) or the given task system.
std::uint64_t stormy_hash(unsigned threads, TaskSystem* tasks, int ticks) {
    auto sim = make_stormy_yard(threads, tasks);
    test::share_work_at_any_size(*sim);
    sim->run(static_cast<std::uint64_t>(ticks));
    return sim->state_hash();
}

TEST(TaskSystem, AnyOrderAndAnyHostThreadsGiveTheBuiltInPoolsHash) {
    const std::uint64_t one = stormy_hash(1, nullptr, 150);
    EXPECT_EQ(stormy_hash(2, nullptr, 150), one);
    ReverseOrder reverse;
    EXPECT_EQ(stormy_hash(1, &reverse, 150), one);
    EXPECT_GT(reverse.calls, 150u); // it really ran the ticks' shared work
    HostThreads host;
    EXPECT_EQ(stormy_hash(1, &host, 150), one);
}

TEST(TaskSystem, AHostTaskSystemMeansSnowCreatesNoThread) {
    HostThreads host;
    const std::size_t before = process_threads();
    {
        auto sim = make_stormy_yard(8, &host); // `threads` is ignored: the host's pool runs it
        test::share_work_at_any_size(*sim);
        sim->run(60);
        EXPECT_EQ(process_threads(), before);
    }
    // The built-in pool with two threads starts one: the count can move.
    auto own = make_stormy_yard(2);
    EXPECT_EQ(process_threads(), before + 1);
}

} // namespace
} // namespace snow
