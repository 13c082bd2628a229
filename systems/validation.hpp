/// @file validation.hpp
/// @brief validate() for every settings struct of the facade; each runs the
/// struct's field table (settings_fields.hpp) and the few rules that relate
/// two fields, and names the field at fault (internal to snow::sim, used by
/// the facade and the scene loader).
#pragma once

#include "systems/body.hpp"
#include "systems/emitter.hpp"
#include "systems/field_rules.hpp"
#include "systems/flake_pool.hpp"
#include "systems/fog.hpp"
#include "systems/geometry.hpp"
#include "systems/occlusion.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_cover.hpp"
#include "systems/snow_surface.hpp"
#include "systems/spectral_snow.hpp"
#include "systems/wind.hpp"
#include "systems/wind_field.hpp"

namespace snow {

[[nodiscard]] Invalid validate(const SimConfig& c);
[[nodiscard]] Invalid validate(const Emitter& e);
/// A box collider's extent (fields "box.min", "box.max").
[[nodiscard]] Invalid validate(const Aabb& box);
[[nodiscard]] Invalid validate(const FlakeSpec& f);
[[nodiscard]] Invalid validate(const Wind& w);
[[nodiscard]] Invalid validate(const Fog& f);
[[nodiscard]] Invalid validate(const SpectralSnow& s);
[[nodiscard]] Invalid validate(const OcclusionCamera& cam);
/// A scripted path (fields "motion.waypoints", "motion.speed").
[[nodiscard]] Invalid validate(const BodyMotion& motion);
/// A body's shape and size, and its motion when it has waypoints (fields "body.*").
[[nodiscard]] Invalid validate(const BodyDef& def);
/// A wind field's grid and solver settings (fields "wind.field.*").
[[nodiscard]] Invalid validate(const WindFieldDef& d);
/// Snow transport by the field's wind (fields "wind.field.transport.*").
[[nodiscard]] Invalid validate(const WindTransportDef& t);
/// A surface's settings; make_surface() adds the checks of the grid they give.
[[nodiscard]] Invalid validate(const SurfaceDef& def);
/// A cover's settings; make_cover_surface() adds the checks of the grid they give.
[[nodiscard]] Invalid validate(const CoverDef& def);

} // namespace snow
