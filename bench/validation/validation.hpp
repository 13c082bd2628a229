/// @file validation.hpp
/// @brief One row of the validation table (docs/validation.md): a quantity
/// the simulation produces, the published value it is held to and the band
/// the source's scatter allows.
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace snow::validation {

struct Row {
    std::string quantity;  ///< what is measured, e.g. "fall speed, D = 5 mm"
    std::string published; ///< the published value or law, with its key in docs/references.md
    std::string scene;     ///< what the probe runs
    double ours = 0.0;     ///< what the simulation gives
    std::string unit;
    double low = 0.0, high = 0.0; ///< the pass band, in `unit`
    [[nodiscard]] bool pass() const { return ours >= low && ours <= high; }
};

/// `v` printed with a printf `format` (one number).
inline std::string number(const char* format, double v) {
    char text[64];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

/// How long the probes simulate: `quick` is a seconds-long smoke run whose
/// numbers are not for the table.
struct Plan {
    bool quick = false;
};

/// A group of rows; `name` is printed as progress while it runs.
struct Probe {
    const char* name;
    std::function<std::vector<Row>(const Plan&)> run;
};

/// Fall speed and mass by size, from one still-air snowfall [LH74].
[[nodiscard]] std::vector<Row> flakes_by_size(const Plan& plan);
/// The density fresh snow lands at by air temperature [HP98].
[[nodiscard]] std::vector<Row> fresh_density_by_temperature(const Plan& plan);
/// The density of a snowpack after days of settling under its own weight [And76].
[[nodiscard]] std::vector<Row> settled_density(const Plan& plan);
[[nodiscard]] std::vector<Row> pile_flank_angle(const Plan& plan);
[[nodiscard]] std::vector<Row> roof_load_by_pitch(const Plan& plan);
/// Still air in a closed building and the reattachment behind a cube [MT93].
[[nodiscard]] std::vector<Row> ground_wind(const Plan& plan);

/// The saltation flux over a snow field against [PG90], and at half the
/// cell, twice the depth, half the tick and half the field's cells.
[[nodiscard]] std::vector<Row> saltation_flux(const Plan& plan);

/// The lee and windward drifts of a 50% porous fence against Tabler's
/// equilibrium drifts [Tab80].
[[nodiscard]] std::vector<Row> fence_drift_shape(const Plan& plan);

} // namespace snow::validation
