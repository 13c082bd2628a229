/// @file scene_loader.hpp
/// @brief Loads a glTF 2.0 scene (.gltf or .glb) whose `extras.snow` objects
/// declare what the simulation does with each node (docs/scenes.md). The
/// public header of snow::scene, with scene_types.hpp (what it takes and
/// gives); the other scene_*.hpp files beside it are internals.
#pragma once

#include "game/scene/scene_types.hpp"

#include <string>
#include <string_view>

namespace snow {

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
