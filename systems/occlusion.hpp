/// @file occlusion.hpp
/// @brief The occlusion ("sky") camera of seed 004: an orthographic depth map
/// from above, rasterised on the CPU from the scene's meshes.
#pragma once

#include "ecs/entity.hpp"

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
};

/// World resource: bump `version` whenever colliders or surfaces are added,
/// removed or moved, so the occlusion map refreshes.
struct GeometryVersion {
    std::uint64_t version = 0;
};

} // namespace snow
