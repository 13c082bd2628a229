/// @file scene_study.hpp
/// @brief Part 2 of the accuracy study: the depth field of a scene after a
/// fixed snowfall, for knob settings around the scene's own, against an
/// ensemble of fine reference runs, with the sampling-noise floor.
#pragma once

#include "bench/accuracy/scene_run.hpp"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace snow::accuracy {

struct SceneStudyOptions {
    std::string scene;
    float seconds = 60.0f; ///< snowfall simulated by every run (s)
    /// Every studied setting runs once per seed; its errors and costs are the means.
    std::vector<std::uint64_t> seeds{2, 3};
    std::vector<std::uint64_t> reference_seeds{101, 102, 103, 104};
    /// Single runs with the reference's knobs: their error is the noise floor.
    std::vector<std::uint64_t> floor_seeds{2, 3, 4, 5};
    SceneKnobs reference{1.0f / 240.0f, Integrator::exponential, 0.5f, 256, 1024};
    SceneKnobs baseline; ///< the scene's own settings: sweeps vary one knob from here
    std::vector<float> dts;
    std::vector<float> integrator_dts; ///< where every integrator is tried
    std::vector<Integrator> integrators;
    std::vector<float> cell_scales;
    std::vector<std::uint32_t> smoothings;
    std::vector<std::uint32_t> occlusions;
    /// Grid for the Pareto front: every dt × cell scale × occlusion in these
    /// (integrator and smoothing from the baseline).
    std::vector<float> grid_dts;
    std::vector<float> grid_cell_scales;
    std::vector<std::uint32_t> grid_occlusions;
    float block = 2.0f;      ///< block edge (m) of the main error measure
    float fine_block = 0.5f; ///< block edge (m) of the secondary one
    /// Wind without its random walk in every studied run, so runs differ only
    /// in their flakes; the walk's share of the noise is measured separately.
    bool steady_wind = true;
};

/// A studied setting: means over SceneStudyOptions::seeds.
struct ScenePoint {
    SceneKnobs knobs;
    std::uint64_t ticks = 0;
    double cpu_ms_per_tick = 0.0;    ///< the fastest seed's run: least disturbed by other load
    double smoothing_per_tick = 0.0; ///< smoothing sub-iterations (all surfaces) per tick
    // Shares of the spawned snow mass at the end of the snowfall.
    double settled_share = 0.0, airborne_share = 0.0, bounds_share = 0.0, sphere_share = 0.0,
           bare_share = 0.0;
    DepthError error;      ///< against the reference ensemble, blocks of `block`
    DepthError fine_error; ///< the same over blocks of `fine_block`
    DepthError cell_error; ///< the same over single reference cells
    /// Against the run with the same dt and seed but the reference's integrator,
    /// cells, smoothing and occlusion, over blocks of `block`: both runs drew
    /// the same flakes, so this is the error of those knobs without sampling noise.
    DepthError paired;
    std::vector<double> rel_l1_by_seed; ///< error.rel_l1 of each seed's run

    /// CPU ms per simulated second: what a real-time loop pays at this dt.
    [[nodiscard]] double cpu_ms_per_second() const {
        return cpu_ms_per_tick / static_cast<double>(knobs.dt);
    }
};

/// The noise floor at the scene's own knobs with the wind's random walk off
/// and on: single runs (floor seeds) against a mean of reference-seed runs.
struct WindCheck {
    double rel_l1_steady = 0.0, rel_l1_walk = 0.0;
    /// Smallest and largest settled share of spawned mass over all those runs.
    double settled_min_steady = 0.0, settled_max_steady = 0.0;
    double settled_min_walk = 0.0, settled_max_walk = 0.0;
};

/// The sweeps as lists of indices into `points` (a setting shared by two sweeps runs once).
struct SceneStudy {
    std::vector<ScenePoint> points;
    std::vector<std::size_t> dt_sweep, integrator_sweep, cell_sweep, smoothing_sweep,
        occlusion_sweep, grid;
    std::vector<ScenePoint> floor; ///< one per floor seed
    double reference_ms_per_tick = 0.0;
    double reference_settled_kg = 0.0;
    double base_cell = 0.0; ///< the scene's finest surface cell (m) before cell_scale
    WindCheck wind;

    /// Mean, smallest and largest error.rel_l1 of the floor runs.
    [[nodiscard]] double floor_rel_l1() const;
    [[nodiscard]] double floor_rel_l1_min() const;
    [[nodiscard]] double floor_rel_l1_max() const;
};

/// Runs everything; `progress` (may be null) gets one line per simulation.
[[nodiscard]] SceneStudy run_scene_study(const SceneStudyOptions& o, std::FILE* progress);

} // namespace snow::accuracy
