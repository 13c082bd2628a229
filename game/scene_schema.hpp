/// @file scene_schema.hpp
/// @brief The `extras.snow` schema (docs/scenes.md) read into the simulation's
/// own def structs (internal to snow::scene). Geometry comes from scene_gltf.
#pragma once

#include "game/scene_json.hpp"
#include "systems/simulation.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace snow {

enum class ColliderKind : std::uint8_t { box, sphere, mesh };

/// A node's `extras.snow`: its role in the simulation. The surface's settings
/// are read here; its rectangle and height come from the node's mesh later.
struct NodeSnow {
    std::optional<SurfaceDef> surface;
    std::optional<ColliderKind> collider;
};

/// The scene's `extras.snow`: settings and the effects it declares. An absent
/// effect stays nullopt and is never created ("simulate only what a scene calls for").
struct SceneSnow {
    SimConfig config;
    bool has_bounds = false; ///< false: bounds come from the geometry
    std::optional<Emitter> emitter;
    std::optional<Wind> wind;
    std::optional<WindFieldDef> wind_field; ///< `wind.field`: the field obstacles shape
    std::optional<Fog> fog;
    std::optional<OcclusionCamera> occlusion;
    std::optional<SpectralSnow> spectral;
    CameraDef camera;
    Environment environment;
};

/// One KHR_lights_punctual light (only "point" lights are supported).
struct LightSpec {
    glm::vec3 color{1.0f};
    float intensity = 1.0f;
};

/// Reads `nodes[i].extras.snow`; `path` is that field's name for errors.
[[nodiscard]] NodeSnow parse_node_snow(const Json& snow, const std::string& path);
/// Reads `scenes[i].extras.snow`; null gives the defaults (no effects).
[[nodiscard]] SceneSnow parse_scene_snow(const Json* snow, const std::string& path);
/// Reads the document's `extensions.KHR_lights_punctual.lights`.
[[nodiscard]] std::vector<LightSpec> parse_lights(const Json& doc);
/// The light index a node refers to (`extensions.KHR_lights_punctual.light`), if any.
[[nodiscard]] std::optional<std::size_t> node_light(const Json& node, const std::string& path,
                                                    std::size_t light_count);

} // namespace snow
