/// @file snapshot.hpp
/// @brief Saved simulation state for rewind (tests) and reset (the game).
#pragma once

#include "ecs/entity.hpp"
#include "ecs/host_memory.hpp"
#include "systems/bodies/body.hpp"
#include "systems/core/mass_ledger.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/sky/occlusion.hpp"
#include "systems/snowpack/snow_cover.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/wind.hpp"
#include "systems/wind/wind_field.hpp"
#include <snow/views.hpp>

#include <optional>
#include <utility>

namespace snow {

/// Everything a tick can change. Geometry and settings are not included: a
/// snapshot restores onto the same scene it was taken from. Caches are not
/// included either: they rebuild from their sources (source_versions.hpp).
/// save_snapshot() makes one with new: in the host's memory, like its arrays.
struct Snapshot : HostAllocated {
    FlakePool flakes;
    SimClock clock;
    MassLedger ledger;
    SimCounters counters;
    std::optional<Wind> wind;            ///< its walk, gust and settings
    std::optional<WindField> wind_field; ///< the whole field: state and what derives from it
    std::optional<OcclusionMap> sky_map; ///< absent while no map was ever built
    /// Snow, compaction and pending smoothing of every surface, by entity.
    Vector<std::pair<Entity, SnowSurface>> surfaces;
    /// What each cover's base was built from and its drop cells, by entity.
    Vector<std::pair<Entity, SnowCover>> covers;
    /// Pose, path progress and carried snow of every body, by entity.
    Vector<std::pair<Entity, Body>> bodies;
};

} // namespace snow
