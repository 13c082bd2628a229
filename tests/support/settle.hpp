/// @file settle.hpp
/// @brief Test support: run redistribution alone until a surface has no
/// dirty cell left.
#pragma once

#include "systems/api/internal_access.hpp"

namespace snow::test {

/// Calls redistribute_system until surface `e` is clean or `max_calls` calls
/// were made; returns the calls it took.
inline int settle_surface(Simulation& sim, Entity e, int max_calls) {
    int calls = 0;
    while (!sim.surface(e).dirty_empty() && calls < max_calls) {
        redistribute_system(InternalAccess::world(sim));
        ++calls;
    }
    return calls;
}

} // namespace snow::test
