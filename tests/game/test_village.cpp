// The default scene end to end (issue #4's "done when"): every system runs,
// snow settles on roofs and ground, roofs spill onto the porch and ground,
// the mass books balance exactly, nothing turns non-finite, and the walker's
// trail shows.
#include "game/scene/scene_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>

namespace snow {
namespace {

/// Snow depth (m) on the ground (a surface cell with its bare top below
/// 0.5 m) at (x, z); 0 where there is none.
double ground_depth(const Simulation& sim, float x, float z) {
    double depth = 0.0;
    sim.world().each<SnowSurface>([&](Entity, const SnowSurface& s) {
        std::uint32_t ix = 0, iz = 0;
        if (s.cell_at(x, z, ix, iz) && !s.is_void(s.index(ix, iz)) &&
            s.height(s.base_level[s.index(ix, iz)]) < 0.5f) {
            depth = std::max(depth, static_cast<double>(s.depth(s.index(ix, iz))));
        }
    });
    return depth;
}

TEST(VillageScene, TenThousandTicksOfTheWholeChain) {
    SceneLoadResult r =
        load_scene_file(std::string(SNOW_SOURCE_DIR) + "/assets/scenes/village.gltf");
    ASSERT_TRUE(r.sim) << r.error;
    Simulation& sim = *r.sim;
    for (int block = 0; block < 10; ++block) {
        sim.run(1000);
        const MassReport m = sim.mass();
        ASSERT_TRUE(m.balanced()) << "tick " << sim.tick_count();
        ASSERT_EQ(sim.nonfinite_count(), 0u) << "tick " << sim.tick_count();
    }
    // Every system ran but the wind field and its transport, which the
    // village does not declare.
    for (const SystemStats& s : sim.schedule().stats()) {
        if (s.name == "wind_field" || s.name == "wind_transport") {
            EXPECT_EQ(s.calls, 0u) << "the village declares no wind field";
            continue;
        }
        EXPECT_GT(s.calls, 0u) << s.name << " never ran";
    }
    // Every surface (ground, both roof sides, porch, garage, the cover) holds snow.
    std::size_t surfaces = 0;
    sim.world().each<SnowSurface>([&](Entity, const SnowSurface& s) {
        ++surfaces;
        EXPECT_GT(s.settled_units(), 0u);
    });
    EXPECT_EQ(surfaces, 6u);
    const SimCounters& c = sim.counters();
    EXPECT_GT(c.spilled_units, 0u); // roof edges shed snow
    EXPECT_GT(c.rolled, 0u);        // rules 2/3 of [ZCL §IV] fired
    EXPECT_GT(c.occlusion_refreshes, 0u);
    EXPECT_GT(c.carved_units, 0u);     // the walker's trail
    EXPECT_GT(sim.mass().removed, 0u); // the snowman and the bounds take flakes
    // The trail is plain to see: along each side of the walker's lap (x from
    // -1 to 5 at z 2.5 and 6.5, z from 2.5 to 6.5 at x -1 and 5) the snow is
    // less than half as deep as 1 m outside the lap, where no one walked.
    double on = 0.0, beside = 0.0;
    for (float s = 0.5f; s < 3.6f; s += 0.25f) {
        const float along_x = -1.0f + 1.5f * s, along_z = 2.5f + s;
        for (const auto& [x, z, ox, oz] :
             {std::tuple{along_x, 2.5f, 0.0f, -1.0f}, std::tuple{along_x, 6.5f, 0.0f, 1.0f},
              std::tuple{-1.0f, along_z, -1.0f, 0.0f}, std::tuple{5.0f, along_z, 1.0f, 0.0f}}) {
            on += ground_depth(sim, x, z);
            beside += ground_depth(sim, x + ox, z + oz);
        }
    }
    EXPECT_GT(beside, 0.0);
    EXPECT_LT(on, 0.5 * beside) << "trail " << on << " m against " << beside << " m beside it";
}

} // namespace
} // namespace snow
