/// @file time_scale.hpp
/// @brief snow_game's time lapse: each frame simulates ×1, ×4, ×16 or ×64 the
/// ticks its wall time is due, but no more than fit a frame budget: when the
/// ticks of a frame take longer than the budget, the ticks per frame stop
/// growing (and shrink to what fits); they grow back while frames are quick.
#pragma once

#include <array>
#include <cstdint>
#include <limits>

namespace snow {

class TimeScale {
  public:
    static constexpr std::array<std::uint32_t, 4> factors{1, 4, 16, 64};

    /// `budget_s`: wall seconds a frame's ticks may take.
    explicit TimeScale(double budget_s = 0.025) : budget_s_(budget_s) {}

    /// The next factor (after ×64 back to ×1).
    void cycle() { index_ = (index_ + 1) % factors.size(); }
    /// Sets the factor; false (and no change) if it is not one of `factors`.
    bool set(std::uint32_t factor);
    [[nodiscard]] std::uint32_t factor() const { return factors[index_]; }

    /// Ticks to run for `due` ticks of wall time: due × factor, capped.
    [[nodiscard]] std::uint64_t ticks(std::uint64_t due) const;
    /// Tells how long (wall seconds) the last frame's `ticks` took; adjusts the cap.
    void took(std::uint64_t ticks, double seconds);
    /// Most ticks a frame may run now (no limit until a frame was too slow).
    [[nodiscard]] std::uint64_t cap() const { return cap_; }
    [[nodiscard]] bool capped(std::uint64_t due) const { return due * factor() > cap_; }

  private:
    double budget_s_;
    std::size_t index_ = 0;
    std::uint64_t cap_ = std::numeric_limits<std::uint64_t>::max();
};

} // namespace snow
