/// @file roof_load.hpp
/// @brief What a plane roof keeps of a snowfall, by pitch: the roofs-by-pitch
/// check of the tests and of snow_validate ([EN1991] in docs/references.md).
#pragma once

#include <snow/snow.hpp>

namespace snow {

/// Plan load (kg/m²) roof_over_ground() snows onto the ground: 1 kN/m², a
/// design ground load of lowland Europe.
inline constexpr double design_ground_load = 1000.0 / 9.81;

/// Roof over ground load, averaged over a still-air snowfall that puts
/// design_ground_load on a 2 × 2 m ground: the same units land on every cell
/// of the ground and of a 2 × 2 m plane roof of `pitch_deg` degrees (`roof`
/// gives its friction, adhesion and repose) in 100 steps 3 ticks apart, and
/// the ratio is that of the two loads summed over the steps. The roof's eaves
/// hold any depth (a large edge_limit): only sliding and rolling shed it.
/// Both grids have cells of `cell` metres.
[[nodiscard]] double roof_over_ground(double pitch_deg, const SurfaceDef& roof = SurfaceDef{},
                                      float cell = 0.1f);

} // namespace snow
