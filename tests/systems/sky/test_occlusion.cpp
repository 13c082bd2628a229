// The occlusion ("sky") camera of [SKY]: depth map from above, exposure, tilt, refresh.
#include "systems/api/simulation_internals.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace snow {
namespace {

SimConfig config() {
    SimConfig c;
    c.bounds = {{-10.0f, -1.0f, -10.0f}, {10.0f, 12.0f, 10.0f}};
    c.max_flakes = 4;
    return c;
}

SurfaceDef ground() {
    SurfaceDef d;
    d.x0 = -10.0f;
    d.z0 = -10.0f;
    d.size_x = 20.0f;
    d.size_z = 20.0f;
    d.cell = 0.25f;
    d.spills = false;
    return d;
}

const OcclusionMap& map_of(const Simulation& sim) {
    return world_of(sim).resource<OcclusionMap>();
}

/// Texel under world (x, z) for a map without tilt.
std::size_t texel(const OcclusionMap& m, float x, float z) {
    std::uint32_t i = 0, j = 0;
    EXPECT_TRUE(occlusion_texel(m, x, 0.0f, z, i, j));
    return static_cast<std::size_t>(j) * m.width + i;
}

/// Walls 4 × 2.5 × 4 m under a pitched mesh roof (ridge along z at y = 3.5,
/// eaves overhanging to x = ±2.5 at y = 2.5), on a ground surface, with a
/// table mesh inside the house.
struct House {
    Simulation sim{config()};
    SurfaceId ground_surface = sim.add_surface(ground());
    ColliderId walls = sim.add_box({{-2.0f, 0.0f, -2.0f}, {2.0f, 2.5f, 2.0f}});
    ColliderId roof = sim.add_mesh_collider({{-2.5f, 2.5f, -2.5f},
                                             {0.0f, 3.5f, -2.5f},
                                             {0.0f, 3.5f, 2.5f},
                                             {-2.5f, 2.5f, -2.5f},
                                             {0.0f, 3.5f, 2.5f},
                                             {-2.5f, 2.5f, 2.5f},
                                             {2.5f, 2.5f, -2.5f},
                                             {0.0f, 3.5f, -2.5f},
                                             {0.0f, 3.5f, 2.5f},
                                             {2.5f, 2.5f, -2.5f},
                                             {0.0f, 3.5f, 2.5f},
                                             {2.5f, 2.5f, 2.5f}});
    ColliderId table =
        sim.add_mesh_collider({{-1.0f, 0.8f, -1.0f}, {1.0f, 0.8f, -1.0f}, {1.0f, 0.8f, 1.0f}});
    ColliderId ball = sim.add_sphere({6.0f, 1.0f, 6.0f}, 1.0f);

    explicit House(float tilt = 0.0f) {
        sim.set_occlusion(OcclusionCamera{160, tilt});
        occlusion_system(InternalAccess::world(sim));
    }
};

TEST(Occlusion, RoofIsTopmostOverTheHouseAndGroundElsewhere) {
    House h;
    const OcclusionMap& m = map_of(h.sim);
    ASSERT_EQ(m.width, 160u);
    ASSERT_EQ(m.height, 160u);
    for (const float x : {-2.3f, -1.0f, 0.0f, 1.0f, 2.3f}) {
        for (const float z : {-2.3f, 0.0f, 2.3f}) {
            const std::size_t t = texel(m, x, z);
            EXPECT_EQ(m.top_id[t], h.roof.bits) << x << ", " << z;
            // The roof's height, up to the texel's offset from (x, z).
            EXPECT_NEAR(m.top_y[t], 3.5f - std::abs(x) / 2.5f, 0.06f);
        }
    }
    EXPECT_EQ(m.top_id[texel(m, -6.0f, 3.0f)], h.ground_surface.bits);
    EXPECT_NEAR(m.top_y[texel(m, -6.0f, 3.0f)], 0.0f, 1e-4f);
    EXPECT_EQ(m.top_id[texel(m, 6.0f, 6.0f)], h.ball.bits);
    EXPECT_NEAR(m.top_y[texel(m, 6.0f, 6.0f)], 2.0f, 0.01f);
}

TEST(Occlusion, UnderTheRoofIsNotExposedOnTheRoofIs) {
    House h;
    const OcclusionMap& m = map_of(h.sim);
    EXPECT_EQ(occlusion_exposure(m, 0.5f, 1.0f, 0.5f), 0.0f);  // inside the house
    EXPECT_EQ(occlusion_exposure(m, 0.5f, 0.8f, -0.5f), 0.0f); // the table under the roof
    EXPECT_EQ(occlusion_exposure(m, 2.25f, 0.0f, 0.0f), 0.0f); // ground under the eaves
    EXPECT_EQ(occlusion_exposure(m, 1.0f, 3.1f, 0.0f), 1.0f);  // on the roof slope
    EXPECT_EQ(occlusion_exposure(m, -6.0f, 0.0f, 3.0f), 1.0f); // open ground
    EXPECT_EQ(occlusion_exposure(m, 6.0f, 1.0f, 6.0f), 0.0f);  // inside the ball
    EXPECT_EQ(occlusion_exposure(m, 50.0f, 0.0f, 0.0f), 1.0f); // off the map: nothing above

    // Per cell of the ground: exactly the roof's 5 × 5 m footprint is in its shadow.
    Vector<float> exposure;
    const SnowSurface& g = snow_surface(h.sim, h.ground_surface);
    surface_exposure(m, g, exposure);
    ASSERT_EQ(exposure.size(), g.cell_count());
    std::size_t shaded_under_roof = 0, shaded_elsewhere = 0;
    for (std::uint32_t iz = 0; iz < g.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < g.nx; ++ix) {
            const float x = g.x0 + (ix + 0.5f) * g.cell, z = g.z0 + (iz + 0.5f) * g.cell;
            const bool under = std::abs(x) < 2.5f && std::abs(z) < 2.5f;
            const bool under_ball = std::hypot(x - 6.0f, z - 6.0f) < 1.2f;
            const bool shaded = exposure[g.index(ix, iz)] == 0.0f;
            shaded_under_roof += under && shaded ? 1 : 0;
            shaded_elsewhere += !under && !under_ball && shaded ? 1 : 0;
        }
    }
    EXPECT_EQ(shaded_under_roof, 400u); // (5 m / 0.25 m)^2 cells
    EXPECT_EQ(shaded_elsewhere, 0u);
}

TEST(Occlusion, RefreshesOnceThenOnlyWhenGeometryChanges) {
    House h;
    const auto refreshes = [&] { return h.sim.counters().occlusion_refreshes; };
    EXPECT_EQ(refreshes(), 1u);
    Wind w;
    w.base = w.current = {3.0f, 0.0f, 1.0f};
    h.sim.set_wind(w);
    for (int i = 0; i < 3; ++i) {
        occlusion_system(InternalAccess::world(h.sim)); // tilt 0: the wind does not matter
    }
    EXPECT_EQ(refreshes(), 1u);
    EXPECT_EQ(map_of(h.sim).version, 1u);
    const ColliderId shed = h.sim.add_box({{-8.0f, 0.0f, -8.0f}, {-6.0f, 1.0f, -6.0f}});
    occlusion_system(InternalAccess::world(h.sim));
    occlusion_system(InternalAccess::world(h.sim));
    EXPECT_EQ(refreshes(), 2u);
    EXPECT_EQ(map_of(h.sim).top_id[texel(map_of(h.sim), -7.0f, -7.0f)], shed.bits);
}

TEST(Occlusion, TiltShadowsTheLeeSideAndFollowsTheWind) {
    const float tilt = std::atan(0.5f); // rays drop 2 m per 1 m downwind
    Simulation sim(config());
    sim.add_surface(ground());
    sim.add_box({{-1.0f, 0.0f, -1.0f}, {1.0f, 2.0f, 1.0f}});
    Wind w;
    w.base = w.current = {3.0f, 0.0f, 0.0f};
    sim.set_wind(w);
    sim.set_occlusion(OcclusionCamera{160, 0.0f});
    occlusion_system(InternalAccess::world(sim));
    const auto exposed = [&](float x, float z) {
        return occlusion_exposure(world_of(sim).resource<OcclusionMap>(), x, 0.0f, z);
    };
    EXPECT_EQ(exposed(1.5f, 0.0f), 1.0f); // straight down: both sides open
    EXPECT_EQ(exposed(-1.5f, 0.0f), 1.0f);

    sim.set_occlusion(OcclusionCamera{160, tilt});
    occlusion_system(InternalAccess::world(sim));
    EXPECT_EQ(exposed(1.5f, 0.0f), 0.0f);  // lee side (downwind) now in the box's shadow
    EXPECT_EQ(exposed(2.5f, 0.0f), 1.0f);  // beyond the shadow (2 m tall → 1 m long)
    EXPECT_EQ(exposed(-1.5f, 0.0f), 1.0f); // windward side stays open
    EXPECT_EQ(exposed(0.0f, 1.5f), 1.0f);  // across the wind: open

    const auto refreshes = [&] { return sim.counters().occlusion_refreshes; };
    const std::uint64_t before = refreshes();
    w.current = {3.0f, 0.0f, 0.05f}; // ~1°: same direction step
    sim.set_wind(w);
    occlusion_system(InternalAccess::world(sim));
    EXPECT_EQ(refreshes(), before);
    w.current = {0.0f, 0.0f, -2.0f}; // wind turns to -z
    sim.set_wind(w);
    occlusion_system(InternalAccess::world(sim));
    EXPECT_EQ(refreshes(), before + 1);
    EXPECT_EQ(exposed(1.5f, 0.0f), 1.0f);
    EXPECT_EQ(exposed(0.0f, -1.5f), 0.0f); // the shadow moved with the wind
    EXPECT_EQ(exposed(0.0f, 1.5f), 1.0f);
}

} // namespace
} // namespace snow
