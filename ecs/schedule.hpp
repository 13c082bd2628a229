/// @file schedule.hpp
/// @brief Named systems run in a fixed order; a system whose needs the world
/// does not meet is skipped and costs nothing. Records calls and time.
#pragma once

#include "ecs/host_memory.hpp"
#include "ecs/world.hpp"

#include <cstdint>
#include <initializer_list>
#include <string_view>

namespace snow {

/// What a system needs: each predicate must hold for the system to run.
/// Plain functions, like the systems: the schedule holds no state of its own
/// (a system keeps its state in the World), and calling one allocates nothing.
using Requirement = bool (*)(const World&);

/// The world has at least one entity with a T, or a T resource.
template <typename T>
[[nodiscard]] Requirement needs() {
    return [](const World& w) { return w.count<T>() > 0 || w.has_resource<T>(); };
}

struct SystemStats {
    String name;
    std::uint64_t calls = 0;   ///< ticks on which the system ran
    std::uint64_t skipped = 0; ///< ticks on which its needs were not met
    double total_ms = 0.0;     ///< wall time spent inside the system
};

class Schedule {
  public:
    using SystemFn = void (*)(World&);

    /// Appends a system; order of add() is the order of execution.
    void add(std::string_view name, SystemFn fn, std::initializer_list<Requirement> needs = {});
    /// Runs every system whose needs hold, in order.
    void run(World& world);

    [[nodiscard]] const Vector<SystemStats>& stats() const { return stats_; }
    /// True if the named system's needs hold for this world (it would run).
    [[nodiscard]] bool would_run(std::string_view name, const World& world) const;
    void reset_stats();

  private:
    struct Entry {
        SystemFn fn;
        Vector<Requirement> needs;
    };
    [[nodiscard]] static bool ready(const Entry& e, const World& w);

    Vector<Entry> entries_;
    Vector<SystemStats> stats_;
};

} // namespace snow
