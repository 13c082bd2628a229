#include <snow/snow.hpp>

#include "systems/core/field_rules.hpp"

namespace snow {

FixedStep::FixedStep(double dt, std::uint32_t max_ticks_per_frame)
    : dt_(dt), max_ticks_(max_ticks_per_frame) {
    Invalid e;
    check::number(e, "fixed_step.dt", positive, dt);
    if (max_ticks_per_frame == 0) {
        check::fail(e, "fixed_step.max_ticks_per_frame", ">= 1", 0);
    }
    throw_if(e);
}

std::uint32_t FixedStep::advance(double seconds) {
    Invalid e;
    check::number(e, "fixed_step.advance(seconds)", non_negative, seconds);
    throw_if(e);
    accumulated_ += seconds;
    std::uint32_t ticks = 0;
    while (accumulated_ >= dt_ && ticks < max_ticks_) {
        accumulated_ -= dt_;
        ++ticks;
    }
    if (accumulated_ >= dt_) {
        accumulated_ = 0.0; // the dropped backlog
    }
    return ticks;
}

} // namespace snow
