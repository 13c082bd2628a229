#include "ecs/job_pool.hpp"

#include <chrono>

namespace snow {

namespace {

/// How long a thread that ran out of work polls (yielding its core) for the
/// next job or the last chunk before it sleeps: a sleeping thread takes tens
/// of µs to wake (a futex wake, on a VM an interrupt), about a chunk's work,
/// and a tick hands out work once or twice.
constexpr auto poll_for = std::chrono::microseconds(100);

/// Polls done() until it holds or poll_for has passed (the caller then
/// waits on its condition variable, which sees the same state).
template <typename Done>
void poll(const Done& done) {
    const auto until = std::chrono::steady_clock::now() + poll_for;
    while (!done() && std::chrono::steady_clock::now() < until) {
        std::this_thread::yield();
    }
}

} // namespace

JobPool::JobPool(unsigned threads) {
    const unsigned extra = threads > 1 ? threads - 1 : 0;
    workers_.reserve(extra);
    for (unsigned i = 0; i < extra; ++i) {
        workers_.emplace_back([this] { worker_loop(); });
    }
}

JobPool::~JobPool() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    for (auto& t : workers_) {
        t.join();
    }
}

void JobPool::drain() {
    std::size_t done_here = 0;
    for (;;) {
        const std::size_t c = next_.fetch_add(1, std::memory_order_acq_rel);
        if (c >= count_) {
            break;
        }
        (*job_)(c);
        ++done_here;
    }
    if (done_here > 0) {
        std::lock_guard lock(mutex_);
        if (finished_.fetch_add(done_here, std::memory_order_acq_rel) + done_here == count_) {
            done_.notify_all();
        }
    }
}

void JobPool::worker_loop() {
    std::uint64_t seen = 0;
    for (;;) {
        poll([&] { return epoch_.load(std::memory_order_acquire) != seen; });
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || epoch_ != seen; });
            if (stop_) {
                return;
            }
            seen = epoch_;
        }
        drain();
    }
}

void JobPool::parallel_for(std::size_t count, TaskFn task) {
    if (workers_.empty() || count <= 1) {
        for (std::size_t c = 0; c < count; ++c) {
            task(c);
        }
        return;
    }
    {
        std::lock_guard lock(mutex_);
        job_ = &task;
        count_ = count;
        finished_ = 0;
        next_.store(0, std::memory_order_release);
        ++epoch_;
    }
    wake_.notify_all();
    drain();
    poll([&] { return finished_.load(std::memory_order_acquire) == count; });
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return finished_ == count_; });
    job_ = nullptr;
}

} // namespace snow
