// Snow on surfaces: sky exposure and incline [SKY], heightfields with
// skirts [WF §6] that leave no crack at borders, eaves or between levels
// of detail, re-upload of the changed tiles only.
#include "render/renderer_internals.hpp"
#include "systems/sky/occlusion.hpp"
#include "tests/render/render_fixture.hpp"

#include <algorithm>
#include <cmath>
#include <string>

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
    const Image image = render_image(scene.world, scene.visuals, scene.camera);
    const glm::vec3 roof = mean_color(image, to_pixel(scene.camera, {2.0f, 2.15f, 0.0f}), 2);
    const glm::vec3 crate = mean_color(image, to_pixel(scene.camera, {2.0f, 0.7f, 0.3f}), 2);
    EXPECT_GT(brightness(roof), 170.0f);
    EXPECT_LT(saturation(roof), 40.0f);
    EXPECT_LT(brightness(crate), 0.6f * brightness(roof));
    EXPECT_GT(crate.x, crate.z + 15.0f) << "the crate keeps its own (brown) colour";

    // Without a sky map the simulation tracks no snow on the meshes, so none
    // is drawn on them: the crate top stays as dark as under the roof (it
    // does not turn white as if the sky saw it).
    scene.world.erase_resource<OcclusionMap>();
    const Image bare = render_image(scene.world, scene.visuals, scene.camera);
    const glm::vec3 crate_bare = mean_color(bare, to_pixel(scene.camera, {2.0f, 0.7f, 0.3f}), 2);
    EXPECT_NEAR(brightness(crate_bare), brightness(crate), 10.0f);
}

TEST(RenderSnowCover, InclineCoefficientLeavesWallsUncovered) {
    FixtureScene scene;
    build_fixture(scene);
    RenderSettings bare;
    bare.mesh_snow = 0.0f;
    const Image with_snow = render_image(scene.world, scene.visuals, scene.camera);
    const Image without = render_image(scene.world, scene.visuals, scene.camera, bare);
    // The house's front wall faces +z: dot(N, up) = 0, so snow never shows [SKY step 3].
    const glm::ivec2 wall = to_pixel(scene.camera, {-2.5f, 1.0f, 1.0f});
    EXPECT_EQ(mean_color(with_snow, wall, 2), mean_color(without, wall, 2));
    // The shelter's roof faces up and is exposed: snow makes it much brighter.
    const glm::ivec2 roof = to_pixel(scene.camera, {2.0f, 2.15f, 0.0f});
    EXPECT_GT(brightness(mean_color(with_snow, roof, 2)),
              brightness(mean_color(without, roof, 2)) + 60.0f);
}

/// The 30° test roofs below, seen from one camera: (darkest, brightest) pixel
/// along a line down the slope at height y0 + 0.58·x, x from 0.2 to 2.8 m.
/// A plane under the sun and the sky is lit evenly, so the two must agree.
glm::vec2 brightness_down_the_slope(const World& world, const SceneVisuals& visuals, float y0) {
    ViewCamera camera;
    camera.position = {-1.0f, 4.6f, 1.8f};
    camera.look_at({1.5f, 2.9f, 0.0f});
    const Image image = render_image(world, visuals, camera);
    glm::vec2 range(255.0f, 0.0f);
    for (int k = 0; k <= 400; ++k) {
        const float x = 0.2f + 2.6f * static_cast<float>(k) / 400.0f;
        const float b =
            brightness(mean_color(image, to_pixel(camera, {x, y0 + 0.58f * x, 0.3f}), 0));
        range = {std::min(range.x, b), std::max(range.y, b)};
    }
    return range;
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
    SceneVisuals visuals;
    constexpr float slope = 0.58f; // as brightness_down_the_slope looks along
    MeshRenderable roof;
    roof.name = "roof";
    roof.positions = {{0.0f, 2.0f, -1.5f},
                      {3.0f, 2.0f + 3.0f * slope, -1.5f},
                      {3.0f, 2.0f + 3.0f * slope, 1.5f},
                      {0.0f, 2.0f, 1.5f}};
    roof.normals.assign(4, glm::normalize(glm::vec3(-slope, 1.0f, 0.0f)));
    roof.indices = {0, 2, 1, 0, 3, 2};
    roof.color = {0.35f, 0.12f, 0.10f};
    visuals.meshes.push_back(std::move(roof));
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
    const glm::vec2 range = brightness_down_the_slope(world, visuals, 2.0f);
    EXPECT_GT(range.x, 170.0f) << "the exposed roof is snow-white";
    EXPECT_LT(range.y - range.x, 3.0f) << "brightness varies down the slope: stripes";
}

/// True when the pixel is (close to) the clear colour: nothing was drawn there.
bool background(const Image& image, glm::ivec2 px, const glm::vec3& sky) {
    const glm::vec3 c = mean_color(image, px, 0);
    return std::max({std::abs(c.x - sky.x), std::abs(c.y - sky.y), std::abs(c.z - sky.z)}) < 3.0f;
}

/// Snow over a bare top with an edge: a 2 m high roof (x < 2) next to the
/// ground (x ≥ 2), 5 cm of snow everywhere; no meshes, so every pixel not
/// drawn by the snow shows the sky.
struct EavesScene {
    World world;
    SceneVisuals visuals;
    glm::vec3 sky{0.0f};
    EavesScene() {
        SnowSurface s = flat_surface(0.0f, 0.0f, 4.0f, 2.0f, 0.05f, 0.0f);
        for (std::uint32_t z = 0; z < s.nz; ++z) {
            for (std::uint32_t x = 0; x < s.nx; ++x) {
                const std::size_t i = s.index(x, z);
                s.base_level[i] = x < 40 ? std::llround(2.0f / s.unit_height) : 0;
                s.snow[i] = 25; // 5 cm
            }
        }
        world.add<SnowSurface>(world.create(), std::move(s));
        sky = visuals.environment.sky * 255.0f;
    }
    /// Renders the view from `eye` toward `target`.
    void look(const glm::vec3& eye, const glm::vec3& target) {
        camera.position = eye;
        camera.look_at(target);
        image = render_image(world, visuals, camera);
    }
    /// True when snow was drawn where p lies in the last view.
    [[nodiscard]] bool snow_at(const glm::vec3& p) const {
        return !background(image, to_pixel(camera, p), sky);
    }
    ViewCamera camera;
    Image image;
};

TEST(RenderSnowCover, EavesHangNoCurtainDownToTheGround) {
    EavesScene scene;
    scene.look({2.0f, 1.2f, 6.0f}, {2.0f, 1.0f, 1.0f});
    // Between the roof's snow (2.0–2.05 m) and the ground's (0–0.05 m) at the
    // edge there is nothing: a heightfield joining them would hang a sheet of
    // snow from the eaves to the ground. (The sight lines to these points pass
    // over the ground snow behind and under the roof snow.)
    int curtain = 0;
    for (const float x : {1.97f, 2.0f, 2.03f}) {
        for (float y = 0.6f; y < 1.75f; y += 0.1f) {
            curtain += scene.snow_at({x, y, 2.0f}) ? 1 : 0;
        }
    }
    EXPECT_EQ(curtain, 0) << "snow drawn between the eaves and the ground";
    // Both snow layers themselves are drawn.
    EXPECT_TRUE(scene.snow_at({1.0f, 2.04f, 2.0f}));
    EXPECT_TRUE(scene.snow_at({3.0f, 0.04f, 2.0f}));
}

TEST(RenderSnowCover, SnowEndsInASideDownToTheBareTopAtBordersAndEaves) {
    EavesScene scene;
    // From the front, a little above: the roof snow's front side (z = 2, from
    // 2.05 m down to its bare top at 2 m) hides the sky behind it.
    scene.look({1.0f, 2.4f, 4.0f}, {1.0f, 2.0f, 1.0f});
    for (const float x : {0.5f, 1.0f, 1.5f}) {
        EXPECT_TRUE(scene.snow_at({x, 2.02f, 2.0f}))
            << "a crack under the snow's edge at the border, x = " << x;
    }
    // From beside the eaves: the roof snow ends in a side facing the drop.
    scene.look({3.5f, 2.3f, 1.0f}, {2.0f, 2.02f, 1.0f});
    for (const float z : {0.6f, 1.0f, 1.4f}) {
        EXPECT_TRUE(scene.snow_at({1.975f, 2.02f, z}))
            << "a crack under the snow's edge at the eaves, z = " << z;
    }
}

TEST(RenderSnowCover, LevelsOfDetailMeetWithoutCracks) {
    // Bumpy ground 40 m across under 10 cm of snow, seen low from the side:
    // near tiles at full detail, far ones coarse. Where levels meet, a crack
    // would show the black sky through the snow.
    World world;
    SnowSurface s = flat_surface(-20.0f, -20.0f, 40.0f, 40.0f, 0.1f, 0.0f);
    for (std::uint32_t z = 0; z < s.nz; ++z) {
        for (std::uint32_t x = 0; x < s.nx; ++x) {
            const double wx = s.x0 + (x + 0.5) * s.cell, wz = s.z0 + (z + 0.5) * s.cell;
            // Bumps 2 m apart, as steep as 1.5 m per m: coarse levels cut
            // corners by many centimetres.
            const double base = 1.0 + 0.5 * std::sin(3.0 * wx) * std::cos(3.0 * wz);
            s.base_level[s.index(x, z)] = std::llround(base / s.unit_height);
            s.snow[s.index(x, z)] = 50;
        }
    }
    world.add<SnowSurface>(world.create(), std::move(s));
    SceneVisuals visuals;
    visuals.environment.sky = glm::vec3(0.0f);
    ViewCamera camera;
    camera.position = {0.0f, 3.5f, 22.0f};
    camera.look_at({0.0f, 0.5f, 0.0f});
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, world, visuals, camera);
    const Image image = renderer.read_pixels();
    EXPECT_GT(renderer.timings().surface_tiles_drawn, 60u);
    // In each column, below the first snow pixel from the top (the hills'
    // outline against the sky), every pixel down to the image's bottom is snow.
    std::size_t cracks = 0, snow = 0;
    for (int x = 0; x < image.width; ++x) {
        bool below_outline = false;
        for (int y = 0; y < image.height; ++y) {
            const bool sky =
                image.pixel(x, y)[0] + image.pixel(x, y)[1] + image.pixel(x, y)[2] == 0;
            below_outline = below_outline || !sky;
            cracks += below_outline && sky ? 1 : 0;
            snow += sky ? 0 : 1;
        }
    }
    EXPECT_GT(snow, image.rgba.size() / 4 / 2) << "the hills fill most of the view";
    EXPECT_EQ(cracks, 0u);
}

TEST(RenderSnowCover, SnowOnASlopedRoofIsEvenWithoutStripes) {
    // A 30° roof surface as in the village (0.1 m cells, bare top quantised to
    // whole snow units per cell) under an even 3 cm of snow: the heightfield
    // and its normals must be as even as the plane.
    World world;
    SurfaceDef def;
    def.x0 = 0.0f;
    def.z0 = -1.5f;
    def.size_x = 3.0f;
    def.size_z = 3.0f;
    def.cell = 0.1f;
    def.base_y = 2.0f;
    def.slope_x = 0.58f;
    SnowSurface roof = make_surface(def);
    const auto units = static_cast<std::uint32_t>(std::lround(0.03 / roof.unit_height));
    std::fill(roof.snow.begin(), roof.snow.end(), units);
    world.add<SnowSurface>(world.create(), std::move(roof));
    const glm::vec2 range = brightness_down_the_slope(world, SceneVisuals{}, 2.03f);
    EXPECT_GT(range.x, 150.0f) << "the roof is covered";
    EXPECT_LT(range.y - range.x, 3.0f) << "brightness varies down the slope: stripes";
}

TEST(RenderSnowCover, SurfacesReuploadOnlyWhenTheirSnowChanges) {
    FixtureScene scene;
    build_fixture(scene);
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 2u);
    EXPECT_EQ(renderer.timings().meshes_uploaded, scene.visuals.meshes.size());
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 0u);
    EXPECT_EQ(renderer.timings().meshes_uploaded, 0u);
    const Image before = renderer.read_pixels();

    SnowSurface& roof = scene.world.get<SnowSurface>(scene.house_roof);
    for (std::uint32_t& cell : roof.snow) {
        cell += 100; // 0.2 m more snow everywhere on the roof
    }
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 1u);
    EXPECT_EQ(renderer.timings().surface_tiles_uploaded, 1u) << "the 30 x 30 roof is one tile";
    const Image after = renderer.read_pixels();
    EXPECT_GT(compare_images(before, after).pixels_over, 100u) << "the taller roof snow shows";

    // One ground cell changes: only its tile of the 48 x 48 ground goes up again.
    SnowSurface& ground = scene.world.get<SnowSurface>(scene.ground_surface);
    ground.snow[ground.index(40, 3)] += 1;
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 1u);
    EXPECT_EQ(renderer.timings().surface_tiles_uploaded, 1u);

    scene.world.destroy(scene.house_roof);
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    EXPECT_EQ(renderer.timings().surfaces_uploaded, 0u);
}

} // namespace
} // namespace snow::test
