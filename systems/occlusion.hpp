/// @file occlusion.hpp
/// @brief The occlusion ("sky") camera of [SKY]: an orthographic depth map
/// from above, rasterised on the CPU from the scene's meshes.
#pragma once

#include "ecs/entity.hpp"
#include "systems/source_versions.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace snow {

/// World resource: settings. Without it, no occlusion system runs.
struct OcclusionCamera {
    /// Texels per side over the simulation bounds (at most max_occlusion_resolution).
    std::uint32_t resolution = 256;
    float tilt = 0.0f; ///< radians; projection leans along the wind (|tilt| <= max_occlusion_tilt)
};

/// World resource: the map the occlusion system writes, and what others read.
/// Texel (i, j) covers x0 + i·texel .. +texel, z0 + j·texel .. +texel. Not a
/// pure function of the current sources (source_versions.hpp): saved,
/// restored and hashed.
struct OcclusionMap {
    float x0 = 0.0f, z0 = 0.0f, texel = 1.0f;
    std::uint32_t width = 0, height = 0;
    std::vector<float> top_y;          ///< highest geometry (m); -inf where none
    std::vector<std::uint32_t> top_id; ///< Entity::bits of that geometry; 0 where none
    /// Bumped whenever the texels are rewritten (a refresh or a restore), for
    /// the caches built on the map; it never goes back.
    std::uint64_t version = 0;
    bool built = false; ///< false until the first refresh
    /// The source versions the texels were rasterised from; while they differ
    /// from the world's the map is stale, and the end of the tick refreshes it.
    SourceVersions built_from;
    /// The wind direction (radians) the projection leans along, held with
    /// hysteresis; occlusion_no_lean when it does not lean. A change refreshes.
    float wind_angle = 0.0f;
    // Projection: (x, y, z) falls in the texel of (x + shear_x·y, z + shear_z·y),
    // the flake path of a tilted camera leaning downwind (0 when not tilted).
    float shear_x = 0.0f, shear_z = 0.0f;
};

class ByteWriter;
class ByteReader;
/// A built map's snapshot record: its projection, lean, texels and the
/// sources it was built from (not its version: a restore moves that on).
void save_state(ByteWriter& out, const OcclusionMap& m);
/// Reads a record of save_state into `m` (throws SimulationError naming what is wrong).
void load_state(ByteReader& in, OcclusionMap& m);

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

} // namespace snow
