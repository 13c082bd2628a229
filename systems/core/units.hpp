/// @file units.hpp
/// @brief Snow mass is counted in integer units so bookkeeping is exact.
#pragma once

#include <cstdint>

namespace snow {

/// One mass unit is 0.005 g, the lightest flake of [WF §3]; the heaviest
/// (5 g) is 1000 units. Flakes and surface cells both count whole units.
inline constexpr double unit_kg = 5.0e-6;
inline constexpr std::uint32_t max_flake_units = 1000;

/// Density of fresh snow (kg/m^3); turns settled units into depth.
inline constexpr double fresh_snow_density = 100.0;
/// Density of the most packed snow (kg/m^3): a snowball's, and the limit a
/// body's compaction reaches.
inline constexpr double packed_snow_density = 400.0;

} // namespace snow
