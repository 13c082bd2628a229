/// @file source_versions.hpp
/// @brief The one policy for derived data: which data is a source, which is
/// derived from it, and how the derived data learns that its sources changed.
///
/// Source data is what the embedder declares through the Simulation's
/// validated calls: solids (box, sphere and mesh colliders), surfaces (their
/// placement, bare tops and owners) and the occlusion camera. Each kind has
/// one counter in SourceVersions; the Simulation call that changes that data
/// bumps it, and nothing else does. Systems trust the sources: the calls
/// validated them, so no system re-checks a collider or a surface.
///
/// Counters only grow. restore() does not roll them back (a snapshot holds
/// what ticks change, not geometry or settings), so a cache built from other
/// sources can never match by accident.
///
/// Every cache stores the versions it was built from and rebuilds when one
/// differs; none is saved or hashed, as each is a pure function of its sources:
///   ColliderGrid (collider_grid.hpp)            solids, surfaces
///   collide's surface pointers and mesh tops    surfaces; solids, OcclusionMap::version
///   deposit's bins (deposit_bins.hpp)           surfaces (and, by value, each
///                                               surface's level_bound)
/// The occlusion map is derived too, but not a pure function of the current
/// sources: it is rasterised at the end of a tick in which they changed, and
/// it leans along the wind direction it last settled on (hysteresis). So it
/// is state: saved, restored and hashed with the sources it was built from.
/// It carries its own counter (OcclusionMap::version), bumped whenever its
/// texels are rewritten (a refresh or a restore), for the caches built on it.
///
/// Per-tick data is produced once, by the stage that owns it, and read by the
/// later stages: the start of each flake's path this tick (PathStarts,
/// flake_stages.hpp) is written by integrate and read by collide and deposit.
#pragma once

#include "ecs/world.hpp"

#include <cstdint>

namespace snow {

/// World resource: one counter per kind of source data (see above).
struct SourceVersions {
    std::uint64_t solids = 0;    ///< box, sphere and mesh colliders added, moved or removed
    std::uint64_t surfaces = 0;  ///< surfaces added or removed (placement, bare tops, owners)
    std::uint64_t occlusion = 0; ///< OcclusionCamera settings
    friend bool operator==(const SourceVersions&, const SourceVersions&) = default;
};

/// The world's source versions (all zero in a world without the resource).
[[nodiscard]] inline SourceVersions source_versions(const World& w) {
    const auto* v = w.try_resource<SourceVersions>();
    return v != nullptr ? *v : SourceVersions{};
}

} // namespace snow
