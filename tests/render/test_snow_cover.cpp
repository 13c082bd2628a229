// Snow on surfaces: sky exposure and incline (seed 004), heightfields with
// skirts (seed 002 §6) that leave no crack at borders, eaves or between levels
// of detail, re-upload of the changed tiles only.
#include "render/renderer.hpp"
#include "render_fixture.hpp"
#include "systems/occlusion.hpp"

#include <gtest/gtest.h>

namespace snow::test {
namespace {

float brightness(const glm::vec3& c) {
    return (c.x + c.y + c.z) / 3.0f;
}
/// Spread between the strongest and weakest channel: 0 for grey/white.
float saturation(const glm::vec3& c) {
    return std::max({c.x, c.y, c.z}) - std::min({c.x, c.y, c.z});
}

TEST(RenderSnowCover, RoofIsWhiteWhileTheMeshUnderItStaysDark) {
    FixtureScene scene;
    build_fixture(scene);
    const Image image = render_image(scene.world, scene.camera);
    const glm::vec3 roof = mean_color(image, to_pixel(scene.camera, {2.0f, 2.15f, 0.0f}), 2);
    const glm::vec3 crate = mean_color(image, to_pixel(scene.camera, {2.0f, 0.7f, 0.3f}), 2);
    EXPECT_GT(brightness(roof), 170.0f);
    EXPECT_LT(saturation(roof), 40.0f);
    EXPECT_LT(brightness(crate), 0.6f * brightness(roof));
    EXPECT_GT(crate.x, crate.z + 15.0f) << "the crate keeps its own (brown) colour";

    // Without the sky camera nothing is occluded: the same crate top turns white.
    scene.world.erase_resource<OcclusionMap>();
    const Image exposed = render_image(scene.world, scene.camera);
    const glm::vec3 crate_exposed =
        mean_color(exposed, to_pixel(scene.camera, {2.0f, 0.7f, 0.3f}), 2);
    EXPECT_GT(brightness(crate_exposed), brightness(crate) + 40.0f);
}

TEST(RenderSnowCover, InclineCoefficientLeavesWallsUncovered) {
    FixtureScene scene;
    build_fixture(scene);
    RenderSettings bare;
    bare.mesh_snow = 0.0f;
    const Image with_snow = render_image(scene.world, scene.camera);
    const Image without = render_image(scene.world, scene.camera, bare);
    // The house's front wall faces +z: dot(N, up) = 0, so snow never shows (seed 004 step 3).
    const glm::ivec2 wall = to_pixel(scene.camera, {-2.5f, 1.0f, 1.0f});
    EXPECT_EQ(mean_color(with_snow, wall, 2), mean_color(without, wall, 2));
    // The shelter's roof faces up and is exposed: snow makes it much brighter.
    const glm::ivec2 roof = to_pixel(scene.camera, {2.0f, 2.15f, 0.0f});
    EXPECT_GT(brightness(mean_color(with_snow, roof, 2)),
              brightness(mean_color(without, roof, 2)) + 60.0f);
}

TEST(RenderSnowCover, SlopedRoofIsEvenlyWhiteWithoutStripes) {
    // A 30° roof, rising 0.58 m per metre toward +x, and the tilted sky
    // camera's map of it as in the village (7.8 cm texels, rays leaning 0.255
    // m per metre against the slope, heights where the ray through each texel
    // centre meets the roof). The texel centres a fragment is filtered over
    // lie up to one texel up the slope, which there rises 5.3 cm: more than
    // the flat tolerance, so without a slope-scaled one every texel row shades
    // as partly occluded and the roof shows stripes.
    World world;
    constexpr float slope = 0.58f;
    MeshRenderable roof;
    roof.name = "roof";
    roof.positions = {{0.0f, 2.0f, -1.5f}, {3.0f, 2.0f + 3.0f * slope, -1.5f},
                      {3.0f, 2.0f + 3.0f * slope, 1.5f}, {0.0f, 2.0f, 1.5f}};
    roof.normals.assign(4, glm::normalize(glm::vec3(-slope, 1.0f, 0.0f)));
    roof.indices = {0, 2, 1, 0, 3, 2};
    roof.color = {0.35f, 0.12f, 0.10f};
    world.add<MeshRenderable>(world.create(), std::move(roof));
    world.set_resource<Environment>();
    OcclusionMap& map = world.set_resource<OcclusionMap>();
    map.x0 = -1.0f;
    map.z0 = -3.0f;
    map.texel = 0.078f;
    map.width = 64;
    map.height = 80;
    map.shear_x = -0.255f;
    map.top_y.resize(static_cast<std::size_t>(map.width) * map.height);
    for (std::uint32_t j = 0; j < map.height; ++j) {
        for (std::uint32_t i = 0; i < map.width; ++i) {
            // The ray x = u − shear·y meets y = 2 + slope·x at this height.
            const float u = map.x0 + (static_cast<float>(i) + 0.5f) * map.texel;
            const float z = map.z0 + (static_cast<float>(j) + 0.5f) * map.texel;
            const float y = (2.0f + slope * u) / (1.0f + slope * map.shear_x);
            const float x = u - map.shear_x * y;
            const bool on_roof = x >= 0.0f && x <= 3.0f && std::abs(z) <= 1.5f;
            map.top_y[j * map.width + i] = on_roof ? y : 0.0f;
        }
    }
    map.version = 1;
    ViewCamera camera;
    camera.position = {-1.0f, 4.6f, 1.8f};
    camera.look_at({1.5f, 2.9f, 0.0f});
    const Image image = render_image(world, camera);
    // A plane under the sun and the sky is lit evenly: every point down the
    // slope must come out the same.
    float lo = 255.0f, hi = 0.0f;
    for (int k = 0; k <= 400; ++k) {
        const float x = 0.2f + 2.6f * static_cast<float>(k) / 400.0f;
        const float b = brightness(mean_color(image, to_pixel(camera, {x, 2.0f + slope * x, 0.3f}), 0));
        lo = std::min(lo, b);
        hi = std::max(hi, b);
    }
    EXPECT_GT(lo, 170.0f) << "the exposed roof is snow-white";
    EXPECT_LT(hi - lo, 3.0f) << "brightness varies down the slope: stripes";
}

TEST(RenderSnowCover, SurfacesReuploadOnlyWhenTheirSnowChanges) {
    FixtureScene scene;
    build_fixture(scene);
    auto context = headless_context();
    Renderer renderer(*context);
    renderer.render(scene.world, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 2u);
    EXPECT_EQ(renderer.timings().meshes_uploaded, scene.world.count<MeshRenderable>());
    renderer.render(scene.world, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 0u);
    EXPECT_EQ(renderer.timings().meshes_uploaded, 0u);
    const Image before = renderer.read_pixels();

    SnowSurface& roof = scene.world.get<SnowSurface>(scene.house_roof);
    for (std::uint32_t& cell : roof.snow) {
        cell += 100; // 0.2 m more snow everywhere on the roof
    }
    renderer.render(scene.world, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 1u);
    EXPECT_EQ(renderer.timings().surface_tiles_uploaded, 1u) << "the 30 x 30 roof is one tile";
    const Image after = renderer.read_pixels();
    EXPECT_GT(compare_images(before, after).pixels_over, 100u) << "the taller roof snow shows";

    // One ground cell changes: only its tile of the 48 x 48 ground goes up again.
    SnowSurface& ground = scene.world.get<SnowSurface>(scene.ground_surface);
    ground.snow[ground.index(40, 3)] += 1;
    renderer.render(scene.world, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 1u);
    EXPECT_EQ(renderer.timings().surface_tiles_uploaded, 1u);

    scene.world.destroy(scene.house_roof);
    renderer.render(scene.world, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 0u);
}

} // namespace
} // namespace snow::test
