// Exact snapshots: save() and restore() carry everything a tick changes, so a
// restored run continues bit for bit as the saved one did (on the same
// simulation, on a twin that never ran, and on 1 or 2 threads), and
// state_hash() changes with every kind of state, so neither can silently
// miss one. The scenes of assets/scenes are checked in tests/game.
#include "systems/api/simulation_internals.hpp"
#include "systems/api/systems.hpp"
#include "systems/geometry/colliders.hpp"
#include "tests/hard_cases/hard_case_util.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/share_work.hpp"
#include "tests/support/snapshot_check.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace snow {
namespace {

constexpr std::uint64_t ahead_ticks = hard::scaled<std::uint64_t>(900, 120);

FlakePool& pool(Simulation& s) {
    return InternalAccess::world(s).resource<FlakePool>();
}
/// An alive slot of the pool.
std::uint32_t alive_slot(const Simulation& s) {
    const FlakePool& f = flake_pool(s);
    std::uint32_t i = 0;
    while (!f.is_alive(i)) {
        ++i;
    }
    return i;
}
SnowSurface& ground(Simulation& s) {
    return InternalAccess::world(s).pool<SnowSurface>().components().front();
}
SnowSurface& cover(Simulation& s) {
    return InternalAccess::world(s).get<SnowSurface>(
        InternalAccess::world(s).pool<SnowCover>().entities().front());
}
SnowCover& cover_of(Simulation& s) {
    return InternalAccess::world(s).pool<SnowCover>().components().front();
}
Body& ball(Simulation& s) {
    return InternalAccess::world(s).pool<Body>().components().front();
}
/// A cell of the cover with geometry under it.
std::size_t solid_cover_cell(Simulation& s) {
    const SnowSurface& c = cover(s);
    std::size_t i = 0;
    while (c.is_void(i)) {
        ++i;
    }
    return i;
}
OcclusionMap& sky_map(Simulation& s) {
    return InternalAccess::world(s).resource<OcclusionMap>();
}

TEST(Snapshot, RestoredStormContinuesBitForBit) {
    auto sim = make_stormy_yard(1);
    test::expect_restore_replays(*sim, 300, ahead_ticks);
    // The storm exercised what the snapshot must carry.
    const SimCounters& c = sim->counters();
    EXPECT_GT(c.occlusion_refreshes, 3u) << "the sky map never followed the wind";
    EXPECT_GT(c.spilled_units, 0u);
    EXPECT_GT(c.rolled, 0u);
    EXPECT_GT(world_of(*sim).resource<MassLedger>().removed_bare, 0u)
        << "no flake met the bare mesh";
    EXPECT_GT(c.carved_units, 0u) << "the snowball never rolled through snow";
    EXPECT_GT(sim->mass().carried, 0u) << "the snowball carries nothing";
    EXPECT_GT(cover(*sim).settled_units(), 0u) << "no snow on the cover";
    EXPECT_TRUE(sim->mass().balanced());
}

TEST(Snapshot, RestoreIntoATwinOnOneOrTwoThreadsContinuesBitForBit) {
    auto source = make_stormy_yard(1);
    source->run(300);
    const auto snap = save_snapshot(*source);
    const std::vector<std::uint64_t> reference = test::hashes_per_tick(*source, ahead_ticks);
    const test::RunEnd reference_end = test::run_end(*source);
    for (const unsigned threads : {1u, 2u}) {
        // A twin that never ticked: every cache is built for the first time
        // after the restore.
        auto twin = make_stormy_yard(threads);
        test::share_work_at_any_size(*twin);
        restore_snapshot(*twin, *snap);
        for (std::uint64_t t = 0; t < ahead_ticks; ++t) {
            twin->tick();
            ASSERT_EQ(twin->state_hash(), reference[t])
                << threads << " thread(s), tick " << t + 1 << " after the restore";
        }
        EXPECT_TRUE(test::same_end(test::run_end(*twin), reference_end)) << threads;
    }
}

TEST(Snapshot, RestoreBeforeTheFirstTickAndBeforeTheFirstMap) {
    // Saved before any sky map exists: the restore must take the map away
    // again (its texels would otherwise meet flakes a tick early).
    auto sim = make_stormy_yard(1);
    test::expect_restore_replays(*sim, 0, 60);
}

TEST(Snapshot, RestoreRightAfterAGeometryChange) {
    // Saved while the map and the cover are stale (a box and a sphere were
    // added after the last tick): the next tick rebuilds the cover's base
    // (shedding its snow there) and refreshes the saved, stale map.
    auto sim = make_stormy_yard(1);
    sim->run(50);
    sim->add_box({{4.0f, 0.0f, 3.0f}, {6.0f, 2.0f, 5.0f}});
    const ColliderId under_cover = sim->add_sphere({6.0f, 0.5f, 6.0f}, 0.5f);
    const Vector<std::int64_t> base = cover(*sim).base_level;
    test::expect_restore_replays(*sim, 0, 60);
    EXPECT_NE(cover(*sim).base_level, base) << "the cover never followed the new sphere";
    // And restored after the geometry changed back: the cover follows it again.
    sim->run(20);
    const auto snap = save_snapshot(*sim);
    sim->remove(under_cover);
    sim->run(20);
    const std::uint64_t without = sim->state_hash();
    restore_snapshot(*sim, *snap);
    EXPECT_NE(sim->state_hash(), without);
    sim->run(20);
    EXPECT_EQ(sim->state_hash(), without) << "a restored cover must follow the current geometry";
}

TEST(Snapshot, RejectsASnapshotOfAnotherScene) {
    {
        auto sim = make_stormy_yard(1);
        auto more = make_stormy_yard(1);
        more->add_body(BodyDef{});
        EXPECT_THROW(restore_snapshot(*sim, *save_snapshot(*more)), SimulationError)
            << "a body too many";
    }
    auto sim = make_stormy_yard(1);
    sim->run(5);
    const std::uint64_t before = sim->state_hash();
    YardOptions small;
    small.max_flakes = 100;
    auto other = make_yard(small);
    EXPECT_THROW(restore_snapshot(*sim, *save_snapshot(*other)), SimulationError);
    YardOptions same_pool;
    same_pool.max_flakes = 60000;
    auto fewer_surfaces = make_yard(same_pool);
    EXPECT_THROW(restore_snapshot(*sim, *save_snapshot(*fewer_surfaces)), SimulationError);
    EXPECT_EQ(sim->state_hash(), before);
}

// -- state_hash covers every kind of state --

/// One kind of state and a change to it.
struct Change {
    std::string what;
    std::function<void(Simulation&)> apply;
    bool tick_state; ///< a tick changes it, so a restore must undo it
};

std::vector<Change> changes() {
    std::vector<Change> c;
    const auto slot_change = [&c](const std::string& name, PoolArray<float> FlakePool::*array) {
        c.push_back({"flake " + name,
                     [array](Simulation& s) { (pool(s).*array)[alive_slot(s)] += 0.25f; }, true});
    };
    slot_change("px", &FlakePool::px);
    slot_change("py", &FlakePool::py);
    slot_change("pz", &FlakePool::pz);
    slot_change("vx", &FlakePool::vx);
    slot_change("vy", &FlakePool::vy);
    slot_change("vz", &FlakePool::vz);
    slot_change("k_over_m", &FlakePool::k_over_m);
    slot_change("size", &FlakePool::size);
    c.push_back({"flake mass", [](Simulation& s) { ++pool(s).mass_units[alive_slot(s)]; }, true});
    c.push_back({"free stack order",
                 [](Simulation& s) {
                     auto& st = pool(s).free_stack;
                     std::swap(st[st.size() - 1], st[st.size() - 2]);
                 },
                 true});
    c.push_back({"alive count", [](Simulation& s) { ++pool(s).alive; }, true});
    c.push_back({"high-water mark", [](Simulation& s) { ++pool(s).max_alive; }, true});
    c.push_back({"slot_end", [](Simulation& s) { ++pool(s).slot_end; }, true});
    c.push_back({"clock",
                 [](Simulation& s) { ++InternalAccess::world(s).resource<SimClock>().tick; },
                 true});
    const auto ledger_change = [&c](const std::string& name, std::uint64_t MassLedger::*field) {
        c.push_back(
            {"ledger " + name,
             [field](Simulation& s) { ++(InternalAccess::world(s).resource<MassLedger>().*field); },
             true});
    };
    ledger_change("spawned", &MassLedger::spawned);
    ledger_change("removed_bounds", &MassLedger::removed_bounds);
    ledger_change("removed_sphere", &MassLedger::removed_sphere);
    ledger_change("removed_bare", &MassLedger::removed_bare);
    ledger_change("removed_surface", &MassLedger::removed_surface);
    const auto counter_change = [&c](const std::string& name, std::uint64_t SimCounters::*field) {
        c.push_back({"counter " + name,
                     [field](Simulation& s) {
                         ++(InternalAccess::world(s).resource<SimCounters>().*field);
                     },
                     true});
    };
    counter_change("stiff_flake_ticks", &SimCounters::stiff_flake_ticks);
    counter_change("landed", &SimCounters::landed);
    counter_change("rolled", &SimCounters::rolled);
    counter_change("smoothing_iterations", &SimCounters::smoothing_iterations);
    counter_change("spilled_units", &SimCounters::spilled_units);
    counter_change("occlusion_refreshes", &SimCounters::occlusion_refreshes);
    counter_change("carved_units", &SimCounters::carved_units);
    c.push_back({"wind current",
                 [](Simulation& s) { InternalAccess::world(s).resource<Wind>().current.x += 0.5f; },
                 true});
    c.push_back(
        {"wind walk offset",
         [](Simulation& s) { InternalAccess::world(s).resource<Wind>().deviation.z += 0.5f; },
         true});
    c.push_back({"gust left",
                 [](Simulation& s) { InternalAccess::world(s).resource<Wind>().gust_left += 0.5f; },
                 true});
    c.push_back({"wind settings",
                 [](Simulation& s) {
                     Wind w = InternalAccess::world(s).resource<Wind>();
                     w.gust_rate += 1.0f;
                     s.set_wind(w);
                 },
                 true});
    c.push_back({"no wind", [](Simulation& s) { s.clear_wind(); }, true});
    c.push_back({"snow in a cell", [](Simulation& s) { ++ground(s).snow[5]; }, true});
    c.push_back(
        {"cells waiting for smoothing", [](Simulation& s) { ground(s).mark_dirty(1, 1); }, true});
    c.push_back({"level bound", [](Simulation& s) { ++ground(s).level_bound; }, true});
    c.push_back(
        {"snow on the cover", [](Simulation& s) { ++cover(s).snow[solid_cover_cell(s)]; }, true});
    c.push_back(
        {"cover base", [](Simulation& s) { ++cover(s).base_level[solid_cover_cell(s)]; }, true});
    c.push_back({"cover gone stale", [](Simulation& s) { cover_of(s).built = false; }, true});
    const auto body_change = [&c](const std::string& name, const std::function<void(Body&)>& fn) {
        c.push_back({"body " + name, [fn](Simulation& s) { fn(ball(s)); }, true});
    };
    body_change("position", [](Body& b) { b.position.x += 0.25f; });
    body_change("previous", [](Body& b) { b.previous.z += 0.25f; });
    body_change("radius", [](Body& b) { b.radius += 0.25f; });
    body_change("path segment", [](Body& b) { b.segment = (b.segment + 1) % 4; });
    body_change("path progress", [](Body& b) { b.along += 0.25f; });
    body_change("carried snow", [](Body& b) { ++b.carried; });
    body_change("target", [](Body& b) {
        b.has_target = true;
        b.target = b.position;
    });
    c.push_back({"body velocity",
                 [](Simulation& s) {
                     s.set_body_velocity(
                         id_of<BodyId>(InternalAccess::world(s).pool<Body>().entities().front()),
                         {1, 0, 0});
                 },
                 true});
    c.push_back({"body path",
                 [](Simulation& s) {
                     BodyMotion m;
                     m.waypoints = {{0, 0, -6}, {2, 0, -6}};
                     s.set_body_motion(
                         id_of<BodyId>(InternalAccess::world(s).pool<Body>().entities().front()),
                         m);
                 },
                 true});
    c.push_back({"sky map lean", [](Simulation& s) { sky_map(s).wind_angle += 0.1f; }, true});
    c.push_back({"sky map never built", [](Simulation& s) { sky_map(s) = OcclusionMap{}; }, true});
    c.push_back(
        {"sky map gone stale", [](Simulation& s) { --sky_map(s).built_from.solids; }, true});
    c.push_back({"integrator", [](Simulation& s) { s.set_integrator(Integrator::rk4); }, false});
    c.push_back({"emitter settings",
                 [](Simulation& s) {
                     InternalAccess::world(s).pool<Emitter>().components().front().rate += 1.0f;
                 },
                 false});
    c.push_back({"another emitter", [](Simulation& s) { s.add_emitter(Emitter{}); }, false});
    c.push_back({"occlusion camera",
                 [](Simulation& s) {
                     s.set_occlusion(OcclusionCamera{97, 0.5f});
                 },
                 false});
    c.push_back({"a box", [](Simulation& s) { s.add_box({{5, 0, 5}, {6, 1, 6}}); }, false});
    c.push_back({"a sphere", [](Simulation& s) { s.add_sphere({5, 1, -5}, 0.5f); }, false});
    c.push_back({"a mesh",
                 [](Simulation& s) {
                     s.add_mesh_collider({{0, 3, 0}, {1, 3, 0}, {0, 3, 1}});
                 },
                 false});
    c.push_back({"a surface", [](Simulation& s) { s.add_surface(SurfaceDef{}); }, false});
    c.push_back({"a cover", [](Simulation& s) { s.add_cover(CoverDef{}); }, false});
    c.push_back({"a body", [](Simulation& s) { s.add_body(BodyDef{}); }, false});
    c.push_back({"removing a solid",
                 [](Simulation& s) {
                     s.remove(id_of<ColliderId>(
                         InternalAccess::world(s).pool<SphereCollider>().entities().front()));
                 },
                 false});
    return c;
}

TEST(Snapshot, StateHashSeesEveryKindOfStateAndRestoreUndoesTickState) {
    int checked = 0;
    // Tick-state changes share one run, put back by restore() after each (the
    // test checks that); a source change needs a fresh run, as restore()
    // leaves sources alone.
    auto shared = make_stormy_yard(1);
    shared->run(40);
    const auto start = save_snapshot(*shared);
    for (const Change& change : changes()) {
        SCOPED_TRACE(change.what);
        std::unique_ptr<Simulation> fresh;
        if (!change.tick_state) {
            fresh = make_stormy_yard(1);
            fresh->run(40);
        } else {
            restore_snapshot(*shared, *start);
        }
        Simulation* sim = change.tick_state ? shared.get() : fresh.get();
        const std::uint64_t before = sim->state_hash();
        const auto snap = save_snapshot(*sim);
        change.apply(*sim);
        EXPECT_NE(sim->state_hash(), before) << "state_hash misses " << change.what;
        if (change.tick_state) {
            restore_snapshot(*sim, *snap);
            EXPECT_EQ(sim->state_hash(), before) << "restore misses " << change.what;
        }
        ++checked;
    }
    EXPECT_GE(checked, 59);
}

TEST(Snapshot, StateHashSeesStaleSkyMapTexelsAndCoverColumnsAndTheOrderOfDirtyTiles) {
    auto sim = make_stormy_yard(1);
    sim->run(40);
    // A stale map (what it is after a source change until the end of the
    // next tick) is no function of the current sources: its texels count.
    --sky_map(*sim).built_from.solids;
    const std::uint64_t stale = sim->state_hash();
    sky_map(*sim).top_y[7] += 1.0f;
    EXPECT_NE(sim->state_hash(), stale);
    // So is a stale cover's record of the columns it was built from.
    cover_of(*sim).built = false;
    const std::uint64_t stale_cover = sim->state_hash();
    cover_of(*sim).column_top[solid_cover_cell(*sim)] += 1.0f;
    EXPECT_NE(sim->state_hash(), stale_cover);
    // The same dirty cells, marked in another order.
    SnowSurface& g = ground(*sim);
    g.clear_dirty();
    g.mark_dirty(40, 40);
    g.mark_dirty(1, 1);
    const std::uint64_t one_order = sim->state_hash();
    g.clear_dirty();
    g.mark_dirty(1, 1);
    g.mark_dirty(40, 40);
    EXPECT_NE(sim->state_hash(), one_order);
}

TEST(Snapshot, StateHashIgnoresTheThreadCount) {
    auto one = make_stormy_yard(1);
    auto two = make_stormy_yard(2);
    EXPECT_EQ(one->state_hash(), two->state_hash());
}

} // namespace
} // namespace snow
