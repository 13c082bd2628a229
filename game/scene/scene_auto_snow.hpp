/// @file scene_auto_snow.hpp
/// @brief Snow on a plain scene (`--auto-snow`, `extras.snow.auto`): what a
/// scene gets for each part it leaves undeclared, so a model from any tool
/// catches snow (internal to snow::scene; docs/scenes.md#snow-on-a-plain-scene).
#pragma once

#include "game/scene/scene_geometry.hpp"
#include "game/scene/scene_schema.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace snow {

/// The auto cover's cell edge: at least this (m), and coarse enough that the
/// cover has at most `auto_cover_cells_per_side` cells along its longer side.
inline constexpr float auto_cover_min_cell = 0.05f;
inline constexpr std::uint32_t auto_cover_cells_per_side = 1024;
/// Parcels a second per m² of the auto emitter: the default rate over 20 × 20 m.
inline constexpr float auto_flakes_per_m2_s = 5.0f;

/// The bounds of every instanced node's triangles; none when no node has any.
[[nodiscard]] std::optional<Aabb> mesh_bounds(const SceneGeometry& g);

/// Fills in what the scene leaves undeclared: every mesh node without a role
/// becomes a mesh collider; the scene gets an occlusion camera, a cover over
/// the meshes' xz footprint, an emitter over `config.bounds` and a camera
/// framing the meshes. What `settings` and `roles` declare stays as it is.
/// `field` names what asked for it (errors start with it); throws SceneError
/// when the scene has no triangle mesh or its footprint is under one cell.
void add_auto_snow(const SceneGeometry& g, const SimConfig& config, const std::string& field,
                   std::vector<NodeSnow>& roles, SceneSnow& settings);

} // namespace snow
