// The default scene end to end (issue #4's "done when"): every system runs,
// snow settles on roofs and ground, roofs spill onto the porch and ground,
// the mass books balance exactly and nothing turns non-finite.
#include "game/scene/scene_loader.hpp"

#include <gtest/gtest.h>

#include <string>

namespace snow {
namespace {

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
    for (const SystemStats& s : sim.schedule().stats()) {
        if (s.name == "wind_field") {
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
}

} // namespace
} // namespace snow
