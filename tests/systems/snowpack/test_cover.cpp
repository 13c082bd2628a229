// cover: snow on whatever geometry lies under it (spheres, meshes, boxes),
// with drops that spill, slopes steeper than repose that shed, geometry
// changes that release snow as flakes, and the ledger exact every tick.
#include "systems/api/simulation_internals.hpp"
#include "systems/snowpack/snow_cover.hpp"
#include "tests/support/units_in.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace snow {
namespace {

SimConfig small_world(unsigned threads = 1) {
    SimConfig c;
    c.seed = 7;
    c.bounds = {{-3.0f, -1.0f, -3.0f}, {3.0f, 5.0f, 3.0f}};
    c.max_flakes = 20000;
    c.threads = threads;
    return c;
}

/// Two triangles: a level ground plane at height y over [-s, s]².
std::vector<glm::vec3> ground_plane(float s, float y) {
    return {{-s, y, -s}, {s, y, -s}, {s, y, s}, {-s, y, -s}, {s, y, s}, {-s, y, s}};
}

CoverDef cover_over(float half, float cell) {
    CoverDef d;
    d.min_x = d.min_z = -half;
    d.max_x = d.max_z = half;
    d.cell = cell;
    return d;
}

/// Depth (m) of the cover's cell under world (x, z).
float depth_at(const Simulation& sim, CoverId cover, float x, float z) {
    const SnowSurface& s = snow_surface(sim, cover);
    std::uint32_t ix = 0, iz = 0;
    if (!s.cell_at(x, z, ix, iz)) {
        return -1.0f;
    }
    return static_cast<float>(s.snow[s.index(ix, iz)] * static_cast<double>(s.unit_height));
}

/// Mean depth (m) of the cover's 3×3 cells around world (x, z): a short
/// snowfall lays a few hundred units on a 5 cm cell, under one big flake,
/// and the crown of a sphere sheds part of its share, so a single cell may
/// hold none.
float patch_depth(const Simulation& sim, CoverId cover, float x, float z) {
    const float c = snow_surface(sim, cover).cell;
    float sum = 0.0f;
    for (const float dz : {-c, 0.0f, c}) {
        for (const float dx : {-c, 0.0f, c}) {
            sum += depth_at(sim, cover, x + dx, z + dz);
        }
    }
    return sum / 9.0f;
}

/// Base height (m) of the cover's cell under (x, z); -inf for void.
float base_at(const Simulation& sim, CoverId cover, float x, float z) {
    const SnowSurface& s = snow_surface(sim, cover);
    std::uint32_t ix = 0, iz = 0;
    if (!s.cell_at(x, z, ix, iz) || s.is_void(s.index(ix, iz))) {
        return -INFINITY;
    }
    return s.height(s.base_level[s.index(ix, iz)]);
}

/// A test-sized blizzard: 100 kg/m²/h, a 30 s run lays ~1 kg/m² (~1 cm).
Emitter heavy_snow() {
    Emitter e;
    e.rate = 6000.0f;
    e.snowfall_kg_m2_h = 100.0f;
    return e;
}

void run_balanced(Simulation& sim, int ticks) {
    for (int t = 0; t < ticks; ++t) {
        sim.tick();
        ASSERT_TRUE(sim.mass().balanced()) << "tick " << t;
    }
}

TEST(SnowCover, BaseFollowsTheHighestGeometryOfEachColumn) {
    Simulation sim(small_world());
    sim.add_mesh_collider(ground_plane(3.0f, 0.0f));
    sim.add_sphere({0.0f, 1.0f, 0.0f}, 0.5f);
    sim.add_box({{1.0f, 0.0f, 1.0f}, {2.0f, 0.8f, 2.0f}});
    const CoverId cover = sim.add_cover(cover_over(2.5f, 0.05f));
    sim.tick();
    EXPECT_NEAR(base_at(sim, cover, 0.01f, 0.01f), 1.5f, 0.01f);  // sphere top
    EXPECT_NEAR(base_at(sim, cover, 1.5f, 1.5f), 0.8f, 1e-3f);    // box top
    EXPECT_NEAR(base_at(sim, cover, -2.0f, -2.0f), 0.0f, 1e-3f);  // ground mesh
    const float shoulder = 1.0f + std::sqrt(0.25f - 0.3f * 0.3f); // sphere at r = 0.3
    EXPECT_NEAR(base_at(sim, cover, 0.3f, 0.0f), shoulder, 0.03f);
}

TEST(SnowCover, SnowLiesOnASphereABoxAndTheGround) {
    Simulation sim(small_world());
    sim.add_mesh_collider(ground_plane(3.0f, 0.0f));
    sim.add_sphere({0.0f, 1.0f, 0.0f}, 0.5f);
    sim.add_box({{1.0f, 0.0f, 1.0f}, {2.0f, 0.8f, 2.0f}});
    sim.add_emitter(heavy_snow());
    const CoverId cover = sim.add_cover(cover_over(2.5f, 0.05f));
    run_balanced(sim, 1800);
    EXPECT_GT(patch_depth(sim, cover, 0.0f, 0.0f), 0.0f) << "sphere top";
    EXPECT_GT(depth_at(sim, cover, 1.5f, 1.5f), 0.0f) << "box top";
    EXPECT_GT(depth_at(sim, cover, -2.0f, -2.0f), 0.0f) << "ground";
    EXPECT_GT(sim.counters().landed, 0u);
}

TEST(SnowCover, ExcessAtABoxEdgeSpillsOntoTheGround) {
    Simulation sim(small_world());
    sim.add_mesh_collider(ground_plane(3.0f, 0.0f));
    sim.add_box({{-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}});
    CoverDef d = cover_over(2.0f, 0.05f);
    d.edge_limit = 0.002f;
    const CoverId cover = sim.add_cover(d);
    sim.add_emitter(heavy_snow());
    run_balanced(sim, 1800);
    EXPECT_GT(sim.counters().spilled_units, 0u);
    // The box top holds at most about its edge limit at its rim.
    const SnowSurface& s = snow_surface(sim, cover);
    std::uint32_t ix = 0, iz = 0;
    ASSERT_TRUE(s.cell_at(0.49f, 0.0f, ix, iz));
    EXPECT_LE(s.snow[s.index(ix, iz)], s.edge_limit_units);
}

TEST(SnowCover, SnowSlidesOffASteepRoofAndCollectsAtItsFoot) {
    Simulation sim(small_world());
    sim.add_mesh_collider(ground_plane(3.0f, 0.0f));
    // A 60° ramp rising along +x from (0, 0) to (0.6, 1.04): steeper than repose.
    const float h = 0.6f * std::tan(60.0f * 3.14159265f / 180.0f);
    sim.add_mesh_collider({{0.0f, 0.0f, -1.0f},
                           {0.6f, h, -1.0f},
                           {0.6f, h, 1.0f},
                           {0.0f, 0.0f, -1.0f},
                           {0.6f, h, 1.0f},
                           {0.0f, 0.0f, 1.0f}});
    CoverDef d = cover_over(2.0f, 0.05f);
    d.drop_limit = 0.2f; // 60° over 5 cm is 8.7 cm: a slope, not a drop
    const CoverId cover = sim.add_cover(d);
    sim.add_emitter(heavy_snow());
    run_balanced(sim, 1800);
    // Mid-slope stays nearly bare, the foot collects what slid.
    const float slope = depth_at(sim, cover, 0.3f, 0.0f);
    const float foot = depth_at(sim, cover, -0.1f, 0.0f);
    const float open = depth_at(sim, cover, -1.5f, 0.0f);
    EXPECT_LT(slope, 0.5f * open);
    EXPECT_GT(foot, open);
}

TEST(SnowCover, RemovedGeometryReleasesItsSnowAsFlakes) {
    SimConfig c = small_world();
    c.max_flakes = 60000; // room for the released snow in the same tick
    Simulation sim(c);
    sim.add_mesh_collider(ground_plane(3.0f, 0.0f));
    const ColliderId box = sim.add_box({{-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}});
    const CoverId cover = sim.add_cover(cover_over(3.0f, 0.05f)); // the whole ground
    const EmitterId emitter = sim.add_emitter(heavy_snow());
    run_balanced(sim, 600);
    const float on_box = depth_at(sim, cover, 0.0f, 0.0f);
    ASSERT_GT(on_box, 0.0f);
    sim.remove(emitter);
    sim.remove(box);
    const MassReport before = sim.mass();
    sim.tick();
    const MassReport after = sim.mass();
    EXPECT_TRUE(after.balanced());
    EXPECT_EQ(after.spawned, before.spawned);
    EXPECT_NEAR(base_at(sim, cover, 0.0f, 0.0f), 0.0f, 1e-3f); // now the ground
    EXPECT_GT(after.airborne, before.airborne) << "the box's snow is falling";
    run_balanced(sim, 600);
    EXPECT_GT(depth_at(sim, cover, 0.0f, 0.0f), 0.0f) << "it landed on the ground";
    EXPECT_EQ(sim.mass().removed, before.removed) << "nothing lost on the way down";
    EXPECT_EQ(sim.mass().airborne, 0u) << "all of it landed again";
}

TEST(SnowCover, FastFlakesDoNotTunnelThroughAThinRoof) {
    SimConfig c = small_world();
    c.gravity = {0.0f, -200.0f * 60.0f, 0.0f}; // 200 m/s after the first tick
    Simulation sim(c);
    sim.add_box({{-1.0f, 1.0f, -1.0f}, {1.0f, 1.001f, 1.0f}}); // a 1 mm roof
    const CoverId cover = sim.add_cover(cover_over(2.0f, 0.05f));
    Emitter e = heavy_snow();
    sim.add_emitter(e);
    for (int t = 0; t < 300; ++t) {
        sim.tick();
        ASSERT_TRUE(sim.mass().balanced());
    }
    EXPECT_GT(test::units_in(snow_surface(sim, cover), -1.0f, -1.0f, 1.0f, 1.0f), 0u)
        << "snow on the roof";
}

TEST(SnowCover, OneAndTwoThreadsGiveTheSameState) {
    Simulation a(small_world(1)), b(small_world(2));
    for (Simulation* s : {&a, &b}) {
        s->add_mesh_collider(ground_plane(3.0f, 0.0f));
        s->add_sphere({0.0f, 1.0f, 0.0f}, 0.5f);
        s->add_emitter(heavy_snow());
        s->add_cover(cover_over(2.5f, 0.05f));
    }
    for (int t = 0; t < 600; ++t) {
        a.tick();
        b.tick();
        ASSERT_EQ(a.state_hash(), b.state_hash()) << "tick " << t;
    }
}

TEST(SnowCover, RestoreFromBeforeTheFirstBuildReplaysExactly) {
    Simulation sim(small_world());
    sim.add_mesh_collider(ground_plane(3.0f, 0.0f));
    sim.add_sphere({0.0f, 1.0f, 0.0f}, 0.5f);
    sim.add_emitter(heavy_snow());
    const CoverId cover = sim.add_cover(cover_over(2.5f, 0.05f));
    const auto start = save_snapshot(sim); // the cover's base is not built yet
    sim.run(600);
    const std::uint64_t straight = sim.state_hash();
    restore_snapshot(sim, *start);
    sim.run(600);
    EXPECT_EQ(sim.state_hash(), straight);
    EXPECT_GT(snow_surface(sim, cover).settled_units(), 0u) << "the cover was built again";
}

TEST(SnowCover, DeclaredSurfacesKeepTheirColumns) {
    Simulation sim(small_world());
    SurfaceDef ground;
    ground.x0 = ground.z0 = -2.0f;
    ground.size_x = ground.size_z = 4.0f;
    ground.cell = 0.1f;
    ground.spills = false;
    const SurfaceId g = sim.add_surface(ground);
    sim.add_sphere({0.0f, 1.0f, 0.0f}, 0.5f);
    const CoverId cover = sim.add_cover(cover_over(2.0f, 0.05f));
    sim.add_emitter(heavy_snow());
    run_balanced(sim, 900);
    EXPECT_EQ(base_at(sim, cover, -1.5f, -1.5f), -INFINITY) << "the ground rectangle's column";
    EXPECT_GT(test::units_in(snow_surface(sim, cover), -0.2f, -0.2f, 0.2f, 0.2f), 0u)
        << "the sphere above it is the cover's";
    EXPECT_GT(snow_surface(sim, g).settled_units(), 0u);
}

TEST(SnowCover, BadDefinitionsNameTheField) {
    Simulation sim(small_world());
    const auto error_of = [&](CoverDef d) {
        try {
            sim.add_cover(d);
        } catch (const SimulationError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    CoverDef d = cover_over(1.0f, 0.1f);
    d.max_x = d.min_x;
    EXPECT_NE(error_of(d).find("cover.max.x"), std::string::npos);
    d = cover_over(1.0f, 0.1f);
    d.min_z = NAN;
    EXPECT_NE(error_of(d).find("cover.min.z"), std::string::npos);
    d = cover_over(1.0e4f, 0.0001f); // 10^16 cells
    EXPECT_NE(error_of(d).find("cover cells"), std::string::npos);
    d = cover_over(1.0f, 0.1f);
    d.cell = 0.0f;
    EXPECT_NE(error_of(d).find("cover.cell"), std::string::npos);
    EXPECT_EQ(world_of(sim).find_pool<SnowCover>(), nullptr) << "nothing was added";
}

} // namespace
} // namespace snow
