/// @file scene_buffers.hpp
/// @brief Fills every glTF buffer with its bytes (internal to snow::scene):
/// from a base64 `data:` URI, from the .glb's BIN chunk, or from a file inside
/// the scene's folder and nowhere else; and decodes the PNG images materials
/// take as base colour textures, from the same places. Other images are never
/// read.
#pragma once

#include "game/scene/scene_document.hpp"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace snow {

/// Where a scene's buffers may come from.
struct BufferSources {
    std::optional<std::span<const unsigned char>> bin; ///< the .glb's BIN chunk
    std::string folder; ///< the scene file's folder (absolute); empty: no file may be read
};

/// Loads `doc.buffers[i].data` (exactly byteLength bytes each, at most
/// max_scene_buffer_bytes in total). A URI may be a `data:` URI or a relative
/// path that stays inside the folder (no absolute paths, schemes, backslashes
/// or `..`; %-escapes are decoded first, symlinks resolved). Throws SceneError
/// naming e.g. `buffers[0].uri`. Then decodes every image a material takes
/// as its baseColorTexture into `doc.images[i].pixels` (PNG only, at most
/// max_scene_texels in all); one that is missing, outside the folder or not a
/// valid PNG throws naming e.g. `images[0].uri`. Other images whose files are
/// missing or outside the folder only add a line to `warnings`.
void load_buffers(GltfDocument& doc, const BufferSources& sources,
                  std::vector<std::string>& warnings);

/// The bytes of the file `uri` names (a relative path, fenced to the scene's
/// `folder` like a buffer's URI; at most max_scene_buffer_bytes). A scene
/// loaded from memory (empty `folder`) reads no file. Throws SceneError
/// naming `field`.
[[nodiscard]] std::vector<unsigned char>
read_scene_file(const std::string& folder, const std::string& uri, const std::string& field);

} // namespace snow
