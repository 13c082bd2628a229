// collide_system against bounds, spheres, boxes and mesh tops ([WF §4], [SKY]).
#include "ecs/rng.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/flakes/flake_stages.hpp"
#include "systems/geometry/collider_grid.hpp"
#include "tests/support/rect_surface.hpp"
#include "tests/support/share_work.hpp"

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {
namespace {

constexpr float dt = 1.0f / 60.0f;

SimConfig config(std::uint32_t capacity, unsigned threads = 1) {
    SimConfig c;
    c.dt = dt;
    c.bounds = {{-10.0f, -1.0f, -10.0f}, {10.0f, 12.0f, 10.0f}};
    c.max_flakes = capacity;
    c.threads = threads;
    return c;
}

/// Puts a flake straight into the pool (no emitter), counted as spawned, as
/// if it had moved at v this tick (its path started at p − v·dt); unlike
/// Simulation::place_flake it takes any value (collide must cope with NaN).
std::uint32_t add_flake(Simulation& sim, glm::vec3 p, glm::vec3 v, std::uint32_t units = 1) {
    World& w = InternalAccess::world(sim);
    FlakePool& f = w.resource<FlakePool>();
    const PathStarts st = stage_path_starts(w);
    std::uint32_t slot = 0;
    EXPECT_TRUE(f.acquire(slot));
    f.px[slot] = p.x, f.py[slot] = p.y, f.pz[slot] = p.z;
    st.x[slot] = p.x - v.x * dt, st.y[slot] = p.y - v.y * dt;
    st.z[slot] = p.z - v.z * dt;
    f.vx[slot] = v.x, f.vy[slot] = v.y, f.vz[slot] = v.z;
    f.mass_units[slot] = units;
    w.resource<MassLedger>().spawned += units;
    return slot;
}

glm::vec3 pos(const Simulation& sim, std::uint32_t s) {
    const FlakePool& f = flake_pool(sim);
    return {f.px[s], f.py[s], f.pz[s]};
}

/// Where a flake that met surface `e` at (x, z) waits: its bare top there,
/// whole levels of fresh snow up (the roof's height rounded to them).
float waits_at(const Simulation& sim, SurfaceId e, float x, float z) {
    const SnowSurface& s = snow_surface(sim, e);
    std::uint32_t ix = 0, iz = 0;
    EXPECT_TRUE(s.cell_at(x, z, ix, iz));
    return s.top_y(s.index(ix, iz));
}

glm::vec3 vel(const Simulation& sim, std::uint32_t s) {
    const FlakePool& f = flake_pool(sim);
    return {f.vx[s], f.vy[s], f.vz[s]};
}

TEST(Collide, SphereRemovesFlakesAndCountsTheirMassExactly) {
    Simulation sim(config(16));
    sim.add_sphere({0.0f, 2.0f, 0.0f}, 1.0f);
    add_flake(sim, {0.0f, 2.0f, 0.0f}, {}, 7);
    add_flake(sim, {0.5f, 2.2f, -0.3f}, {}, 13);
    // Fast enough to jump over the whole sphere in one tick: the swept test catches it.
    add_flake(sim, {0.0f, 4.5f - 300.0f * dt, 0.0f}, {0.0f, -300.0f, 0.0f}, 100);
    const std::uint32_t outside = add_flake(sim, {3.0f, 2.0f, 0.0f}, {0.0f, -1.0f, 0.0f}, 5);
    collide_system(InternalAccess::world(sim));
    const MassLedger& ledger = world_of(sim).resource<MassLedger>();
    EXPECT_EQ(ledger.removed_sphere, 120u);
    EXPECT_EQ(ledger.removed(), 120u);
    EXPECT_EQ(flake_pool(sim).alive, 1u);
    EXPECT_TRUE(flake_pool(sim).is_alive(outside));
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(Collide, FlakesOutsideTheBoundsAreRemoved) {
    Simulation sim(config(16));
    add_flake(sim, {10.5f, 1.0f, 0.0f}, {}, 2);
    add_flake(sim, {0.0f, -1.5f, 0.0f}, {}, 3);
    add_flake(sim, {0.0f, 1.0f, -11.0f}, {}, 4);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    add_flake(sim, {nan, 1.0f, 0.0f}, {}, 8);
    const std::uint32_t inside = add_flake(sim, {9.99f, 11.99f, -9.99f}, {}, 16);
    collide_system(InternalAccess::world(sim));
    EXPECT_EQ(world_of(sim).resource<MassLedger>().removed_bounds, 17u);
    EXPECT_EQ(flake_pool(sim).alive, 1u);
    EXPECT_TRUE(flake_pool(sim).is_alive(inside));
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(Collide, FlakePushedIntoABoxSideEndsOnTheFaceAndSlidesDown) {
    Simulation sim(config(4));
    const Aabb box{{0.0f, 0.0f, -1.0f}, {2.0f, 3.0f, 1.0f}};
    sim.add_box(box);
    // Came from x = -0.01 this tick: entered through the -x face.
    const glm::vec3 v0{1.2f, -0.5f, 0.1f};
    const std::uint32_t s = add_flake(sim, glm::vec3{-0.01f, 2.0f, 0.0f} + v0 * dt, v0);
    const glm::vec3 p_in = pos(sim, s);
    ASSERT_GT(p_in.x, box.min.x);
    collide_system(InternalAccess::world(sim));
    ASSERT_TRUE(flake_pool(sim).is_alive(s));
    EXPECT_EQ(pos(sim, s).x, box.min.x);
    EXPECT_EQ(pos(sim, s).y, p_in.y); // motion along the face is kept
    EXPECT_EQ(pos(sim, s).z, p_in.z);
    EXPECT_EQ(vel(sim, s).x, 0.0f); // into-face component zeroed
    EXPECT_EQ(vel(sim, s).y, v0.y);
    EXPECT_EQ(vel(sim, s).z, v0.z);

    // Wind keeps pressing it against the wall while gravity pulls: it slides down the face.
    FlakePool& f = InternalAccess::world(sim).resource<FlakePool>();
    float y = pos(sim, s).y;
    for (int t = 0; t < 30; ++t) {
        f.vx[s] += 3.0f * dt;
        f.vy[s] += -9.81f * dt;
        f.px[s] += f.vx[s] * dt;
        f.py[s] += f.vy[s] * dt;
        f.pz[s] += f.vz[s] * dt;
        collide_system(InternalAccess::world(sim));
        ASSERT_TRUE(f.is_alive(s));
        EXPECT_EQ(f.px[s], box.min.x);
        EXPECT_EQ(f.vx[s], 0.0f);
        EXPECT_LT(f.py[s], y);
        y = f.py[s];
    }
    EXPECT_LT(y, 1.0f);
}

TEST(Collide, FastFlakeCannotTunnelThroughAThinRoof) {
    // 1 mm roof, 200 m/s, dt 1/60: the flake moves 3.3 m per tick.
    const Aabb roof{{-1.0f, 3.0f, -1.0f}, {1.0f, 3.001f, 1.0f}};
    const glm::vec3 v{30.0f, -200.0f, 0.0f};
    const glm::vec3 from{-0.5f, 4.5f, 0.0f};
    {
        Simulation sim(config(4));
        sim.add_box(roof);
        add_flake(sim, from + v * dt, v, 9);
        const std::uint32_t beside = add_flake(sim, glm::vec3{5.0f, 4.5f, 0.0f} + v * dt, v, 1);
        collide_system(InternalAccess::world(sim));
        EXPECT_EQ(world_of(sim).resource<MassLedger>().removed_bare, 9u); // caught, bare roof
        EXPECT_TRUE(flake_pool(sim).is_alive(beside));
    }
    {
        Simulation sim(config(4));
        const ColliderId house = sim.add_box(roof);
        const SurfaceId top =
            sim.add_surface(test::rect_surface(-1.0f, -1.0f, 2.0f, 2.0f, roof.max.y), house);
        const std::uint32_t s = add_flake(sim, from + v * dt, v, 9);
        collide_system(InternalAccess::world(sim));
        ASSERT_TRUE(flake_pool(sim).is_alive(s));
        // Waits at the entry point on the roof for the deposit system, no
        // higher than the surface's top there.
        const float t = (from.y - roof.max.y) / (-v.y * dt);
        const float x = from.x + v.x * dt * t;
        EXPECT_EQ(pos(sim, s).y, std::min(roof.max.y, waits_at(sim, top, x, from.z)));
        EXPECT_NEAR(pos(sim, s).x, x, 1e-4f);
        EXPECT_EQ(vel(sim, s).y, 0.0f);
    }
}

TEST(Collide, FastFlakeMeetsTheFirstRoofOnItsPath) {
    // The lower roof holds snow and is listed first; the flake must still stop at the upper one.
    Simulation sim(config(4));
    const ColliderId lower = sim.add_box({{-1.0f, 3.0f, -1.0f}, {1.0f, 3.1f, 1.0f}});
    sim.add_surface(test::rect_surface(-1.0f, -1.0f, 2.0f, 2.0f, 3.1f), lower);
    sim.add_box({{-1.0f, 5.0f, -1.0f}, {1.0f, 5.1f, 1.0f}});
    const glm::vec3 v{0.0f, -300.0f, 0.0f};
    add_flake(sim, glm::vec3{0.0f, 6.5f, 0.0f} + v * dt, v, 3);
    collide_system(InternalAccess::world(sim));
    EXPECT_EQ(world_of(sim).resource<MassLedger>().removed_bare, 3u);
    EXPECT_EQ(flake_pool(sim).alive, 0u);
}

TEST(Collide, FastFlakeIsCaughtByAWallFarFromWhereItEnds) {
    Simulation sim(config(4));
    const Aabb wall{{0.0f, 0.0f, -2.0f}, {0.01f, 4.0f, 2.0f}};
    sim.add_box(wall);
    const glm::vec3 v{120.0f, 0.0f, 0.0f};
    const std::uint32_t s = add_flake(sim, glm::vec3{-1.0f, 2.0f, 0.0f} + v * dt, v, 1);
    collide_system(InternalAccess::world(sim));
    // 0.25 m cells: the wall (x = 0) is not among the cells around the end point
    // (x = 1); only the flake's speed gets it looked at.
    ASSERT_EQ(world_of(sim).resource<ColliderGrid>().nx, 80u);
    ASSERT_TRUE(flake_pool(sim).is_alive(s));
    EXPECT_EQ(pos(sim, s).x, wall.min.x);
    EXPECT_EQ(vel(sim, s).x, 0.0f);
}

TEST(Collide, BoxTopWithoutSurfaceRemovesAsBareAndWithSurfaceKeepsFlakeOnTop) {
    Simulation sim(config(8));
    const Aabb box{{-1.0f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}};
    const ColliderId holder = sim.add_box(box);
    // The surface covers only the half x < 0 of the top.
    const SurfaceId half =
        sim.add_surface(test::rect_surface(-1.0f, -1.0f, 1.0f, 2.0f, 1.0f), holder);
    const Aabb bare_box{{4.0f, 0.0f, -1.0f}, {6.0f, 1.0f, 1.0f}};
    sim.add_box(bare_box);
    const glm::vec3 v{0.0f, -2.0f, 0.0f};
    const std::uint32_t on_surface = add_flake(sim, {-0.5f, 0.99f, 0.5f}, v, 3);
    add_flake(sim, {0.5f, 0.99f, 0.5f}, v, 5);  // holder's top, but no surface there
    add_flake(sim, {5.0f, 0.99f, 0.0f}, v, 11); // a box without surfaces
    collide_system(InternalAccess::world(sim));
    EXPECT_EQ(world_of(sim).resource<MassLedger>().removed_bare, 16u);
    ASSERT_TRUE(flake_pool(sim).is_alive(on_surface));
    const float top = std::min(1.0f, waits_at(sim, half, -0.5f, 0.5f));
    EXPECT_EQ(pos(sim, on_surface), (glm::vec3{-0.5f, top, 0.5f}));
    EXPECT_EQ(vel(sim, on_surface).y, 0.0f);
    EXPECT_EQ(flake_pool(sim).alive, 1u);
}

TEST(Collide, MeshTopIsMetThroughTheOcclusionMapOnlyFromAbove) {
    // A flat square roof at y = 2 as two triangles.
    const std::vector<glm::vec3> quad{{-1, 2, -1}, {1, 2, -1}, {1, 2, 1},
                                      {-1, 2, -1}, {1, 2, 1},  {-1, 2, 1}};
    for (const bool holder : {false, true}) {
        for (const float tilt : {0.0f, 0.4f}) { // tilted: looked up along the wind
            Simulation sim(config(8));
            const ColliderId roof = sim.add_mesh_collider(quad);
            if (holder) {
                sim.add_surface(test::rect_surface(-1.0f, -1.0f, 2.0f, 2.0f, 2.0f), roof);
            }
            Wind w;
            w.base = w.current = {3.0f, 0.0f, 0.0f};
            sim.set_wind(w);
            sim.set_occlusion(OcclusionCamera{128, tilt});
            occlusion_system(InternalAccess::world(sim));
            ASSERT_EQ(world_of(sim).resource<OcclusionMap>().shear_x == 0.0f, tilt == 0.0f);
            const std::uint32_t from_above =
                add_flake(sim, {0.2f, 1.99f, 0.3f}, {0.0f, -2.0f, 0.0f}, 4);
            const std::uint32_t sideways =
                add_flake(sim, {0.0f, 1.5f, 0.0f}, {1.0f, 0.0f, 0.0f}, 6);
            collide_system(InternalAccess::world(sim));
            EXPECT_TRUE(flake_pool(sim).is_alive(sideways));
            EXPECT_EQ(pos(sim, sideways), (glm::vec3{0.0f, 1.5f, 0.0f}));
            if (holder) {
                ASSERT_TRUE(flake_pool(sim).is_alive(from_above));
                EXPECT_NEAR(pos(sim, from_above).y, 2.0f, 1e-4f);
                EXPECT_EQ(vel(sim, from_above).y, 0.0f);
                EXPECT_EQ(world_of(sim).resource<MassLedger>().removed(), 0u);
            } else {
                EXPECT_FALSE(flake_pool(sim).is_alive(from_above));
                EXPECT_EQ(world_of(sim).resource<MassLedger>().removed_bare, 4u);
            }
        }
    }
}

TEST(Collide, GridIndexesManyBoxesAndRebuildsWhenTheSolidsChange) {
    Simulation sim(config(1024));
    // 20 × 20 small bare boxes; one flake falls onto each top.
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            const float x = -9.5f + i * 0.95f, z = -9.5f + j * 0.95f;
            sim.add_box({{x, 0.0f, z}, {x + 0.5f, 1.0f + 0.01f * i, z + 0.5f}});
            add_flake(sim, {x + 0.25f, 0.99f + 0.01f * i, z + 0.25f}, {0.0f, -2.0f, 0.0f}, 1);
        }
    }
    collide_system(InternalAccess::world(sim));
    EXPECT_EQ(world_of(sim).resource<MassLedger>().removed_bare, 400u);
    const auto& grid = world_of(sim).resource<ColliderGrid>();
    EXPECT_EQ(grid.nx, 80u);
    std::uint32_t most = 0;
    for (std::size_t c = 0; c + 1 < grid.cell_start.size(); ++c) {
        most = std::max(most, grid.cell_start[c + 1] - grid.cell_start[c]);
    }
    EXPECT_LE(most, 4u); // a flake meets a handful of boxes, not 400

    const std::uint64_t built = grid.solids_version;
    const std::uint32_t s = add_flake(sim, {0.0f, 5.0f, 0.0f}, {}, 1);
    sim.add_sphere({0.0f, 5.0f, 0.0f}, 0.5f); // bumps SourceVersions::solids
    collide_system(InternalAccess::world(sim));
    EXPECT_NE(world_of(sim).resource<ColliderGrid>().solids_version, built);
    EXPECT_FALSE(flake_pool(sim).is_alive(s));
    EXPECT_EQ(world_of(sim).resource<MassLedger>().removed_sphere, 1u);
}

/// A scene with every kind of collider and 100k flakes drawn from a fixed seed.
void fill_scene(Simulation& sim, std::uint32_t flakes) {
    const std::vector<glm::vec3> tent{{2, 1, 2}, {6, 3, 4}, {2, 1, 6},
                                      {6, 3, 4}, {8, 1, 2}, {8, 1, 6}};
    const ColliderId mesh = sim.add_mesh_collider(tent);
    sim.add_surface(test::rect_surface(2.0f, 2.0f, 3.0f, 4.0f, 2.0f), mesh);
    for (std::uint32_t i = 0; i < 40; ++i) {
        const RngKey k{7, 0, i, random_stream::test};
        const glm::vec3 c{rng_range(k, 0, -9, 9), rng_range(k, 1, 0, 4), rng_range(k, 2, -9, 9)};
        const glm::vec3 h{rng_range(k, 3, 0.2f, 1.5f), rng_range(k, 4, 0.01f, 1.0f),
                          rng_range(k, 5, 0.2f, 1.5f)};
        if (i % 4 == 3) {
            sim.add_sphere(c, h.x);
            continue;
        }
        const ColliderId b = sim.add_box({c - h, c + h});
        if (i % 3 == 0) {
            sim.add_surface(test::rect_surface(c.x - h.x, c.z - h.z, h.x, 2.0f * h.z, c.y + h.y),
                            b);
        }
    }
    sim.set_occlusion(OcclusionCamera{128, 0.0f});
    occlusion_system(InternalAccess::world(sim));
    for (std::uint32_t i = 0; i < flakes; ++i) {
        const RngKey k{11, 0, i, random_stream::test};
        const glm::vec3 p{rng_range(k, 0, -10.5f, 10.5f), rng_range(k, 1, -1.2f, 8.0f),
                          rng_range(k, 2, -10.5f, 10.5f)};
        const float fast = i % 97 == 0 ? 60.0f : 1.0f;
        const glm::vec3 v{rng_range(k, 3, -2, 2) * fast, rng_range(k, 4, -3, 0.5f) * fast,
                          rng_range(k, 5, -2, 2) * fast};
        add_flake(sim, p, v, 1 + rng_below(k, 6, 1000));
    }
}

TEST(Collide, OneAndTwoThreadsLeaveIdenticalPoolState) {
    constexpr std::uint32_t n = 100000;
    Simulation one(config(n, 1));
    Simulation two(config(n, 2));
    test::share_work_at_any_size(two);
    fill_scene(one, n);
    fill_scene(two, n);
    const FlakePool before = flake_pool(one);
    collide_system(InternalAccess::world(one));
    collide_system(InternalAccess::world(two));
    const FlakePool& a = flake_pool(one);
    const FlakePool& b = flake_pool(two);
    EXPECT_EQ(a.px, b.px);
    EXPECT_EQ(a.py, b.py);
    EXPECT_EQ(a.pz, b.pz);
    EXPECT_EQ(a.vx, b.vx);
    EXPECT_EQ(a.vy, b.vy);
    EXPECT_EQ(a.vz, b.vz);
    EXPECT_EQ(a.mass_units, b.mass_units);
    EXPECT_EQ(a.free_stack, b.free_stack);
    EXPECT_EQ(a.alive, b.alive);
    EXPECT_EQ(one.state_hash(), two.state_hash());
    const MassLedger& la = world_of(one).resource<MassLedger>();
    const MassLedger& lb = world_of(two).resource<MassLedger>();
    EXPECT_EQ(la.removed_bounds, lb.removed_bounds);
    EXPECT_EQ(la.removed_sphere, lb.removed_sphere);
    EXPECT_EQ(la.removed_bare, lb.removed_bare);
    // Every path was exercised, and the books still balance.
    EXPECT_GT(la.removed_bounds, 0u);
    EXPECT_GT(la.removed_sphere, 0u);
    EXPECT_GT(la.removed_bare, 0u);
    EXPECT_NE(a.px, before.px); // some flakes were pushed out of boxes
    EXPECT_TRUE(one.mass().balanced());
}

TEST(Collide, NoFlakeLiesAtRestOnATiltedMeshRoof) {
    // A mesh roof seen through the sky map: a texel's top may lie above the
    // snow top of the cell under it. A flake stopped there must still become
    // snow of the roof's surface (or slide off), never rest on the bare plane.
    for (const float pitch_deg : {30.0f, 45.0f, 60.0f}) {
        SCOPED_TRACE(pitch_deg);
        SimConfig c;
        c.bounds = {{-3.0f, 0.0f, -3.0f}, {3.0f, 8.0f, 3.0f}};
        c.max_flakes = 20000;
        Simulation sim(c);
        const float slope = std::tan(glm::radians(pitch_deg));
        const auto y = [&](float x) { return 3.0f + slope * (x + 1.0f); };
        const std::vector<glm::vec3> roof_mesh{{-1, y(-1), -1}, {1, y(1), -1}, {1, y(1), 1},
                                               {-1, y(-1), -1}, {1, y(1), 1},  {-1, y(-1), 1}};
        const ColliderId roof = sim.add_mesh_collider(roof_mesh);
        SurfaceDef d = test::rect_surface(-1.0f, -1.0f, 2.0f, 2.0f, 0.0f, true);
        d.cell = 0.1f;
        d.slope_x = slope;
        d.base_y = y(-1.0f);
        const SurfaceId surface = sim.add_surface(d, roof);
        sim.set_occlusion(OcclusionCamera{64, 0.0f});
        Emitter e;
        e.snowfall_kg_m2_h = 30.0f;
        sim.add_emitter(e);
        sim.run(900);
        const FlakePool& f = flake_pool(sim);
        std::uint32_t resting = 0;
        for (std::uint32_t i = 0; i < f.slot_end; ++i) {
            const bool over_roof = std::abs(f.px[i]) < 0.95f && std::abs(f.pz[i]) < 0.95f &&
                                   f.py[i] > 2.0f && f.py[i] < 7.0f;
            if (f.is_alive(i) && over_roof && std::abs(f.vy[i]) < 0.05f) {
                ++resting;
            }
        }
        EXPECT_EQ(resting, 0u);
        EXPECT_GT(snow_surface(sim, surface).settled_units(), 0u);
        EXPECT_TRUE(sim.mass().balanced());
    }
}

} // namespace
} // namespace snow
