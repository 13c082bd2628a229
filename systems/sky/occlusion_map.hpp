/// @file occlusion_map.hpp
/// @brief The occlusion ("sky") map of [SKY]: the highest geometry per texel
/// of an orthographic view from above, as the rasteriser writes it and the
/// occlusion system, the covers and the flakes read it.
#pragma once

#include "ecs/host_memory.hpp"
#include "systems/core/source_versions.hpp"

#include <cstdint>

namespace snow {

/// World resource: the map the occlusion system writes, and what others read.
/// Texel (i, j) covers x0 + i·texel .. +texel, z0 + j·texel .. +texel. Not a
/// pure function of the current sources (source_versions.hpp): saved,
/// restored and hashed.
struct OcclusionMap {
    float x0 = 0.0f, z0 = 0.0f, texel = 1.0f;
    std::uint32_t width = 0, height = 0;
    Vector<float> top_y;          ///< highest geometry (m); -inf where none
    Vector<std::uint32_t> top_id; ///< Entity::bits of that geometry; 0 where none
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
class StateHasher;
/// A built map where it is not a pure function of hashed state: its lean
/// (held with hysteresis) always, its texels while it is `stale`.
void hash_state(StateHasher& h, const OcclusionMap& m, bool stale);

} // namespace snow
