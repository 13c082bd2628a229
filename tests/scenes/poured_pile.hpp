/// @file poured_pile.hpp
/// @brief A pile poured at one point onto a flat surface, and its flank
/// angle: the angle-of-repose check of the tests and of snow_validate
/// ([NSA] in docs/references.md).
#pragma once

#include <snow/snow.hpp>

#include <cstdint>

namespace snow {

/// Mean flank angle (degrees) of the pile on `g`: the slope between 80 % and
/// 20 % of its height, along the four grid directions from its top.
[[nodiscard]] double flank_degrees(const SnowGrid& g);

/// Pours `units` of snow onto the centre of a flat 3 × 3 m surface of `cell`
/// metres (`def_repose_deg` its angle of repose), lets it come to rest for
/// `rest_ticks` and returns its flank angle.
[[nodiscard]] double poured_pile_degrees(double cell, std::uint64_t units, std::uint64_t rest_ticks,
                                         float repose_deg = SurfaceDef{}.repose_deg);

} // namespace snow
