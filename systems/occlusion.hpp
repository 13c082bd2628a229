/// @file occlusion.hpp
/// @brief The occlusion ("sky") camera of [SKY]: an orthographic depth map
/// from above, rasterised on the CPU from the scene's meshes.
#pragma once

#include "ecs/entity.hpp"
#include "ecs/world.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace snow {

/// World resource: settings. Without it, no occlusion system runs.
struct OcclusionCamera {
    std::uint32_t resolution = 256; ///< texels per side over the simulation bounds
    float tilt = 0.0f;              ///< radians; projection leans along the wind
};

/// World resource: the map the occlusion system writes, and what others read.
/// Texel (i, j) covers x0 + i·texel .. +texel, z0 + j·texel .. +texel.
struct OcclusionMap {
    float x0 = 0.0f, z0 = 0.0f, texel = 1.0f;
    std::uint32_t width = 0, height = 0;
    std::vector<float> top_y;          ///< highest geometry (m); -inf where none
    std::vector<std::uint32_t> top_id; ///< Entity::bits of that geometry; 0 where none
    std::uint64_t version = 0;         ///< bumped on every refresh
    // What the map was built from; a change triggers a refresh.
    std::uint64_t geometry_version = ~0ull;
    float wind_angle = 0.0f;
    // Projection: (x, y, z) falls in the texel of (x + shear_x·y, z + shear_z·y),
    // the flake path of a tilted camera leaning downwind (0 when not tilted).
    float shear_x = 0.0f, shear_z = 0.0f;
};

/// OcclusionMap::wind_angle when the projection does not lean (no tilt, no wind, calm).
inline constexpr float occlusion_no_lean = -1.0f;
/// Number of wind directions the tilted projection distinguishes (refresh granularity).
inline constexpr std::uint32_t occlusion_wind_steps = 64;
/// Default height tolerance (m) of occlusion_exposure: absorbs texel sampling of slopes.
inline constexpr float occlusion_tolerance = 0.05f;

struct SnowSurface;

/// Texel (i, j) of world point (x, y, z) along the map's projection; false outside the map.
[[nodiscard]] inline bool occlusion_texel(const OcclusionMap& map, float x, float y, float z,
                                          std::uint32_t& i, std::uint32_t& j) {
    const float u = (x + map.shear_x * y - map.x0) / map.texel;
    const float v = (z + map.shear_z * y - map.z0) / map.texel;
    if (!(u >= 0.0f && v >= 0.0f && u < static_cast<float>(map.width) &&
          v < static_cast<float>(map.height))) {
        return false;
    }
    i = static_cast<std::uint32_t>(u);
    j = static_cast<std::uint32_t>(v);
    return true;
}
/// 1 when the point sees the sky (y >= top_y - tolerance at its texel, or no map
/// data there), 0 when something is above it along the projection.
[[nodiscard]] float occlusion_exposure(const OcclusionMap& map, float x, float y, float z,
                                       float tolerance = occlusion_tolerance);
/// Exposure (0 or 1) of every cell centre of a surface at its snow top; `out`
/// is resized to the cell count (reuse it to avoid allocation).
void surface_exposure(const OcclusionMap& map, const SnowSurface& s, std::vector<float>& out,
                      float tolerance = occlusion_tolerance);
/// Writes the scene's geometry into `map` along its projection: per texel
/// the highest box, sphere, mesh or declared surface top and its entity
/// (covers are snow, not geometry). `map` must be sized and filled with
/// -inf / 0 first.
void rasterise_geometry(const World& w, OcclusionMap& map);
/// Corners of a surface's bare top as the plane through its corner cells (what
/// the occlusion map rasterises): (x0,z0), (x1,z0), (x1,z1), (x0,z1). False for an empty surface.
[[nodiscard]] bool surface_base_corners(const SnowSurface& s, glm::vec3 (&corners)[4]);

/// World resource: bump `version` whenever colliders or surfaces are added,
/// removed or moved, so the occlusion map refreshes.
struct GeometryVersion {
    std::uint64_t version = 0;
};

} // namespace snow
