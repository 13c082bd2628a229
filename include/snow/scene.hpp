/// @file scene.hpp
/// @brief Scene loading (target snow::scene, no GL): load_scene_file and
/// load_scene_memory turn a glTF 2.0 file (.gltf or .glb) whose `extras.snow`
/// objects declare surfaces, colliders, moving bodies, a cover and effects
/// (or, with auto snow, a plain model's meshes imply them) into a Simulation
/// and its SceneVisuals (meshes, lights, camera, sky, fog), with
/// SceneOverrides for command-line settings. Self-contained: the standard
/// library and GLM. See docs/scenes.md and docs/embedding.md.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <snow/render.hpp>
#include <snow/snow.hpp>

namespace snow {

/// The most work a scene may declare (docs/scenes.md#work-budget). The
/// loader adds up what a file declares and refuses one past any of these with
/// one error naming the declaration and the budget, before anything is
/// allocated. The defaults admit every shipped scene with room to spare and
/// bound any input's load (docs/reliability.md "Bounded work"); a host that
/// can afford more raises them.
struct WorkBudget {
    std::uint64_t snow_cells = 1u << 21;         ///< the surfaces' and the cover's cells together
    std::uint64_t surfaces = 1024;               ///< snow surfaces
    std::uint64_t collider_triangles = 1u << 18; ///< triangles of the mesh colliders
    std::uint64_t bodies = 64;                   ///< moving bodies
    std::uint64_t flakes = 1u << 20;             ///< the flake pool (max_flakes)
    std::uint64_t field_cells = 1u << 17;        ///< the wind field's cells
    /// Field cells times pressure_iterations: the work of one solver step.
    std::uint64_t field_cell_sweeps = 1u << 21;
    std::uint64_t occlusion_texels = 1u << 20; ///< the sky map's resolution squared
};

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
    /// The work the scene may declare; the apps raise `flakes` to --max-flakes.
    WorkBudget budget;
};

/// Either a ready simulation and its visuals (sim set, error empty) or one
/// error naming the file and the field (sim null). Never a partly built scene.
struct SceneLoadResult {
    std::unique_ptr<Simulation> sim;
    SceneVisuals visuals; ///< meshes, lights, camera, sky: what the renderer draws
    std::string error;
    std::string name; ///< the glTF scene's name, else the file's stem
    /// What the loader skipped ("<file>: <field> <problem>": a missing image
    /// no material draws, a non-triangle primitive, ...); each is also printed
    /// to stderr.
    std::vector<std::string> warnings;
};

/// Largest glTF JSON accepted (a .gltf file, or a .glb's JSON chunk; bytes).
inline constexpr std::size_t max_scene_bytes = 16u << 20;
/// Largest total size of the buffers of one scene (bytes): external files,
/// data URIs and a .glb's BIN chunk.
inline constexpr std::size_t max_scene_buffer_bytes = 256u << 20;
/// Largest scene file accepted (bytes); larger files are rejected unread.
inline constexpr std::size_t max_scene_file_bytes = max_scene_bytes + max_scene_buffer_bytes;

/// Loads a .gltf or .glb file (told apart by the .glb magic; a file named
/// `.glb` must have it). Buffers come from data URIs, the .glb's BIN chunk or
/// files inside the scene file's own folder.
[[nodiscard]] SceneLoadResult load_scene_file(const std::string& path,
                                              const SceneOverrides& overrides = {});

/// Loads .gltf text or .glb bytes from memory; no file may be read, so
/// buffers come from data URIs or the BIN chunk. `name_for_errors` prefixes
/// every error and warning.
[[nodiscard]] SceneLoadResult load_scene_memory(std::string_view bytes,
                                                std::string_view name_for_errors,
                                                const SceneOverrides& overrides = {});

} // namespace snow
