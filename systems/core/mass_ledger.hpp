/// @file mass_ledger.hpp
/// @brief Exact snow-mass bookkeeping in integer units (docs/design.md "Mass");
/// Simulation::mass() reports it as a MassReport (<snow/views.hpp>).
#pragma once

#include <cstdint>

#include <snow/views.hpp>

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

/// The ledger's and the counters' record: the state hash and the snapshot
/// read and write these fields, in this order (Io: ByteWriter or ByteReader).
template <typename Io, typename Ledger, typename Counters>
void ledger_record(Io& io, Ledger& l, Counters& c) {
    for (auto* v :
         {&l.spawned, &l.removed_bounds, &l.removed_sphere, &l.removed_bare, &l.removed_surface}) {
        io(*v);
    }
    for (auto* v : {&c.stiff_flake_ticks, &c.landed, &c.rolled, &c.smoothing_iterations,
                    &c.spilled_units, &c.occlusion_refreshes, &c.carved_units}) {
        io(*v);
    }
}

} // namespace snow
