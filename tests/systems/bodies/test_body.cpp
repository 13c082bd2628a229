// Moving bodies: trails with raised rims, mass-exact; a snowball that grows
// by exactly what it takes; swept trenches at speed; flakes pushed aside;
// determinism and restore with bodies; bad input rejected.
#include "systems/api/simulation_internals.hpp"
#include "systems/api/validation.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/units.hpp"
#include "tests/support/even_snow.hpp"
#include "tests/support/share_work.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace snow {
namespace {

constexpr float cell = 0.05f;
/// 10 cm of snow on 5 cm cells: the units that stand 10 cm at the default
/// air temperature's fresh density (75 kg/m³ at −5 °C [HP98]).
const std::uint32_t depth_units = static_cast<std::uint32_t>(
    std::lround(0.1 * fresh_snow_density(SimConfig{}.air_temperature) * cell * cell / unit_kg));

SimConfig world_config(unsigned threads = 1) {
    SimConfig c;
    c.seed = 3;
    c.bounds = {{-3.0f, -1.0f, -3.0f}, {3.0f, 4.0f, 3.0f}};
    c.max_flakes = 20000;
    c.threads = threads;
    return c;
}

/// A 4 m ground surface with 10 cm of snow in every cell.
struct SnowyGround {
    Simulation sim;
    SurfaceId ground;
    explicit SnowyGround(unsigned threads = 1) : sim(world_config(threads)) {
        SurfaceDef d;
        d.x0 = d.z0 = -2.0f;
        d.size_x = d.size_z = 4.0f;
        d.cell = cell;
        d.spills = false;
        ground = sim.add_surface(d);
        test::snow_every_cell(sim, ground, depth_units);
    }
    const SnowSurface& s() const { return snow_surface(sim, ground); }
    std::uint32_t at(float x, float z) const {
        std::uint32_t ix = 0, iz = 0;
        EXPECT_TRUE(s().cell_at(x, z, ix, iz));
        return s().snow[s().index(ix, iz)];
    }
    void run(int ticks) {
        for (int t = 0; t < ticks; ++t) {
            sim.tick();
            ASSERT_TRUE(sim.mass().balanced()) << "tick " << t;
        }
    }
};

BodyDef ball(float x, float y, float r) {
    BodyDef d;
    d.position = {x, y, 0.0f};
    d.radius = r;
    return d;
}

TEST(Body, TrenchDepthMatchesTheSinkingAndRimsHoldTheSnow) {
    SnowyGround g;
    // Bottom 4 cm below the 10 cm snow top: a 4 cm deep trench.
    const float r = 0.25f;
    const BodyId b = g.sim.add_body(ball(-1.5f, 0.06f + r, r));
    g.sim.set_body_velocity(b, {1.0f, 0.0f, 0.0f});
    const std::uint64_t settled = g.s().settled_units();
    g.run(66); // 1.1 m: the body is 10 cm past x = -0.5
    EXPECT_EQ(g.s().settled_units(), settled) << "pushed, not lost";
    EXPECT_GT(g.sim.counters().carved_units, 0u);
    // Smoothing starts softening the trench walls at once; the floor is still
    // at the body's lowest point.
    const std::uint32_t trench = g.at(-0.5f, 0.0f);
    EXPECT_NEAR(static_cast<double>(trench) * g.s().unit_height, 0.06, 0.003);
    // Just outside the footprint the rim stands above the untouched snow.
    EXPECT_GT(g.at(-0.5f, r + 0.03f), depth_units);
    EXPECT_EQ(g.at(-0.5f, 1.2f), depth_units) << "far away nothing changed";
}

TEST(Body, AFastBodyLeavesAContinuousTrench) {
    SnowyGround g;
    BodyDef d = ball(-1.8f, 0.0f, 0.2f);
    d.on_ground = true; // rolls on the bare ground: the trench goes down to it
    const BodyId b = g.sim.add_body(d);
    g.sim.set_body_velocity(b, {60.0f, 0.0f, 0.0f}); // a metre per tick, 20 cells
    g.run(3);
    // Down to the ground all along (smoothing lets a little back in from the rims).
    for (float x = -1.6f; x < 1.2f; x += cell) {
        EXPECT_LT(g.at(x, 0.0f), depth_units / 20) << "x = " << x;
    }
}

TEST(Body, SnowfallFillsATrailAgain) {
    SnowyGround g;
    const BodyId b = g.sim.add_body(ball(-1.5f, 0.0f, 0.2f));
    g.sim.set_body_motion(b, BodyMotion{{{-1.5f, 0.2f, 0.0f}, {1.5f, 0.2f, 0.0f}}, 2.0f, false});
    g.run(120);
    const std::uint32_t carved = g.at(0.0f, 0.0f);
    EXPECT_LT(carved, depth_units / 4);
    Emitter e;
    e.rate = 4000.0f;
    e.snowfall_kg_m2_h = 200.0f; // a test-sized blizzard: 0.8 kg/m² in the 15 s
    g.sim.add_emitter(e);
    g.run(900);
    EXPECT_GT(g.at(0.0f, 0.0f), carved + 100) << "new snow lies in the trail";
}

TEST(Body, SnowballGrowsByExactlyWhatItTookAndDropsItBack) {
    SnowyGround g;
    BodyDef d = ball(-1.5f, 0.0f, 0.1f);
    d.on_ground = true;
    d.snowball = true;
    d.motion = BodyMotion{{{-1.5f, 0.0f, 0.0f}, {1.5f, 0.0f, 0.0f}}, 1.0f, false};
    const BodyId b = g.sim.add_body(d);
    const std::uint64_t settled = g.s().settled_units();
    g.run(180);
    const Body& body = body_of(g.sim, b);
    ASSERT_GT(body.carried, 0u);
    EXPECT_EQ(g.s().settled_units() + body.carried, settled);
    EXPECT_EQ(g.sim.mass().carried, body.carried);
    EXPECT_GT(body.radius, 0.1f);
    EXPECT_FLOAT_EQ(body.radius, snowball_radius(0.1f, body.carried));
    const std::uint64_t carried = body.carried;
    EXPECT_EQ(g.sim.drop_snowball(b), carried);
    EXPECT_EQ(body_of(g.sim, b).carried, 0u);
    EXPECT_EQ(g.s().settled_units(), settled);
    g.run(10);
}

TEST(Body, RemovingASnowballBooksItsSnowAsRemoved) {
    SnowyGround g;
    BodyDef d = ball(-1.5f, 0.0f, 0.1f);
    d.on_ground = true;
    d.snowball = true;
    d.motion = BodyMotion{{{-1.5f, 0.0f, 0.0f}, {1.5f, 0.0f, 0.0f}}, 1.0f, false};
    const BodyId b = g.sim.add_body(d);
    g.run(60);
    const std::uint64_t carried = body_of(g.sim, b).carried;
    ASSERT_GT(carried, 0u);
    const MassReport before = g.sim.mass();
    g.sim.remove(b);
    const MassReport after = g.sim.mass();
    EXPECT_TRUE(after.balanced());
    EXPECT_EQ(after.carried, 0u);
    EXPECT_EQ(after.removed, before.removed + carried);
}

TEST(Body, FlakesDoNotEndInsideAMovingBody) {
    SnowyGround g;
    Emitter e;
    e.rate = 8000.0f;
    g.sim.add_emitter(e);
    const BodyId b = g.sim.add_body(ball(-1.5f, 1.0f, 0.5f));
    g.sim.set_body_motion(b, BodyMotion{{{-1.5f, 1.0f, 0.0f}, {1.5f, 1.0f, 0.0f}}, 1.5f, true});
    for (int t = 0; t < 600; ++t) {
        g.sim.tick();
        ASSERT_TRUE(g.sim.mass().balanced());
        const Body& body = body_of(g.sim, b);
        const FlakePool& f = flake_pool(g.sim);
        std::uint32_t inside = 0;
        for (std::uint32_t i = 0; i < f.slot_end; ++i) {
            const float dx = f.px[i] - body.position.x, dy = f.py[i] - body.position.y,
                        dz = f.pz[i] - body.position.z;
            inside += f.is_alive(i) && dx * dx + dy * dy + dz * dz < 0.99f * 0.25f ? 1 : 0;
        }
        ASSERT_EQ(inside, 0u) << "tick " << t;
    }
}

TEST(Body, SameStateForOneAndTwoThreadsAndAfterRestore) {
    SnowyGround a(1), b(2);
    test::share_work_at_any_size(b.sim);
    for (SnowyGround* g : {&a, &b}) {
        Emitter e;
        e.rate = 3000.0f;
        g->sim.add_emitter(e);
        BodyDef d = ball(-1.5f, 0.0f, 0.15f);
        d.on_ground = true;
        d.snowball = true;
        d.motion =
            BodyMotion{{{-1.5f, 0.0f, -1.0f}, {1.5f, 0.0f, 1.0f}, {0.0f, 0.0f, 1.5f}}, 1.2f, true};
        g->sim.add_body(d);
        BodyDef walker;
        walker.shape = BodyShape::capsule;
        walker.radius = 0.2f;
        walker.half_height = 0.6f;
        walker.on_ground = true;
        walker.compaction = 0.5f; // it packs half of what it treads on
        walker.motion = BodyMotion{{{1.0f, 0.0f, -1.5f}, {-1.0f, 0.0f, 1.5f}}, 1.4f, true};
        g->sim.add_body(walker);
    }
    for (int t = 0; t < 300; ++t) {
        a.sim.tick();
        b.sim.tick();
        ASSERT_EQ(a.sim.state_hash(), b.sim.state_hash()) << "tick " << t;
    }
    ASSERT_FALSE(a.s().compacted.empty()) << "the walker packed no snow";
    const auto saved = save_snapshot(a.sim);
    const std::uint64_t saved_hash = a.sim.state_hash();
    a.sim.run(200);
    const std::uint64_t straight = a.sim.state_hash();
    const Vector<std::uint32_t> packed = a.s().compacted;
    restore_snapshot(a.sim, *saved);
    a.sim.run(200);
    EXPECT_EQ(a.sim.state_hash(), straight);
    EXPECT_EQ(a.s().compacted, packed);
    // The compaction is state: the same snow packed otherwise hashes otherwise.
    Snapshot changed = *saved;
    for (auto& [e, s] : changed.surfaces) {
        for (std::size_t i = 0; i < s.compacted.size(); ++i) {
            s.compacted[i] = s.compacted[i] > 0 ? s.compacted[i] - 1 : 0;
        }
    }
    restore_snapshot(a.sim, changed);
    EXPECT_NE(a.sim.state_hash(), saved_hash);
}

/// A walker-sized capsule standing on the ground, walking +x along z = 0
/// across 1.5 m of snow, packing `compaction` of what is in its way.
BodyDef trudger(float compaction) {
    BodyDef d;
    d.shape = BodyShape::capsule;
    d.radius = 0.2f;
    d.half_height = 0.6f;
    d.on_ground = true;
    d.compaction = compaction;
    d.motion = BodyMotion{{{-1.5f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}}, 1.5f, false};
    return d;
}

/// Mean snow depth (m) and units over the cells of a 0.2 m square at (x, z).
struct Patch {
    double depth = 0.0;
    std::uint64_t units = 0;
};
Patch patch(const SnowSurface& s, float x, float z) {
    Patch p;
    std::uint32_t n = 0;
    for (float dz = -0.075f; dz < 0.1f; dz += cell) {
        for (float dx = -0.075f; dx < 0.1f; dx += cell) {
            std::uint32_t ix = 0, iz = 0;
            EXPECT_TRUE(s.cell_at(x + dx, z + dz, ix, iz));
            p.depth += s.depth(s.index(ix, iz));
            p.units += s.snow[s.index(ix, iz)];
            ++n;
        }
    }
    p.depth /= n;
    return p;
}

TEST(Body, ACompactingBodyPacksTheSnowLowerWithTheSameUnits) {
    SnowyGround plain, packing;
    plain.sim.add_body(trudger(0.0f));
    packing.sim.add_body(trudger(0.75f));
    const std::uint64_t settled = packing.s().settled_units();
    plain.run(90);
    packing.run(90); // both at x = 0 now
    EXPECT_EQ(packing.s().settled_units(), settled) << "packed, not lost";
    EXPECT_EQ(packing.sim.mass().carried, 0u);
    EXPECT_FALSE(packing.s().compacted.empty());
    const Patch pushed = patch(plain.s(), -0.7f, 0.0f);
    const Patch packed = patch(packing.s(), -0.7f, 0.0f);
    // The plain trench goes down to the ground (smoothing lets a little back
    // from the rims); the packed one keeps 3/4 of its units at max_packing
    // times the density: 3/4 · 10 cm / 6 = 1.25 cm of snow (a little more
    // where smoothing let fresh snow back over it), lower than 3/4 of the
    // units would stand fresh (7.5 cm).
    EXPECT_LT(pushed.depth, 0.005);
    EXPECT_GT(packed.units, 3 * pushed.units);
    const double at_most_packed = 0.075 / max_packing;
    EXPECT_GT(packed.depth, at_most_packed - 0.001);
    EXPECT_LT(packed.depth, 1.5 * at_most_packed);
    EXPECT_LT(packed.depth, 0.5 * static_cast<double>(packed.units) / 16 * packing.s().unit_height);
    // The rims beside it got only the quarter it pushed aside, and what
    // stood steeper than the angle of repose over the trench slid back into
    // it: they stand near the untouched depth.
    const std::uint32_t rim_plain = plain.at(-0.7f, 0.225f), rim_packed = packing.at(-0.7f, 0.225f);
    EXPECT_GT(rim_plain, rim_packed);
    EXPECT_NEAR(rim_packed, depth_units, depth_units / 4);
    // Fresh snow on the packed trail stands on the packed layer: every new
    // unit a level higher, the compaction kept, the mean density relaxing
    // towards fresh.
    std::uint32_t ix = 0, iz = 0;
    ASSERT_TRUE(packing.s().cell_at(-0.7f, 0.0f, ix, iz));
    const std::size_t c = packing.s().index(ix, iz);
    const std::uint32_t squeezed = packing.s().compacted[c];
    const std::uint32_t units = packing.s().snow[c];
    const std::int64_t levels = packing.s().depth_levels(c);
    EXPECT_GT(squeezed, 0u);
    packing.sim.add_settled_snow(packing.ground, ix, iz, 4000);
    EXPECT_EQ(packing.s().compacted[c], squeezed);
    EXPECT_EQ(packing.s().depth_levels(c), levels + 4000);
    EXPECT_LT(static_cast<double>(packing.s().snow[c]) / packing.s().depth_levels(c),
              static_cast<double>(units) / levels);
}

TEST(Body, ABodyUnderASnowyRoofLeavesTheRoofsSnowAlone) {
    SnowyGround g;
    SurfaceDef d; // a porch roof 2.2 m up over the middle of the ground
    d.x0 = -1.0f;
    d.z0 = -1.0f;
    d.size_x = d.size_z = 2.0f;
    d.cell = cell;
    d.base_y = 2.2f;
    d.spills = false;
    const SurfaceId roof = g.sim.add_surface(d);
    test::snow_every_cell(g.sim, roof, depth_units);
    const Vector<std::uint32_t> roof_snow = snow_surface(g.sim, roof).snow;
    // A 1.7 m walker under it, and a 0.5 m ball whose top is 5 cm under the
    // roof's bare top; both cut the ground's snow, neither the roof's.
    BodyDef walker = trudger(0.0f);
    walker.motion = BodyMotion{{{-1.5f, 0.0f, 0.0f}, {1.5f, 0.0f, 0.0f}}, 1.5f, false};
    g.sim.add_body(walker);
    const BodyId b = g.sim.add_body(ball(-1.5f, 1.9f, 0.25f));
    g.sim.set_body_velocity(b, {1.5f, 0.0f, 0.5f});
    g.run(120);
    EXPECT_EQ(body_of(g.sim, b).position.y, 1.9f);
    EXPECT_GT(g.sim.counters().carved_units, 0u);
    EXPECT_LT(g.at(0.0f, 0.0f), depth_units / 4) << "the walker's trench under the roof";
    EXPECT_EQ(snow_surface(g.sim, roof).snow, roof_snow);
    // The same ball 10 cm higher reaches into the roof's snow and cuts it.
    g.sim.move_body(b, {-0.5f, 2.25f, 0.5f});
    g.sim.set_body_velocity(b, {0.0f, 0.0f, 0.0f});
    g.run(2);
    EXPECT_NE(snow_surface(g.sim, roof).snow, roof_snow);
}

TEST(Body, BadBodiesAndMotionsNameTheFieldAndChangeNothing) {
    SnowyGround g;
    const std::uint64_t before = g.sim.state_hash();
    const auto error_of = [&](auto&& fn) {
        try {
            fn();
        } catch (const SimulationError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(error_of([&] { g.sim.add_body(ball(0.0f, 0.0f, 0.0f)); }).find("body.radius"),
              std::string::npos);
    EXPECT_NE(error_of([&] { g.sim.add_body(ball(0.0f, 0.0f, 1.0e6f)); }).find("body.radius"),
              std::string::npos);
    for (const float bad : {NAN, -0.1f, 1.5f}) {
        BodyDef d = ball(0.0f, 1.0f, 0.2f);
        d.compaction = bad;
        EXPECT_EQ(validate(d).field, "body.compaction") << bad;
        EXPECT_NE(error_of([&] { g.sim.add_body(d); }).find("body.compaction"), std::string::npos)
            << bad;
    }
    EXPECT_EQ(g.sim.state_hash(), before);
    const BodyId b = g.sim.add_body(ball(0.0f, 1.0f, 0.2f));
    const std::uint64_t with_body = g.sim.state_hash();
    EXPECT_NE(error_of([&] {
                  g.sim.set_body_motion(b, BodyMotion{{}, 1.0f, true});
              }).find("motion.waypoints"),
              std::string::npos);
    EXPECT_NE(error_of([&] {
                  g.sim.set_body_motion(b, BodyMotion{{{0.0f, NAN, 0.0f}}, 1.0f, true});
              }).find("motion.waypoints[0]"),
              std::string::npos);
    EXPECT_NE(error_of([&] {
                  g.sim.set_body_motion(b, BodyMotion{{{0.0f, 0.0f, 0.0f}}, -1.0f, true});
              }).find("motion.speed"),
              std::string::npos);
    EXPECT_NE(error_of([&] {
                  g.sim.move_body(b, {NAN, 0.0f, 0.0f});
              }).find("move_body.position"),
              std::string::npos);
    EXPECT_NE(error_of([&] {
                  g.sim.move_body(id_of<BodyId>(entity_of(g.ground)), {0.0f, 0.0f, 0.0f});
              }).find("not a living body"),
              std::string::npos);
    EXPECT_EQ(g.sim.state_hash(), with_body);
    EXPECT_NE(before, with_body);
}

} // namespace
} // namespace snow
