// The renderer on a World built and stepped by the real Simulation: it reads
// the state (never writes it) and uses the occlusion system's map.
#include "render/renderer_internals.hpp"
#include "render_fixture.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/flakes/snowfall.hpp"

#include <gtest/gtest.h>

namespace snow::test {
namespace {

TEST(RenderSimulation, RendersASteppedSimulationWithoutChangingIt) {
    SimConfig config;
    config.seed = 11;
    config.bounds = {{-6.0f, -1.0f, -6.0f}, {6.0f, 8.0f, 6.0f}};
    config.max_flakes = 6000;
    Simulation sim(config);
    SurfaceDef ground;
    ground.x0 = -6.0f;
    ground.z0 = -6.0f;
    ground.size_x = ground.size_z = 12.0f;
    ground.cell = 0.2f;
    ground.spills = false;
    sim.add_surface(ground);
    const Aabb roof_box{{0.5f, 2.0f, -1.5f}, {3.5f, 2.15f, 1.5f}};
    const Aabb crate_box{{1.4f, 0.0f, -0.6f}, {2.6f, 0.7f, 0.6f}};
    const ColliderId roof = sim.add_box(roof_box);
    SurfaceDef top;
    top.x0 = roof_box.min.x;
    top.z0 = roof_box.min.z;
    top.size_x = top.size_z = 3.0f;
    top.cell = 0.1f;
    top.base_y = roof_box.max.y;
    sim.add_surface(top, roof);
    sim.add_box(crate_box);
    sim.add_emitter(with_snowfall(Emitter{}, 100.0f, 12.0 * 12.0)); // a test-sized blizzard
    sim.set_occlusion(OcclusionCamera{});
    SceneVisuals visuals;
    visuals.meshes = {box_mesh(roof_box, {0.4f, 0.4f, 0.45f}),
                      box_mesh(crate_box, {0.45f, 0.30f, 0.15f})};
    sim.run(240);
    ASSERT_GT(flake_pool(sim).alive, 0u);
    ASSERT_TRUE(world_of(sim).has_resource<OcclusionMap>());

    CameraDef def;
    def.position = {1.5f, 3.4f, 8.5f};
    def.target = {0.0f, 0.9f, 0.0f};
    const ViewCamera camera = ViewCamera::from_def(def);
    auto context = headless_context();
    Renderer renderer(*context);
    const std::uint64_t before = sim.state_hash();
    renderer.render(sim, visuals, camera);
    EXPECT_EQ(sim.state_hash(), before) << "rendering changed the simulation";
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 2u);
    EXPECT_GT(renderer.timings().flakes_drawn, 0u);
    const Image image = renderer.read_pixels();

    const auto brightness = [&](const glm::vec3& p) {
        const glm::vec3 c = mean_color(image, to_pixel(camera, p), 2);
        return (c.x + c.y + c.z) / 3.0f;
    };
    // The sim's own sky map: the shelter roof is exposed, the crate under it is not.
    EXPECT_GT(brightness({2.0f, 2.15f, 0.0f}), brightness({2.0f, 0.7f, 0.3f}) + 60.0f);

    sim.run(60); // more snow lands: only changed surfaces are re-uploaded
    renderer.render(sim, visuals, camera);
    EXPECT_GE(renderer.timings().surfaces_uploaded, 1u);
    EXPECT_LE(renderer.timings().surfaces_uploaded, 2u);
}

} // namespace
} // namespace snow::test
