/// @file schedule.hpp
/// @brief Named systems run in a fixed order; a system whose needs the world
/// does not meet is skipped and costs nothing. Records calls and time.
#pragma once

#include "ecs/world.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace snow {

/// What a system needs: each predicate must hold for the system to run.
using Requirement = std::function<bool(const World&)>;

/// The world has at least one entity with a T, or a T resource.
template <typename T>
[[nodiscard]] Requirement needs() {
    return [](const World& w) { return w.count<T>() > 0 || w.has_resource<T>(); };
}

struct SystemStats {
    std::string name;
    std::uint64_t calls = 0;   ///< ticks on which the system ran
    std::uint64_t skipped = 0; ///< ticks on which its needs were not met
    double total_ms = 0.0;     ///< wall time spent inside the system
};

class Schedule {
  public:
    using SystemFn = std::function<void(World&)>;

    /// Appends a system; order of add() is the order of execution.
    void add(std::string name, SystemFn fn, std::vector<Requirement> needs = {});
    /// Runs every system whose needs hold, in order.
    void run(World& world);

    [[nodiscard]] const std::vector<SystemStats>& stats() const { return stats_; }
    [[nodiscard]] std::vector<std::string> names() const;
    /// True if the named system's needs hold for this world (it would run).
    [[nodiscard]] bool would_run(const std::string& name, const World& world) const;
    void reset_stats();

  private:
    struct Entry {
        SystemFn fn;
        std::vector<Requirement> needs;
    };
    [[nodiscard]] static bool ready(const Entry& e, const World& w);

    std::vector<Entry> entries_;
    std::vector<SystemStats> stats_;
};

} // namespace snow
