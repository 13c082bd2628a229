/// @file snapshot_check.hpp
/// @brief Test support: a restored simulation continues bit for bit as the
/// run it was saved from (the state hash on every tick, the full flake
/// arrays, every surface's snow and base, every cover's drop cells and every
/// body at the end).
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace snow::test {

/// Everything a run leaves behind that a test can compare exactly.
struct RunEnd {
    FlakePool flakes;
    std::vector<Vector<std::uint32_t>> snow;       ///< per surface, pool order
    std::vector<Vector<std::uint32_t>> packed;     ///< per surface: its compaction (density)
    std::vector<Vector<std::int64_t>> base;        ///< per surface, pool order
    std::vector<Vector<std::uint32_t>> edge_cells; ///< per cover, pool order
    std::vector<Body> bodies;                      ///< pool order
    MassLedger ledger;
    SimCounters counters;
};

inline RunEnd run_end(const Simulation& sim) {
    RunEnd r{flake_pool(sim), {}, {}, {}, {}, {}, world_of(sim).resource<MassLedger>(),
             sim.counters()};
    world_of(sim).each<SnowSurface>([&](Entity, const SnowSurface& s) {
        r.snow.push_back(s.snow);
        r.packed.push_back(s.compacted);
        r.base.push_back(s.base_level);
    });
    world_of(sim).each<SnowCover>(
        [&](Entity, const SnowCover& c) { r.edge_cells.push_back(c.edge_cells); });
    world_of(sim).each<Body>([&](Entity, const Body& b) { r.bodies.push_back(b); });
    return r;
}

/// Pose, path progress and carried snow agree bit for bit.
inline bool same_body(const Body& a, const Body& b) {
    return a.position == b.position && a.previous == b.previous && a.radius == b.radius &&
           a.segment == b.segment && a.along == b.along && a.carried == b.carried;
}

/// The live parts of two runs' ends agree bit for bit.
inline ::testing::AssertionResult same_end(const RunEnd& a, const RunEnd& b) {
    const FlakePool& f = a.flakes;
    const FlakePool& g = b.flakes;
    const auto same_arrays = f.px == g.px && f.py == g.py && f.pz == g.pz && f.vx == g.vx &&
                             f.vy == g.vy && f.vz == g.vz && f.k_over_m == g.k_over_m &&
                             f.size == g.size && f.mass_units == g.mass_units &&
                             f.free_stack == g.free_stack;
    if (!same_arrays || f.alive != g.alive || f.max_alive != g.max_alive ||
        f.slot_end != g.slot_end) {
        return ::testing::AssertionFailure() << "flake pools differ";
    }
    if (a.snow != b.snow || a.packed != b.packed) {
        return ::testing::AssertionFailure() << "surface snow or its density differs";
    }
    if (a.base != b.base || a.edge_cells != b.edge_cells) {
        return ::testing::AssertionFailure() << "cover bases differ";
    }
    if (!std::equal(a.bodies.begin(), a.bodies.end(), b.bodies.begin(), b.bodies.end(),
                    same_body)) {
        return ::testing::AssertionFailure() << "bodies differ";
    }
    const MassLedger &l = a.ledger, &m = b.ledger;
    if (l.spawned != m.spawned || l.removed() != m.removed()) {
        return ::testing::AssertionFailure() << "ledgers differ";
    }
    const SimCounters &c = a.counters, &d = b.counters;
    if (c.landed != d.landed || c.rolled != d.rolled || c.spilled_units != d.spilled_units ||
        c.occlusion_refreshes != d.occlusion_refreshes ||
        c.smoothing_iterations != d.smoothing_iterations ||
        c.stiff_flake_ticks != d.stiff_flake_ticks || c.carved_units != d.carved_units) {
        return ::testing::AssertionFailure() << "counters differ";
    }
    return ::testing::AssertionSuccess();
}

/// The state hash after each of `ticks` further ticks of `sim`.
inline std::vector<std::uint64_t> hashes_per_tick(Simulation& sim, std::uint64_t ticks) {
    std::vector<std::uint64_t> out;
    out.reserve(ticks);
    for (std::uint64_t t = 0; t < ticks; ++t) {
        sim.tick();
        out.push_back(sim.state_hash());
    }
    return out;
}

/// `sim` runs `warm` ticks and saves; runs `ahead` ticks as the reference;
/// is restored and runs them again: the hash must match on every tick and
/// the flakes and snow at the end. Returns the snapshot for further use.
inline std::unique_ptr<Snapshot> expect_restore_replays(Simulation& sim, std::uint64_t warm,
                                                        std::uint64_t ahead) {
    sim.run(warm);
    auto snap = save_snapshot(sim);
    const std::uint64_t saved = sim.state_hash();
    const std::vector<std::uint64_t> reference = hashes_per_tick(sim, ahead);
    const RunEnd reference_end = run_end(sim);
    restore_snapshot(sim, *snap);
    EXPECT_EQ(sim.state_hash(), saved) << "restore did not bring back the saved state";
    for (std::uint64_t t = 0; t < ahead; ++t) {
        sim.tick();
        const std::uint64_t h = sim.state_hash();
        if (h != reference[t]) {
            ADD_FAILURE() << "restored run differs " << t + 1 << " ticks after the restore";
            return snap;
        }
    }
    EXPECT_TRUE(same_end(run_end(sim), reference_end));
    return snap;
}

} // namespace snow::test
