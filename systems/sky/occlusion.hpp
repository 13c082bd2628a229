/// @file occlusion.hpp
/// @brief The occlusion ("sky") camera of [SKY]: an orthographic depth map
/// from above, rasterised on the CPU from the scene's meshes.
#pragma once

#include "ecs/entity.hpp"
#include "ecs/host_memory.hpp"
#include "ecs/world.hpp"
#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"
#include "systems/core/source_versions.hpp"
#include "systems/sky/occlusion_map.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>

#include <snow/defs.hpp>

namespace snow {

/// OcclusionMap::wind_angle when the projection does not lean (no tilt, no wind, calm).
inline constexpr float occlusion_no_lean = -1.0f;
/// Number of wind directions the tilted projection distinguishes (refresh granularity).
inline constexpr std::uint32_t occlusion_wind_steps = 64;
/// Default height tolerance (m) of occlusion_exposure: absorbs texel sampling of slopes.
inline constexpr float occlusion_tolerance = 0.05f;

struct SnowSurface;

/// The texels of a camera's map over the simulation bounds: `resolution`
/// along the longer side, square.
struct OcclusionGrid {
    float texel = 1.0f;
    std::uint32_t width = 1, height = 1;
};
[[nodiscard]] OcclusionGrid occlusion_grid(const World& w, const OcclusionCamera& cam);

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
void surface_exposure(const OcclusionMap& map, const SnowSurface& s, Vector<float>& out,
                      float tolerance = occlusion_tolerance);

/// `occlusion.*`: the sky-map camera [SKY].
inline constexpr FieldRule<OcclusionCamera> occlusion_fields[] = {
    {"resolution", &OcclusionCamera::resolution, between(1, max_occlusion_resolution)},
    {"tilt", &OcclusionCamera::tilt, between(-max_occlusion_tilt, max_occlusion_tilt)},
};

[[nodiscard]] Invalid validate(const OcclusionCamera& cam);

} // namespace snow
