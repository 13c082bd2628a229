/// @file limits.hpp
/// @brief Every size and range limit of the simulation, spelled once: the
/// validation of user input checks against these, and the systems size their
/// structures by them. A value past a limit is an input error naming its field.
#pragma once

#include "systems/core/units.hpp"

#include <cstdint>

namespace snow {

// -- SimConfig --
inline constexpr double max_dt = 1.0;                           ///< s per tick
inline constexpr std::uint32_t max_flakes = 16u << 20;          ///< flake pool capacity
inline constexpr unsigned max_threads = 256;                    ///< job pool workers
inline constexpr std::uint32_t max_smoothing_iterations = 4096; ///< per surface per tick
inline constexpr double min_air_temperature = -80.0;            ///< °C, colder than any snowfall
inline constexpr double max_air_temperature = 40.0;             ///< °C
inline constexpr double max_settle_interval = 3600.0;           ///< s between settling steps

// -- settings structs --
inline constexpr double max_emitter_rate = 1.0e8; ///< flakes per second
/// Heaviest declared snowfall (kg/m²/h): far past any storm, so a scene
/// may fast-forward its weather.
inline constexpr double max_snowfall_kg_m2_h = 1.0e4;
inline constexpr double max_flake_size = 1.0;            ///< diameter (m)
inline constexpr double max_wind_base_component = 200.0; ///< |wind.base.x|, .y, .z (m/s)

// -- surfaces --
/// Largest grid a surface may have (cells per side).
inline constexpr std::uint32_t max_surface_cells_per_side = 4096;
/// Largest level magnitude a surface may use (snow units): differences and
/// products in redistribution stay far inside 64/128-bit range.
inline constexpr double max_surface_level = 1.0e15;
/// Most settled units Simulation::add_settled_snow lets one cell reach: far
/// above any real pile, and clear of unsigned wrap-around in later landings.
inline constexpr std::uint32_t max_cell_units = (1u << 31) - 1;

// -- covers --
/// Largest cover (cells in all).
inline constexpr std::uint64_t max_cover_cells = 4096ull * 4096ull;
/// Steepest angle of repose a cover may use (degrees; its tangent stays finite).
inline constexpr double max_repose_deg = 89.0;

// -- the wind field --
/// Largest cells_x·cells_y·cells_z a field may have.
inline constexpr std::uint64_t max_wind_field_cells = 1ull << 24;
inline constexpr std::uint32_t max_wind_field_update_every = 1u << 16; ///< ticks
inline constexpr std::uint32_t max_wind_field_sample_every = 1u << 10; ///< ticks
inline constexpr std::uint32_t max_pressure_iterations = 4096;         ///< SOR sweeps per step
inline constexpr double max_eddy_viscosity = 10.0;                     ///< m²/s

// -- moving bodies --
inline constexpr double max_body_size = 100.0;   ///< radius, half extent or half height (m)
inline constexpr double max_body_speed = 1000.0; ///< m/s along a scripted path

// -- wind transport --
inline constexpr double max_transport_roughness = 1.0;            ///< z0 (m)
inline constexpr double max_transport_fast_forward = 1.0e5;       ///< seconds of drifting a second
inline constexpr double max_transport_adjustment_length = 1000.0; ///< m
inline constexpr double max_transport_height = 100.0;             ///< m above the snow

// -- the occlusion camera --
inline constexpr std::uint32_t max_occlusion_resolution = 4096; ///< texels per side
inline constexpr double max_occlusion_tilt = 1.2;               ///< |tilt| (radians)

// -- the collider grid --
/// Cells per axis of the grid that indexes boxes and spheres.
inline constexpr std::uint32_t max_collider_cells_per_side = 256;

// -- spectral snow --
inline constexpr std::uint32_t min_spectral_size_xy = 8, max_spectral_size_xy = 512;
inline constexpr std::uint32_t min_spectral_size_t = 4, max_spectral_size_t = 256;

} // namespace snow
