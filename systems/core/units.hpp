/// @file units.hpp
/// @brief Snow mass is counted in integer units so bookkeeping is exact.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace snow {

/// One mass unit is 0.005 g, the lightest flake of [WF §3]; the heaviest
/// (5 g) is 1000 units. Flakes and surface cells both count whole units.
inline constexpr double unit_kg = 5.0e-6;
inline constexpr std::uint32_t max_flake_units = 1000;

/// Density (kg/m^3) of snow falling through air at `air_c` °C: Hedstrom &
/// Pomeroy 1998 (docs/references.md [HP98]), fitted for T <= 0 °C; warmer
/// air gets the 0 °C value (there is no melt).
[[nodiscard]] inline double fresh_snow_density(double air_c) {
    return 67.92 + 51.25 * std::exp(std::min(air_c, 0.0) / 2.59);
}
/// Density of snow the wind lays down (kg/m^3): the middle of wind-packed
/// snow's 350–400 kg/m^3 (Cuffey & Paterson 2010, docs/references.md [CP10]).
inline constexpr double wind_packed_snow_density = 375.0;
/// Density of a snowball's packed snow (kg/m^3).
inline constexpr double packed_snow_density = 400.0;

} // namespace snow
