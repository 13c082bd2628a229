/// @file scene_parse.hpp
/// @brief A scene file read up to its instanced geometry, before anything is
/// simulated (internal to snow::scene): the container split, the JSON parsed
/// once, glTF's objects and the snow schema read from that one parse, the
/// buffers loaded and the scene instanced. The loader builds the simulation
/// from it; the tinygltf oracle test (tests/gltf_oracle) compares it with
/// another reader.
#pragma once

#include "game/scene/scene_geometry.hpp"
#include "game/scene/scene_schema.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace snow {

/// What one file holds, read and checked.
struct ParsedScene {
    GltfDocument gltf; ///< every buffer's bytes loaded
    SceneSchema schema;
    SceneGeometry geometry;
};

/// Reads .gltf text or .glb bytes (a .glb by its magic, or always when
/// `must_be_glb`: a file named .glb). Relative URIs resolve inside `folder`;
/// an empty `folder` allows no file. Warnings add lines to `warnings`.
/// Throws SceneError naming the field.
[[nodiscard]] ParsedScene parse_scene(std::string_view bytes, const std::string& folder,
                                      bool must_be_glb, std::vector<std::string>& warnings);

} // namespace snow
