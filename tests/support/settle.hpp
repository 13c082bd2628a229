/// @file settle.hpp
/// @brief Test support: run redistribution alone until a surface has no
/// dirty cell left.
#pragma once

#include "systems/simulation.hpp"
#include "systems/systems.hpp"

namespace snow::test {

/// Calls redistribute_system until surface `e` is clean or `max_calls` calls
/// were made; returns the calls it took.
inline int settle_surface(Simulation& sim, Entity e, int max_calls) {
    int calls = 0;
    while (!sim.world().get<SnowSurface>(e).dirty_empty() && calls < max_calls) {
        redistribute_system(sim.world());
        ++calls;
    }
    return calls;
}

} // namespace snow::test
