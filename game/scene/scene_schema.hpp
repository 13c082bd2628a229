/// @file scene_schema.hpp
/// @brief The `extras.snow` schema (docs/scenes.md) and KHR_lights_punctual,
/// read into the simulation's own def structs by one field table per struct
/// (internal to snow::scene). Geometry comes from scene_geometry.
#pragma once

#include "game/scene/scene_fields.hpp"
#include "game/scene/scene_terrain.hpp"
#include "systems/api/simulation_internals.hpp"
#include <snow/render.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace snow {

enum class ColliderKind : std::uint8_t { box, sphere, mesh, capsule };

/// A node's `extras.snow`: its role in the simulation. The surface's settings
/// are read here; its rectangle and height come from the node's mesh later.
struct NodeSnow {
    std::optional<SurfaceDef> surface;
    std::optional<ColliderKind> collider;
    /// A scripted path: the node's collider becomes a moving body.
    std::optional<BodyMotion> motion;
    bool snowball = false;   ///< a moving sphere that picks up snow
    bool on_ground = false;  ///< the body stands on the bare ground under it
    float compaction = 0.0f; ///< the body packs this fraction of the snow in its way
    float porosity = 0.0f;   ///< a box collider's open share (a slat fence)
};

/// A node whose collider moves (a path, a snowball, or a capsule) is a body.
[[nodiscard]] inline bool is_body(const NodeSnow& role) {
    return role.motion || role.snowball || role.collider == ColliderKind::capsule;
}

/// The scene's `extras.snow`: settings and the effects it declares. An absent
/// effect stays nullopt and is never created ("simulate only what a scene calls for").
struct SceneSnow {
    SimConfig config;
    bool has_bounds = false; ///< false: bounds come from the geometry
    std::optional<Emitter> emitter;
    std::optional<Wind> wind;
    std::optional<WindFieldDef> wind_field;         ///< `wind.field`: the field obstacles shape
    std::optional<WindTransportDef> wind_transport; ///< `wind.field.transport`
    std::optional<Fog> fog;
    std::optional<OcclusionCamera> occlusion;
    std::optional<SpectralSnow> spectral;
    std::optional<Sun> sun;
    std::optional<CoverDef> cover;
    std::optional<CameraDef> camera; ///< absent: the default view, or one framing auto snow
    std::optional<WorldDef> world;   ///< a terrain from a height map (docs/world.md)
    Environment environment;
    /// `auto`: snow on the plain scene (scene_auto_snow.hpp) for what it leaves undeclared.
    bool auto_snow = false;
};

/// One KHR_lights_punctual light (only "point" lights are supported).
struct LightSpec {
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
};

/// Everything the schema says about a file, indexed like the file's arrays.
struct SceneSchema {
    std::vector<NodeSnow> nodes;                       ///< per `nodes[i]`
    std::vector<std::optional<LightSpec>> node_lights; ///< per `nodes[i]`: the light it carries
    std::vector<SceneSnow> scenes;                     ///< per `scenes[s]`
    bool asset_auto_snow = false; ///< `asset.extras.snow.auto`: auto snow whichever scene is used
};

/// The JSON path of `scenes[s].extras.snow`, which prefixes its errors.
[[nodiscard]] std::string scene_snow_path(std::size_t scene);

/// The JSON path of `asset.extras.snow`, which holds only `auto`.
inline constexpr const char* asset_snow_path = "asset.extras.snow";

/// Reads every node's and scene's `extras.snow` and the lights of a parsed
/// glTF file (whose structure read_document() has checked). Types, ranges and
/// unknown keys are checked by the tables; the simulation's own validate()
/// functions check the effects' values (one place, shared with the facade).
/// Extras other than `snow` are ignored. Throws SceneError naming the field.
[[nodiscard]] SceneSchema read_schema(const Json& doc);

} // namespace snow
