/// @file fixed_step.hpp
/// @brief The fixed-timestep accumulator between a host's variable frames and
/// the simulation's fixed tick: each frame, advance() says how many ticks are
/// due; the remainder carries to the next frame.
#pragma once

#include <cstdint>

namespace snow {

class FixedStep {
  public:
    /// Ticks of `dt` seconds, at most `max_ticks_per_frame` per frame: after a
    /// stall (a breakpoint, a dragged window) the backlog beyond that is
    /// dropped, so a slow frame never makes the next ones slower still.
    /// Throws SimulationError for a dt that is not finite and > 0, or a cap of 0.
    explicit FixedStep(double dt, std::uint32_t max_ticks_per_frame = 8);

    /// Adds `seconds` of host time; returns the ticks to run now. Throws
    /// SimulationError for a negative or non-finite `seconds`.
    [[nodiscard]] std::uint32_t advance(double seconds);

    /// Host time not simulated yet (s), below dt after every advance().
    [[nodiscard]] double remainder() const { return accumulated_; }
    [[nodiscard]] double dt() const { return dt_; }

  private:
    double dt_;
    std::uint32_t max_ticks_;
    double accumulated_ = 0.0;
};

} // namespace snow
