/// @file internal_access.hpp
/// @brief For tests and benchmarks of single systems only (never installed):
/// the Simulation's World, writable, so one system can run on it alone or a
/// state no facade call makes can be arranged. Code that drives a running
/// simulation uses the facade's validated calls instead.
#pragma once

#include "systems/api/simulation.hpp"
#include "systems/api/systems.hpp"

namespace snow {

struct InternalAccess {
    [[nodiscard]] static World& world(Simulation& sim) { return sim.world_; }
};

} // namespace snow
