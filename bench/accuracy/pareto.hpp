/// @file pareto.hpp
/// @brief The cost/error Pareto front of the scene study and the quality
/// presets picked from it (rules in docs/accuracy.md "Pareto front and presets").
#pragma once

#include "bench/accuracy/scene_study.hpp"
#include "bench/accuracy/trajectory_study.hpp"

#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

namespace snow::accuracy {

/// Indices (into study.points) of `candidates` that no other candidate beats
/// on both CPU ms per simulated second and error.rel_l1, cheapest first.
[[nodiscard]] std::vector<std::size_t> pareto_front(const SceneStudy& study,
                                                    const std::vector<std::size_t>& candidates);

/// Costs within this factor of the cheapest count as equal, and the more
/// accurate of them wins: same-knob runs on a shared machine spread by this
/// much or more, so a smaller difference says nothing.
inline constexpr double preset_cost_tie = 1.15;

struct PresetRule {
    std::string_view name;
    /// Allowed rel L1 as a multiple of the noise floor.
    double tolerance;
    /// Longest tick (s): the renderer draws the last tick without
    /// interpolating, so the tick rate is the rate at which flakes move on
    /// screen; below 30 Hz that stutters, and the default preset keeps 60 Hz.
    float max_dt;
    /// Finest cells allowed (cell_scale): the renderer draws a quad per
    /// surface cell, so presets that must run on a software rasteriser keep
    /// the scene's own cells or coarser.
    float min_cell_scale;
};

/// high is within a fifth of what sampling noise alone gives, low within twice it.
inline constexpr std::array<PresetRule, 3> preset_rules{{
    {"low", 2.0, 1.0f / 30.0f, 1.0f},
    {"medium", 1.5, 1.0f / 60.0f, 1.0f},
    {"high", 1.2, 1.0f / 60.0f, 0.0f},
}};

struct PresetPick {
    PresetRule rule;
    double max_error;               ///< rule.tolerance × the noise floor
    std::vector<std::size_t> front; ///< of the settings the rule allows
    std::size_t point;              ///< index into study.points: dt, cells, smoothing, occlusion
    Integrator integrator;          ///< cheapest whose trajectory error is within max_drift
    double max_drift;               ///< m: half the preset's finest surface cell
    double drift; ///< m: that integrator's largest trajectory error at the preset's dt
};

/// For each rule: the front of the settings with dt and cells within its
/// limits; its cheapest setting whose rel L1 is within the
/// tolerance (the most accurate one when none is); then the integrator with
/// the fewest ns per flake-tick at that dt whose trajectory error stays under
/// half a surface cell (the most accurate one when none does). "Cheapest"
/// means the most accurate within preset_cost_tie of the cheapest. Throws
/// std::invalid_argument if a rule allows no setting or `trajectory` has no
/// row at a picked dt.
[[nodiscard]] std::vector<PresetPick> pick_presets(const SceneStudy& study,
                                                   const std::vector<TrajectoryRow>& trajectory);

} // namespace snow::accuracy
