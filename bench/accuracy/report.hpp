/// @file report.hpp
/// @brief What snow_accuracy writes: CSV files for gnuplot and the body of
/// docs/accuracy.md (tables and method) as markdown.
#pragma once

#include "bench/accuracy/pareto.hpp"
#include "bench/accuracy/scene_study.hpp"
#include "bench/accuracy/trajectory_study.hpp"
#include "bench/accuracy/wind_field_study.hpp"

#include <string>
#include <vector>

namespace snow::accuracy {

/// Everything one run of the study produced.
struct StudyResults {
    TrajectoryOptions trajectory_options;
    std::vector<TrajectoryRow> trajectory;
    float large_pool_dt = 0.0f;
    std::uint32_t large_pool_flakes = 0;
    std::vector<double> large_pool_ns; ///< per trajectory_options.integrators
    SceneStudyOptions scene_options;
    SceneStudy scene;
    std::vector<std::size_t> front; ///< over all studied settings
    std::vector<PresetPick> presets;
    WindFieldStudyOptions wind_options;
    WindFieldStudy wind;
    double seconds_total = 0.0; ///< wall time of the whole study
};

/// trajectory.csv, trajectory_<integrator>.dat (one per integrator, for
/// gnuplot), scene.csv, scene.dat, floor.gp, wind_field.csv, wind_field.dat
/// and report.md in `dir` (which must exist).
/// Each file is written all or nothing; throws FileWriteError naming a file
/// that cannot be written.
void write_results(const std::string& dir, const StudyResults& r);

} // namespace snow::accuracy
