/// @file wind_field_study.hpp
/// @brief Part 3 of the accuracy study: the wind field's resolution, update
/// interval and flakes' sample interval (docs/wind_field.md) against a fine
/// reference field, on the same scene, seed and snowfall: the time-mean wind
/// near the ground and in the garage's lee, and the snow that lands.
#pragma once

#include "bench/accuracy/depth_field.hpp"
#include "systems/wind/wind_field.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace snow::accuracy {

/// What the wind-field study varies.
struct WindFieldKnobs {
    float cell_scale = 1.0f;        ///< cells per axis × 64 × 16 × 64
    std::uint32_t update_every = 4; ///< ticks between solver steps
    std::uint32_t sample_every = 1; ///< ticks between a flake's samples of the field

    bool operator==(const WindFieldKnobs&) const = default;
    /// Cells per axis: round(64 s), round(16 s), round(64 s), at least 1.
    [[nodiscard]] std::uint32_t cells(int axis) const;
    [[nodiscard]] std::uint64_t total_cells() const;
};

struct WindFieldStudyOptions {
    std::string scene;
    float seconds = 30.0f; ///< simulated by every run (s)
    float warmup = 10.0f;  ///< before the time means start: the flow develops (s)
    std::uint64_t seed = 2;
    WindFieldKnobs reference{2.0f, 1, 1};
    /// The sweeps vary one knob from here: the defaults of WindFieldDef.
    WindFieldKnobs baseline{1.0f, WindFieldDef{}.update_every, WindFieldDef{}.sample_every};
    std::vector<float> cell_scales{0.5f, 0.75f, 1.0f, 1.5f};
    std::vector<std::uint32_t> update_everys{1, 2, 4, 8, 16};
    /// The first is the sample sweep's own reference (the error of the rest).
    std::vector<std::uint32_t> sample_everys{1, 2, 4, 8, 16, 32, 64};
};

struct WindFieldPoint {
    WindFieldKnobs knobs;
    std::uint64_t ticks = 0;
    double cpu_ms_per_tick = 0.0;   ///< the whole tick after the warm-up, thread CPU time
    double field_ms_per_tick = 0.0; ///< the wind_field system alone, thread CPU time
    /// Σ |mean wind − reference's| / Σ |reference's| over a lattice of the
    /// scene's ground area at 0.5, 1.5 and 3 m (horizontal components).
    double wind_rel_l1 = 0.0;
    double lee_speed = 0.0;       ///< mean horizontal speed in the lee box (m/s)
    double free_speed = 0.0;      ///< the same upwind of everything (m/s)
    std::uint64_t lee_units = 0;  ///< snow units on the ground in the lee strip at the end
    double lee_units_ratio = 0.0; ///< lee_units / the reference's
    DepthField depth;             ///< the settled snow at the end
    /// Sample sweep only: the settled snow against the sweep's first point
    /// (every surface, 1 m blocks), and the lee strip's units over its.
    DepthError depth_vs_first;
    double lee_units_vs_first = 0.0;

    /// Field ms per simulated second: what a real-time loop pays for it.
    [[nodiscard]] double field_ms_per_second(float dt) const {
        return field_ms_per_tick / static_cast<double>(dt);
    }
};

struct WindFieldStudy {
    WindFieldPoint reference;
    std::vector<WindFieldPoint> points; ///< each distinct setting once
    std::vector<std::size_t> cell_sweep, update_sweep, sample_sweep;
    float dt = 0.0f; ///< the scene's tick (s)
};

/// Runs the reference and the sweeps; `progress` (may be null) gets one line per run.
[[nodiscard]] WindFieldStudy run_wind_field_study(const WindFieldStudyOptions& o,
                                                  std::FILE* progress);

} // namespace snow::accuracy
