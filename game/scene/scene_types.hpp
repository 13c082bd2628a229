/// @file scene_types.hpp
/// @brief What the scene loader takes and gives (SceneOverrides,
/// SceneLoadResult) and the size limits it enforces, apart from the loader
/// (scene_loader.hpp) so the loader's internals can use them without
/// including it. Reached through <snow/scene.hpp>.
#pragma once

#include "render/scene_visuals.hpp"
#include "systems/api/simulation.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace snow {

/// Values that replace the scene's own `simulation` settings (command line).
struct SceneOverrides {
    std::optional<std::uint64_t> seed;
    std::optional<float> dt;
    std::optional<unsigned> threads;
    std::optional<Integrator> integrator;
    std::optional<std::uint32_t> max_flakes;
    /// Multiplies every surface's cell edge (quality presets, docs/accuracy.md).
    std::optional<float> cell_scale;
    /// Replaces the occlusion camera's resolution; ignored when the scene has none.
    std::optional<std::uint32_t> occlusion_resolution;
    /// Replaces SimConfig::smoothing_iterations.
    std::optional<std::uint32_t> smoothing_iterations;
    /// Replaces the file's `extras.snow.auto`: true fills in mesh colliders, an
    /// occlusion camera, a cover, an emitter and a camera where the scene
    /// declares none (docs/scenes.md#snow-on-a-plain-scene).
    std::optional<bool> auto_snow;
    /// Replaces the global wind's mean (m/s); the scene's random walk and
    /// gusts stay (a scene without wind gets the default walk).
    std::optional<glm::vec3> wind;
};

/// Either a ready simulation and its visuals (sim set, error empty) or one
/// error naming the file and the field (sim null). Never a partly built scene.
struct SceneLoadResult {
    std::unique_ptr<Simulation> sim;
    SceneVisuals visuals; ///< meshes, lights, camera, sky: what the renderer draws
    std::string error;
    std::string name; ///< the glTF scene's name, else the file's stem
    /// What the loader skipped ("<file>: <field> <problem>": a missing texture
    /// image, a non-triangle primitive, ...); each is also printed to stderr.
    std::vector<std::string> warnings;
};

/// Largest glTF JSON accepted (a .gltf file, or a .glb's JSON chunk; bytes).
inline constexpr std::size_t max_scene_bytes = 64u << 20;
/// Largest total size of the buffers of one scene (bytes): external files,
/// data URIs and a .glb's BIN chunk.
inline constexpr std::size_t max_scene_buffer_bytes = 256u << 20;
/// Largest scene file accepted (bytes); larger files are rejected unread.
inline constexpr std::size_t max_scene_file_bytes = max_scene_bytes + max_scene_buffer_bytes;

} // namespace snow
