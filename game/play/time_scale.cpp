#include "game/play/time_scale.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

bool TimeScale::set(std::uint32_t factor) {
    const auto it = std::find(factors.begin(), factors.end(), factor);
    if (it == factors.end()) {
        return false;
    }
    index_ = static_cast<std::size_t>(it - factors.begin());
    return true;
}

std::uint64_t TimeScale::ticks(std::uint64_t due) const {
    return std::min(due * factor(), cap_);
}

void TimeScale::took(std::uint64_t ticks, double seconds) {
    if (ticks == 0 || !(seconds >= 0.0)) {
        return;
    }
    if (seconds > budget_s_) {
        // Too slow: no more ticks than fit the budget at this frame's pace.
        const double fit = std::floor(static_cast<double>(ticks) * budget_s_ / seconds);
        cap_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(fit));
    } else if (ticks >= cap_ && seconds < 0.5 * budget_s_) {
        cap_ += cap_ / 4 + 1; // capped but quick: let it grow back
    }
}

} // namespace snow
