/// @file run_report.hpp
/// @brief The report snow_run prints: state hash, mass balance, per-system cost.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <string>

namespace snow {

struct RunInfo {
    std::string scene;
    std::uint64_t ticks = 0;
    double wall_ms = 0.0;
};

/// One JSON object (see README "snow_run report").
[[nodiscard]] std::string run_report_json(const Simulation& sim, const RunInfo& info);
/// The same facts for a person.
[[nodiscard]] std::string run_report_text(const Simulation& sim, const RunInfo& info);
/// 16 lower-case hex digits.
[[nodiscard]] std::string hash_hex(std::uint64_t h);

} // namespace snow
