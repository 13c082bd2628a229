/// @file settle.hpp
/// @brief Test support: run redistribution alone until a surface has no
/// dirty cell left.
#pragma once

#include "systems/api/simulation_internals.hpp"

namespace snow::test {

/// Calls redistribute_system until surface `e` is clean or `max_calls` calls
/// were made; returns the calls it took.
inline int settle_surface(Simulation& sim, SurfaceId e, int max_calls) {
    int calls = 0;
    while (!snow_surface(sim, e).dirty_empty() && calls < max_calls) {
        redistribute_system(InternalAccess::world(sim));
        ++calls;
    }
    return calls;
}

} // namespace snow::test
