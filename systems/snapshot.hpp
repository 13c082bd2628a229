/// @file snapshot.hpp
/// @brief Saved simulation state for rewind (tests) and reset (the game).
#pragma once

#include "ecs/entity.hpp"
#include "systems/body.hpp"
#include "systems/flake_pool.hpp"
#include "systems/mass_ledger.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_surface.hpp"
#include "systems/wind.hpp"

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
    std::vector<std::pair<Entity, SnowSurface>> surfaces;
    std::vector<std::pair<Entity, Body>> bodies;
};

} // namespace snow
