/// @file mass_ledger.hpp
/// @brief Exact snow-mass bookkeeping in integer units (docs/design.md "Mass").
#pragma once

#include <cstdint>

namespace snow {

/// World resource: counters that only grow. Airborne and settled mass are
/// read from the flake pool and the surfaces, so they cannot drift.
struct MassLedger {
    std::uint64_t spawned = 0;
    std::uint64_t removed_bounds = 0;  ///< left the simulation box
    std::uint64_t removed_sphere = 0;  ///< eliminated by sphere colliders [WF §4]
    std::uint64_t removed_bare = 0;    ///< landed on geometry without a snow surface
    std::uint64_t removed_surface = 0; ///< on a surface or snowball the embedder removed
    [[nodiscard]] std::uint64_t removed() const {
        return removed_bounds + removed_sphere + removed_bare + removed_surface;
    }
};

/// The invariant `spawned == airborne + settled + carried + removed`, all in
/// units; `carried` is the snow snowballs picked up.
struct MassReport {
    std::uint64_t spawned = 0;
    std::uint64_t airborne = 0;
    std::uint64_t settled = 0;
    std::uint64_t carried = 0;
    std::uint64_t removed = 0;
    [[nodiscard]] bool balanced() const {
        return spawned == airborne + settled + carried + removed;
    }
};

} // namespace snow
