/// @file scene_geometry.hpp
/// @brief Instances a glTF scene: walks the node graph from the scene's roots,
/// composes transforms (glTF 2.0 §3.5.3) and turns every triangle primitive
/// into world-space triangles (internal to snow::scene).
#pragma once

#include "game/scene/scene_document.hpp"
#include "systems/geometry/geometry.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace snow {

/// Caps on what one scene may instance (beyond them: an input error).
inline constexpr std::size_t max_scene_nodes = 1u << 16;
inline constexpr std::size_t max_scene_primitives = 1u << 16;
inline constexpr std::size_t max_scene_vertices = 1u << 22;
inline constexpr std::size_t max_scene_indices = 1u << 24;

/// A mesh primitive in world space: triangles, unit normals per vertex, and
/// its material's base colour (and texture).
struct WorldPrimitive {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;   ///< 3 per triangle, counter-clockwise seen from outside
    glm::vec3 color{1.0f};                ///< material baseColorFactor (glTF default white)
    std::shared_ptr<const Image> texture; ///< the material's baseColorTexture, if it has one
    std::vector<glm::vec2> texcoords;     ///< TEXCOORD_0 per vertex, with a texture only
};

/// One node the scene instances, with its world transform applied.
struct WorldNode {
    std::size_t index = 0; ///< into the file's `nodes`
    std::string name;
    glm::dmat4 world{1.0};                  ///< its parents' transforms times its own
    glm::vec3 position{0.0f};               ///< world-space origin (for lights)
    std::vector<WorldPrimitive> primitives; ///< empty without a mesh of triangles
    Aabb bounds;                            ///< of all primitives; meaningful when non-empty
};

/// The instanced scene, nodes in depth-first order (children in file order).
struct SceneGeometry {
    std::optional<std::size_t> scene_index; ///< none: the file has no `scenes`
    std::string scene_name;
    std::vector<WorldNode> nodes;
};

/// Instances the file's default scene (`scene`, else scenes[0]); a file
/// without `scenes` instances every root node (one that is nobody's child),
/// in index order. Rejects bad indices, cycles and shared children, malformed,
/// non-finite or non-affine transforms and anything over the caps. Primitives
/// that are not triangles (points, lines, strips, fans) are skipped with a
/// line in `warnings`. Throws SceneError.
[[nodiscard]] SceneGeometry instance_scene(const GltfDocument& doc,
                                           std::vector<std::string>& warnings);

/// All triangles of a node, three world-space vertices each (mesh colliders).
[[nodiscard]] std::vector<glm::vec3> node_triangles(const WorldNode& node);

} // namespace snow
