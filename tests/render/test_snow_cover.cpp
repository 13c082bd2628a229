// Snow on surfaces: sky exposure and incline [SKY], heightfield meshes
// with aprons [WF §6], re-upload only when snow changed.
#include "render/renderer.hpp"
#include "render/surface_mesh.hpp"
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
    // The house's front wall faces +z: dot(N, up) = 0, so snow never shows [SKY step 3].
    const glm::ivec2 wall = to_pixel(scene.camera, {-2.5f, 1.0f, 1.0f});
    EXPECT_EQ(mean_color(with_snow, wall, 2), mean_color(without, wall, 2));
    // The shelter's roof faces up and is exposed: snow makes it much brighter.
    const glm::ivec2 roof = to_pixel(scene.camera, {2.0f, 2.15f, 0.0f});
    EXPECT_GT(brightness(mean_color(with_snow, roof, 2)),
              brightness(mean_color(without, roof, 2)) + 60.0f);
}

TEST(RenderSnowCover, SurfaceMeshHasHeightsNormalsAndApron) {
    SnowSurface s = flat_surface(0.0f, 0.0f, 0.2f, 0.1f, 0.1f, 1.0f); // 2 x 1 cells
    s.snow = {50, 150};                                               // 0.1 m and 0.3 m
    std::vector<float> v;
    std::vector<std::uint32_t> idx;
    build_surface_mesh(s, v, &idx);
    const std::size_t grid = 3 * 2, apron = 2 * (3 + 3) + 2 * (2 + 2);
    ASSERT_EQ(v.size(), (grid + apron) * surface_vertex_floats);
    EXPECT_EQ(idx.size(), 2u * 6u + 2u * (2u + 1u) * 6u);
    const auto at = [&](std::size_t vertex, std::size_t k) {
        return v[vertex * surface_vertex_floats + k];
    };
    // Corners: x = 0 sees cell 0 only, x = 0.1 averages both, x = 0.2 sees cell 1.
    EXPECT_NEAR(at(0, 1), 1.1f, 1e-5f);
    EXPECT_NEAR(at(1, 1), 1.2f, 1e-5f);
    EXPECT_NEAR(at(2, 1), 1.3f, 1e-5f);
    EXPECT_NEAR(at(1, 6), 0.2f, 1e-5f); // depth above the bare top
    // Snow rises toward +x, so the normal leans toward −x.
    EXPECT_LT(at(1, 3), -0.5f);
    EXPECT_GT(at(1, 4), 0.5f);
    // Every apron vertex pair: top at the snow, bottom at the bare top (y = 1).
    for (std::size_t a = grid; a < grid + apron; a += 2) {
        EXPECT_NEAR(at(a + 1, 1), 1.0f, 1e-5f);
        EXPECT_GE(at(a, 1), 1.1f - 1e-5f);
        EXPECT_EQ(at(a, 3), at(a + 1, 3)); // same outward normal
    }
    for (const std::uint32_t i : idx) {
        EXPECT_LT(i, grid + apron);
    }
}

TEST(RenderSnowCover, MalformedSurfaceBuildsNothing) {
    SnowSurface s = flat_surface(0.0f, 0.0f, 1.0f, 1.0f, 0.1f, 0.0f);
    s.snow.pop_back();
    std::vector<float> v{1.0f};
    std::vector<std::uint32_t> idx{1u};
    build_surface_mesh(s, v, &idx);
    EXPECT_TRUE(v.empty());
    EXPECT_TRUE(idx.empty());
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
    const Image after = renderer.read_pixels();
    EXPECT_GT(compare_images(before, after).pixels_over, 100u) << "the taller roof snow shows";

    scene.world.destroy(scene.house_roof);
    renderer.render(scene.world, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 0u);
}

} // namespace
} // namespace snow::test
