/// @file settings_fields.hpp
/// @brief One field table per settings struct: every field a user may set,
/// by the name scenes and error messages use, with the values it accepts
/// (limits from limits.hpp). validate() checks a struct by its table; the
/// scene loader reads the same fields by it (internal to snow::sim).
#pragma once

#include "systems/body.hpp"
#include "systems/emitter.hpp"
#include "systems/field_rules.hpp"
#include "systems/flake_pool.hpp"
#include "systems/fog.hpp"
#include "systems/geometry.hpp"
#include "systems/limits.hpp"
#include "systems/occlusion.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_cover.hpp"
#include "systems/snow_surface.hpp"
#include "systems/spectral_snow.hpp"
#include "systems/wind.hpp"
#include "systems/wind_field.hpp"

namespace snow {

/// `simulation.*` (bounds and the integrator are checked by validate()).
inline constexpr FieldRule<SimConfig> sim_config_fields[] = {
    {"seed", &SimConfig::seed},
    {"dt", &SimConfig::dt, positive_up_to(max_dt)},
    {"gravity", &SimConfig::gravity},
    {"max_flakes", &SimConfig::max_flakes, between(1, max_flakes)},
    {"threads", &SimConfig::threads, between(1, max_threads)},
    {"smoothing_iterations", &SimConfig::smoothing_iterations,
     between(1, max_smoothing_iterations)},
};

/// A box's corners (min <= max per axis is checked by validate()).
inline constexpr FieldRule<Aabb> aabb_fields[] = {
    {"min", &Aabb::min},
    {"max", &Aabb::max},
};

/// `emitter.*`; each min <= its max is checked by validate().
inline constexpr FieldRule<Emitter> emitter_fields[] = {
    {"rate", &Emitter::rate, between(0, max_emitter_rate)},
    {"mass_min_g", &Emitter::mass_min_g, between(min_flake_mass_g, max_flake_mass_g)},
    {"mass_max_g", &Emitter::mass_max_g, between(min_flake_mass_g, max_flake_mass_g)},
    {"size_min", &Emitter::size_min, positive_up_to(max_flake_size)},
    {"size_max", &Emitter::size_max, positive_up_to(max_flake_size)},
    {"fall_speed_min", &Emitter::fall_speed_min, positive_up_to(max_fall_speed)},
    {"fall_speed_max", &Emitter::fall_speed_max, positive_up_to(max_fall_speed)},
};

/// `flake.*`: one flake placed by hand.
inline constexpr FieldRule<FlakeSpec> flake_fields[] = {
    {"position", &FlakeSpec::position},
    {"velocity", &FlakeSpec::velocity},
    {"k_over_m", &FlakeSpec::k_over_m, positive},
    {"size", &FlakeSpec::size, non_negative},
    {"mass_units", &FlakeSpec::mass_units, between(1, max_flake_units)},
};

/// `wind.*`; current, deviation and gust_left are its running state.
inline constexpr FieldRule<Wind> wind_fields[] = {
    {"base", &Wind::base, between(-max_wind_base_component, max_wind_base_component)},
    {"current", &Wind::current},
    {"deviation", &Wind::deviation},
    {"walk", &Wind::walk, non_negative},
    {"max_deviation", &Wind::max_deviation, non_negative},
    {"gust_strength", &Wind::gust_strength, non_negative},
    {"gust_rate", &Wind::gust_rate, non_negative},
    {"gust_duration", &Wind::gust_duration, positive},
    {"gust_left", &Wind::gust_left, non_negative},
};

/// `wind.field.*`; the total cell count is checked by validate().
inline constexpr FieldRule<WindFieldDef> wind_field_fields[] = {
    {"cells[0]", &WindFieldDef::cells_x, at_least(1)},
    {"cells[1]", &WindFieldDef::cells_y, at_least(1)},
    {"cells[2]", &WindFieldDef::cells_z, at_least(1)},
    {"update_every", &WindFieldDef::update_every, between(1, max_wind_field_update_every)},
    {"sample_every", &WindFieldDef::sample_every, between(1, max_wind_field_sample_every)},
    {"pressure_iterations", &WindFieldDef::pressure_iterations,
     between(1, max_pressure_iterations)},
    {"eddy_viscosity", &WindFieldDef::eddy_viscosity, between(0, max_eddy_viscosity)},
};

/// `wind.field.transport.*`.
inline constexpr FieldRule<WindTransportDef> wind_transport_fields[] = {
    {"threshold", &WindTransportDef::threshold, positive_up_to(max_wind_base_component)},
    {"rate", &WindTransportDef::rate, between(0, max_transport_rate)},
    {"max_fraction", &WindTransportDef::max_fraction, positive_up_to(1)},
    {"height", &WindTransportDef::height, between(0, max_transport_height)},
};

/// `fog.*` (the mode is a choice; puffs have their own table; layer_bottom
/// <= layer_top is checked by validate()).
inline constexpr FieldRule<Fog> fog_fields[] = {
    {"color", &Fog::color},
    {"density", &Fog::density, non_negative},
    {"half_distance", &Fog::half_distance, positive},
    {"layer_bottom", &Fog::layer_bottom},
    {"layer_top", &Fog::layer_top},
    {"layer_density", &Fog::layer_density, non_negative},
};

/// `fog.puffs[i].*`.
inline constexpr FieldRule<FogPuff> fog_puff_fields[] = {
    {"center", &FogPuff::center},
    {"sigma", &FogPuff::sigma, positive},
    {"density", &FogPuff::density, non_negative},
    {"frequency", &FogPuff::frequency},
    {"phase", &FogPuff::phase},
};

/// `occlusion.*`: the sky-map camera [SKY].
inline constexpr FieldRule<OcclusionCamera> occlusion_fields[] = {
    {"resolution", &OcclusionCamera::resolution, between(1, max_occlusion_resolution)},
    {"tilt", &OcclusionCamera::tilt, between(-max_occlusion_tilt, max_occlusion_tilt)},
};

/// `spectral.*` [LZ]; sizes must also be powers of two, and the band ordered
/// and below the volume's Nyquist frequency (checked by validate()).
inline constexpr FieldRule<SpectralSnow> spectral_fields[] = {
    {"size_xy", &SpectralSnow::size_xy, between(min_spectral_size_xy, max_spectral_size_xy)},
    {"size_t", &SpectralSnow::size_t, between(min_spectral_size_t, max_spectral_size_t)},
    {"speed", &SpectralSnow::speed, positive},
    {"band_low", &SpectralSnow::band_low, positive},
    {"band_high", &SpectralSnow::band_high, positive},
    {"opacity", &SpectralSnow::opacity, between(0, 1)},
    {"start_distance", &SpectralSnow::start_distance, non_negative},
};

/// `surface.*`: a snow surface's grid and smoothing [WF §3].
inline constexpr FieldRule<SurfaceDef> surface_fields[] = {
    {"x0", &SurfaceDef::x0},
    {"z0", &SurfaceDef::z0},
    {"size_x", &SurfaceDef::size_x, positive},
    {"size_z", &SurfaceDef::size_z, positive},
    {"cell", &SurfaceDef::cell, positive},
    {"base_y", &SurfaceDef::base_y},
    {"slope_x", &SurfaceDef::slope_x},
    {"slope_z", &SurfaceDef::slope_z},
    {"edge_limit", &SurfaceDef::edge_limit, non_negative},
    {"spills", &SurfaceDef::spills},
    {"laplacian_limit", &SurfaceDef::laplacian_limit, positive},
    {"slide_depth", &SurfaceDef::slide_depth, non_negative},
};

/// `cover.*` [ZCL]; max > min per axis is checked by validate().
inline constexpr FieldRule<CoverDef> cover_fields[] = {
    {"min.x", &CoverDef::min_x},
    {"min.z", &CoverDef::min_z},
    {"max.x", &CoverDef::max_x},
    {"max.z", &CoverDef::max_z},
    {"cell", &CoverDef::cell, positive},
    {"edge_limit", &CoverDef::edge_limit, non_negative},
    {"drop_limit", &CoverDef::drop_limit, positive},
    {"laplacian_limit", &CoverDef::laplacian_limit, positive},
    {"repose_deg", &CoverDef::repose_deg, positive_up_to(max_repose_deg)},
};

/// `motion.*`: a scripted path (its waypoints are checked by validate()).
inline constexpr FieldRule<BodyMotion> motion_fields[] = {
    {"speed", &BodyMotion::speed, between(0, max_body_speed)},
    {"loop", &BodyMotion::loop},
};

/// `body.*` of every shape, then the size fields each shape uses (its
/// motion has its own table).
inline constexpr FieldRule<BodyDef> body_fields[] = {
    {"position", &BodyDef::position},
    {"compaction", &BodyDef::compaction, between(0, 1)},
};
inline constexpr FieldRule<BodyDef> box_body_fields[] = {
    {"half_extents", &BodyDef::half_extents, positive_up_to(max_body_size)},
};
inline constexpr FieldRule<BodyDef> sphere_body_fields[] = {
    {"radius", &BodyDef::radius, positive_up_to(max_body_size)},
};
inline constexpr FieldRule<BodyDef> capsule_body_fields[] = {
    {"radius", &BodyDef::radius, positive_up_to(max_body_size)},
    {"half_height", &BodyDef::half_height, between(0, max_body_size)},
};

} // namespace snow
