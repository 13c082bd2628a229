/// @file scene_document.hpp
/// @brief The glTF 2.0 objects the loader uses, read from the parsed JSON by
/// one field table each (internal to snow::scene). Types are checked here;
/// indices between objects are checked where they are followed
/// (scene_accessor, scene_geometry), and buffer bytes come from scene_buffers.
#pragma once

#include "game/scene/scene_fields.hpp"

#include <snow/render.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace snow {

/// glTF's component types and primitive modes (glTF 2.0 §5.1.2, §5.24.1).
namespace gltf {
inline constexpr std::uint32_t unsigned_byte = 5121;
inline constexpr std::uint32_t unsigned_short = 5123;
inline constexpr std::uint32_t unsigned_int = 5125;
inline constexpr std::uint32_t float_type = 5126;
inline constexpr std::uint32_t mode_triangles = 4;
} // namespace gltf

struct GltfBuffer {
    std::uint64_t byte_length = 0;
    std::optional<std::string> uri;  ///< absent: the .glb's BIN chunk (buffer 0 only)
    std::vector<unsigned char> data; ///< byte_length bytes once scene_buffers has loaded it
};

struct GltfBufferView {
    std::uint64_t buffer = 0;
    std::uint64_t byte_offset = 0;
    std::uint64_t byte_length = 0;
    std::uint32_t byte_stride = 0; ///< 0: tightly packed
};

struct GltfAccessor {
    std::optional<std::uint64_t> buffer_view;
    std::uint64_t byte_offset = 0;
    std::uint32_t component_type = 0;
    std::uint64_t count = 0;
    std::string type; ///< "SCALAR", "VEC3", ...
    bool normalized = false;
    bool sparse = false;
};

struct GltfPrimitive {
    std::optional<std::uint64_t> position, normal; ///< accessors of `attributes`
    std::optional<std::uint64_t> texcoord;         ///< TEXCOORD_0, read with a texture only
    std::optional<std::uint64_t> indices;
    std::optional<std::uint64_t> material;
    std::uint32_t mode = gltf::mode_triangles;
};

struct GltfMesh {
    std::vector<GltfPrimitive> primitives;
};

struct GltfMaterial {
    std::vector<double> base_color{1.0, 1.0, 1.0, 1.0}; ///< pbrMetallicRoughness.baseColorFactor
    /// pbrMetallicRoughness.baseColorTexture: `index` into `textures`, and
    /// `texCoord`, the TEXCOORD_n it reads (only 0 is supported).
    std::optional<std::uint64_t> base_color_texture;
    std::uint64_t base_color_texcoord = 0;
};

struct GltfTexture {
    std::optional<std::uint64_t> source; ///< into `images`
};

struct GltfImage {
    std::optional<std::string> uri;
    std::optional<std::uint64_t> buffer_view;
    /// Decoded by scene_buffers when a material takes it as its base colour
    /// texture; null for an image nothing draws.
    std::shared_ptr<const Image> pixels;
};

struct GltfNode {
    std::string name;
    std::optional<std::uint64_t> mesh;
    std::vector<std::uint64_t> children;
    std::vector<double> matrix, translation, rotation, scale; ///< empty when absent
};

struct GltfScene {
    std::string name;
    std::vector<std::uint64_t> nodes;
};

/// The parts of a glTF file the loader reads.
struct GltfDocument {
    std::string version;                          ///< asset.version
    std::vector<std::string> required_extensions; ///< extensionsRequired
    std::optional<std::uint64_t> scene;           ///< the default scene
    std::vector<GltfScene> scenes;
    std::vector<GltfNode> nodes;
    std::vector<GltfMesh> meshes;
    std::vector<GltfMaterial> materials;
    std::vector<GltfAccessor> accessors;
    std::vector<GltfBufferView> buffer_views;
    std::vector<GltfBuffer> buffers;
    std::vector<GltfTexture> textures;
    std::vector<GltfImage> images;
};

/// Reads a parsed glTF file: rejects what is not glTF 2.0 (not an object, no
/// `asset.version` "2.x"), any wrong type or out-of-range value in the
/// objects above, and required extensions that change geometry or buffers
/// (compression, quantization); required extensions that only change the
/// look add a line to `warnings`. Throws SceneError naming the field.
[[nodiscard]] GltfDocument read_document(const Json& doc, std::vector<std::string>& warnings);

} // namespace snow
