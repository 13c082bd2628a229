/// @file task_system.hpp
/// @brief The host's threads: a TaskSystem the host implements and gives in
/// SimConfig::task_system. snow cuts its work into tasks whose bounds depend
/// only on the problem size, never on who runs them, so results are
/// bit-identical for any task system, any thread count and any order.
/// Self-contained: includes only the standard library.
#pragma once

#include <concepts>
#include <cstddef>
#include <type_traits>

namespace snow {

/// A non-owning reference to a callable task(index). Valid only during the
/// TaskSystem::parallel_for call that hands it out; calling it allocates nothing.
class TaskFn {
  public:
    template <typename F>
    requires(!std::same_as<std::remove_cvref_t<F>, TaskFn> && std::invocable<const F&, std::size_t>)
        TaskFn(const F& f)
    noexcept // NOLINT(google-explicit-constructor): lambdas convert
        : object_(&f), call_([](const void* object, std::size_t index) {
              (*static_cast<const F*>(object))(index);
          }) {}

    void operator()(std::size_t index) const { call_(object_, index); }

  private:
    const void* object_;
    void (*call_)(const void*, std::size_t);
};

/// What a host implements to run snow's work on its own threads (Box2D's
/// enqueueTask/finishTask, Jolt's JobSystem, PhysX's PxCpuDispatcher).
class TaskSystem {
  public:
    virtual ~TaskSystem() = default;

    /// How many threads may run tasks at once (1: snow keeps its work on the
    /// calling thread and never calls parallel_for).
    [[nodiscard]] virtual unsigned concurrency() const = 0;

    /// Runs task(0) .. task(count − 1), each exactly once, on any threads in
    /// any order (the calling thread may take part); returns when all have
    /// finished. Tasks are independent: none waits for another.
    virtual void parallel_for(std::size_t count, TaskFn task) = 0;
};

} // namespace snow
