/// @file scene_build.hpp
/// @brief Turns a read and validated scene into a Simulation, only through the
/// facade (<snow/snow.hpp>), and its SceneVisuals (internal to snow::scene).
#pragma once

#include "game/scene/scene_geometry.hpp"
#include "game/scene/scene_image.hpp"
#include "game/scene/scene_schema.hpp"
#include <snow/scene.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace snow {

/// Default simulation bounds: the meshes' bounds grown by this much (m)
/// sideways and below, and by `default_bounds_headroom` above (room to fall).
inline constexpr float default_bounds_margin = 1.0f;
inline constexpr float default_bounds_headroom = 4.0f;

/// Everything read from one file, checked, ready to create.
struct SceneDescription {
    SceneGeometry geometry;
    std::vector<NodeSnow> roles;                  ///< per geometry node
    std::vector<std::optional<LightSpec>> lights; ///< per geometry node
    SceneSnow settings;
    std::string settings_path; ///< "scenes[i].extras.snow", prefixes facade errors
    /// The `auto` field that asks for auto snow (scene or asset level); empty: none.
    std::string auto_snow_path;
    /// The height map of `settings.world`, decoded (present iff it is).
    std::optional<HeightSamples> heights;
};

/// The rectangle and base plane of a node's surface: the top of `bounds`; a
/// sloped plane touches the top of the bounds at its highest corner.
[[nodiscard]] SurfaceDef surface_over(const SurfaceDef& settings, const Aabb& bounds);

/// Creates the simulation and fills `visuals` (meshes, lights, camera, sky).
/// Facade errors (SimulationError) come back as SceneError prefixed with the
/// JSON path they belong to. Throws SceneError.
[[nodiscard]] std::unique_ptr<Simulation>
build_scene(const SceneDescription& d, const SceneOverrides& overrides, SceneVisuals& visuals);

} // namespace snow
