/// @file trajectory_study.hpp
/// @brief Part 1 of the accuracy study: flakes released from rest into a
/// constant wind (what a spilled flake does, [WF §3] drag), stepped by the
/// real SoA integrate system, against the closed-form solution.
#pragma once

#include "systems/core/sim_config.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace snow::accuracy {

struct TrajectoryOptions {
    std::vector<float> dts;
    std::vector<Integrator> integrators;
    float seconds = 2.0f;        ///< simulated time per trajectory (s)
    std::uint32_t flakes = 1024; ///< fall speeds spread evenly over [fall_min, fall_max]
    float fall_min = 0.5f;       ///< terminal speeds in still air (m/s): the village emitter's
    float fall_max = 1.5f;
    glm::vec3 wind{2.0f, 0.0f, 0.0f};
    std::uint32_t timing_flakes = 50000; ///< pool size of the timing runs
    std::uint32_t timing_ticks = 200;    ///< ticks per timed repeat
    int timing_repeats = 5;              ///< the fastest repeat is reported
};

struct TrajectoryRow {
    Integrator integrator;
    float dt;
    double max_pos_error;     ///< m, largest over flakes and ticks
    double rms_pos_error;     ///< m, over flakes at the last tick
    double max_vel_error;     ///< m/s, largest over flakes and ticks
    double stiff_share;       ///< share of flake-ticks the guard gave the exact update
    double ns_per_flake_tick; ///< CPU time of integrate_system per alive flake per tick
};

/// One row per (integrator, dt), integrators outermost.
[[nodiscard]] std::vector<TrajectoryRow> run_trajectory_study(const TrajectoryOptions& o);

/// ns per flake-tick of each of o.integrators (in that order) at one dt for a
/// pool of `flakes` (e.g. one far larger than the caches).
[[nodiscard]] std::vector<double> integrator_costs(const TrajectoryOptions& o, float dt,
                                                   std::uint32_t flakes);

} // namespace snow::accuracy
