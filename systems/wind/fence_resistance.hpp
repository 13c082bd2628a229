/// @file fence_resistance.hpp
/// @brief The pressure loss of air through a slat fence by its porosity: the
/// wind field takes a porous box as a momentum sink of this coefficient
/// [Wil85] (docs/wind_field.md "Porous fences").
#pragma once

#include <cmath>

namespace snow {

/// Pressure-loss coefficient k (Δp = k·½ρu²) of a thin plate with sharp-edged
/// openings making up `porosity` of its area, Idelchik's law [Idel]:
/// k = (0.707·(1 − ε)^0.375 + 1 − ε)² / ε²: 4.4 at ε = 0.5, 0 at ε = 1.
[[nodiscard]] inline double fence_pressure_loss(double porosity) {
    const double closed = 1.0 - porosity;
    const double jet = 0.707 * std::pow(closed, 0.375) + closed;
    return jet * jet / (porosity * porosity);
}

} // namespace snow
