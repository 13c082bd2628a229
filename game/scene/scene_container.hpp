/// @file scene_container.hpp
/// @brief The two forms of a glTF file (internal to snow::scene): JSON text
/// (.gltf) or the binary container (.glb: a 12-byte header, a JSON chunk and
/// an optional BIN chunk; glTF 2.0 §4.4). Every size and offset of a .glb is
/// checked before any of its bytes is used.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace snow {

/// The four bytes a .glb starts with.
inline constexpr std::string_view glb_magic = "glTF";

/// A scene file split into its parts; views into the file's bytes.
struct SceneSource {
    std::string_view json;                             ///< the glTF JSON text
    std::optional<std::span<const unsigned char>> bin; ///< a .glb's BIN chunk, if it has one
};

/// True when `bytes` start with the .glb magic.
[[nodiscard]] bool is_glb(std::string_view bytes);

/// Splits a .glb (header, JSON chunk, optional BIN chunk, unknown chunks
/// ignored). Throws SceneError naming the header field or chunk that is wrong:
/// bad magic or version, a length that disagrees with the file, a chunk that
/// overruns the file, a first chunk that is not JSON, a misplaced BIN chunk.
[[nodiscard]] SceneSource split_glb(std::string_view bytes);

} // namespace snow
