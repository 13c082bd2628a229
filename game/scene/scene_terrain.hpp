/// @file scene_terrain.hpp
/// @brief A scene's terrain (`scenes[s].extras.snow.world`, docs/world.md): a
/// 16-bit grey height map stretched over a world rectangle centred on the
/// origin, turned into a triangle mesh that is both a mesh collider and drawn
/// geometry (internal to snow::scene).
#pragma once

#include "game/scene/scene_fields.hpp"
#include "game/scene/scene_image.hpp"
#include "systems/geometry/geometry.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace snow {

/// Widest terrain side accepted (m): beyond it float positions lose the
/// centimetres the snow is resolved in.
inline constexpr double max_world_extent = 64000.0;
/// Highest and lowest terrain height accepted (m).
inline constexpr double max_world_height = 100000.0;

/// `world`: the height map file and how it is stretched.
struct WorldDef {
    std::string heightmap;      ///< PNG path relative to the scene file
    std::vector<double> extent; ///< [x, z] (m), centred on the origin
    std::vector<double> height; ///< [min, max] (m): grey 0 → min, 65535 → max
};

/// Rows of `world` (every field required).
inline constexpr Field<WorldDef> world_fields[] = {
    {"heightmap", &WorldDef::heightmap, {}, true},
    {"extent", &WorldDef::extent, positive_up_to(max_world_extent), true},
    {"height", &WorldDef::height, between(-max_world_height, max_world_height), true},
};

/// Reads `world` at `path` and checks what the table cannot: two numbers each,
/// max >= min. Throws SceneError naming the field.
[[nodiscard]] WorldDef read_world(const Json& j, const std::string& path);

/// Triangles of a height map of `width` × `height` samples (for the work budget).
[[nodiscard]] std::uint64_t terrain_triangle_count(std::uint32_t width, std::uint32_t height);

/// The terrain's bounds: the extent round the origin, the height range.
[[nodiscard]] Aabb terrain_bounds(const WorldDef& def);

/// The terrain as an indexed mesh: one vertex per sample, sample (i, j) at
/// x = −extent_x/2 + i·extent_x/(width−1), z likewise with row j (row 0 at
/// minimum z); two triangles per square of samples, counter-clockwise seen
/// from above; unit normals from the neighbouring samples.
struct TerrainMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
};
[[nodiscard]] TerrainMesh terrain_mesh(const WorldDef& def, const HeightSamples& samples);

/// The mesh as three world-space vertices per triangle (a mesh collider).
[[nodiscard]] std::vector<glm::vec3> terrain_triangles(const TerrainMesh& mesh);

} // namespace snow
