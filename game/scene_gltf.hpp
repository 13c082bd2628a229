/// @file scene_gltf.hpp
/// @brief tinygltf behind a fence (docs/design.md "Bad input"): ASCII
/// glTF only, no image decoding, file access only inside the scene's folder
/// (internal to snow::scene).
#pragma once

#include "game/scene_json.hpp"

#include <tiny_gltf.h>

#include <string>
#include <string_view>

namespace snow {

/// Rejects buffer and image URIs that are not data URIs or plain relative
/// paths (absolute, `..`, schemes, `%` escapes); `files_allowed` false rejects
/// every external file. Throws SceneError naming e.g. `buffers[0].uri`.
void check_uris(const Json& doc, bool files_allowed);

/// Parses glTF text with tinygltf. `folder` (absolute; empty = no file access)
/// is the only directory it may read from, and reads are capped in total at
/// max_scene_buffer_bytes. Any tinygltf error or warning throws SceneError.
[[nodiscard]] tinygltf::Model parse_gltf(std::string_view text, const std::string& folder);

} // namespace snow
