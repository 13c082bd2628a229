/// @file snapshot.hpp
/// @brief Saved simulation state for rewind (tests) and reset (the game).
#pragma once

#include "ecs/entity.hpp"
#include "systems/body.hpp"
#include "systems/snow_cover.hpp"
#include "systems/flake_pool.hpp"
#include "systems/mass_ledger.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_surface.hpp"
#include "systems/wind.hpp"
#include "systems/wind_field.hpp"

#include <optional>
#include <utility>
#include <vector>

namespace snow {

/// Everything a tick can change. Geometry and settings are not included: a
/// snapshot restores onto the same scene it was taken from.
struct Snapshot {
    FlakePool flakes;
    SimClock clock;
    MassLedger ledger;
    std::optional<Wind> wind;
    std::optional<WindField> wind_field; ///< the whole field: state and what derives from it
    std::vector<std::pair<Entity, SnowSurface>> surfaces;
    std::vector<std::pair<Entity, Body>> bodies;
    /// What each cover's base was built from: without it a cover restored to
    /// a base from before a rebuild would never rebuild again.
    std::vector<std::pair<Entity, SnowCover>> covers;
};

} // namespace snow
