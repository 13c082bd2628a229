#include "ecs/schedule.hpp"

#include <chrono>

namespace snow {

void Schedule::add(std::string_view name, SystemFn fn, std::initializer_list<Requirement> needs) {
    entries_.push_back(Entry{fn, Vector<Requirement>(needs)});
    stats_.push_back(SystemStats{String(name)});
}

bool Schedule::ready(const Entry& e, const World& w) {
    for (const auto& need : e.needs) {
        if (!need(w)) {
            return false;
        }
    }
    return true;
}

void Schedule::run(World& world) {
    for (std::size_t i = 0; i < entries_.size(); ++i) {
        if (!ready(entries_[i], world)) {
            ++stats_[i].skipped;
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        entries_[i].fn(world);
        const auto t1 = std::chrono::steady_clock::now();
        ++stats_[i].calls;
        stats_[i].total_ms += std::chrono::duration<double, std::milli>(t1 - t0).count();
    }
}

bool Schedule::would_run(std::string_view name, const World& world) const {
    for (std::size_t i = 0; i < stats_.size(); ++i) {
        if (stats_[i].name == name) {
            return ready(entries_[i], world);
        }
    }
    return false;
}

void Schedule::reset_stats() {
    for (auto& s : stats_) {
        s.calls = 0;
        s.skipped = 0;
        s.total_ms = 0.0;
    }
}

} // namespace snow
