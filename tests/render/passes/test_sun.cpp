// The sun (SceneVisuals::sun): cascades fitted to the view and snapped to
// whole texels [CSM] [MSDN-SM], shadows on the snow, the snow material under
// the filmic curve, the masks (AOVs), and measures of the image: shade turns
// blue, sunlit snow does not clip, shadows change the picture, detail normals
// and glints show, and the glints hold still as the camera turns.
#include "render/passes/sun_cascades.hpp"
#include "render/renderer_internals.hpp"
#include "tests/render/detail_bars.hpp"
#include "tests/render/render_fixture.hpp"
#include "tests/render/snow_image_measures.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace snow::test {
namespace {

const glm::vec3 test_sun_direction{-0.6f, 0.5f, 0.45f};

/// The fixture in sunshine: no lamps, a low sun from the left, in front.
void build_sunny_scene(FixtureScene& scene) {
    build_fixture(scene);
    scene.visuals.lights.clear();
    scene.visuals.sun = Sun{test_sun_direction, {1.0f, 0.95f, 0.86f}, 2.0f};
}

MaskedFrame render_sunny(const RenderSettings& settings = {}) {
    FixtureScene scene;
    build_sunny_scene(scene);
    auto context = headless_context();
    Renderer renderer(*context, settings);
    return render_masked(renderer,
                         [&] { render_world(renderer, scene.world, scene.visuals, scene.camera); });
}

TEST(SunCascades, EndAtTheShadowDistanceInGrowingSlices) {
    ViewCamera camera;
    const SunCascades c = fit_sun_cascades(camera, 4.0f / 3.0f, test_sun_direction, 40.0f, 512);
    EXPECT_FLOAT_EQ(c.far[2], 40.0f);
    EXPECT_LT(c.far[0], c.far[1]);
    EXPECT_LT(c.far[1] - c.far[0], c.far[2] - c.far[1]);
    EXPECT_LT(c.texel[0], c.texel[1]);
    EXPECT_LT(c.texel[1], c.texel[2]);
}

TEST(SunCascades, EveryPointOfASliceLandsInItsThirdOfTheAtlas) {
    ViewCamera camera;
    camera.position = {3.0f, 2.0f, 9.0f};
    camera.look_at({0.0f, 0.5f, 0.0f});
    const float aspect = 16.0f / 9.0f;
    const SunCascades c = fit_sun_cascades(camera, aspect, test_sun_direction, 30.0f, 1024);
    const float tan_y = std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
    const glm::vec3 up = glm::cross(camera.right(), camera.forward());
    for (int i = 0; i < sun_cascade_count; ++i) {
        const auto k = static_cast<std::size_t>(i);
        const float d = c.far[k] * 0.999f; // the slice's far corners, its widest part
        for (const float sx : {-1.0f, 1.0f}) {
            for (const float sy : {-1.0f, 1.0f}) {
                const glm::vec3 p = camera.position + camera.forward() * d +
                                    camera.right() * (sx * d * tan_y * aspect) +
                                    up * (sy * d * tan_y);
                const glm::vec4 a = c.to_atlas[k] * glm::vec4(p, 1.0f);
                EXPECT_GE(a.x, static_cast<float>(i) / 3.0f) << "cascade " << i;
                EXPECT_LE(a.x, static_cast<float>(i + 1) / 3.0f) << "cascade " << i;
                EXPECT_GE(a.y, 0.0f);
                EXPECT_LE(a.y, 1.0f);
                EXPECT_GT(a.z, 0.0f);
                EXPECT_LT(a.z, 1.0f);
            }
        }
    }
}

TEST(SunCascades, CameraMovesShiftTheMapsByWholeTexelsOnly) {
    // A fixed world point keeps its place within a texel however the camera
    // moves or turns: shadow edges do not crawl.
    ViewCamera camera;
    const int res = 1024;
    const glm::vec3 p{0.3f, 0.0f, -2.7f};
    auto texel_phase = [&](const SunCascades& c) {
        const glm::vec4 a = c.light_clip[0] * glm::vec4(p, 1.0f);
        const float tx = (a.x * 0.5f + 0.5f) * static_cast<float>(res);
        return tx - std::floor(tx);
    };
    const float phase0 =
        texel_phase(fit_sun_cascades(camera, 1.5f, test_sun_direction, 40.0f, res));
    for (int step = 1; step <= 20; ++step) {
        camera.position += glm::vec3(0.0137f, 0.0051f, -0.0093f);
        camera.turn(0.003f, 0.001f);
        const float phase =
            texel_phase(fit_sun_cascades(camera, 1.5f, test_sun_direction, 40.0f, res));
        const float off = std::abs(phase - phase0);
        EXPECT_LT(std::min(off, 1.0f - off), 2e-3f) << "step " << step;
    }
}

TEST(RenderSun, WithoutASunNothingOfItIsDrawnOrCompiled) {
    FixtureScene scene;
    build_fixture(scene);
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    const auto names = renderer.pass_names();
    EXPECT_EQ(std::count(names.begin(), names.end(), "sun_shadows"), 0);
    for (const std::string& v : renderer.compiled_variants()) {
        EXPECT_EQ(v.find("SUN"), std::string::npos) << v;
    }
    renderer.settings().output = RenderOutput::shadow_mask;
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    const Image shadow = renderer.read_pixels();
    std::size_t shadowed = 0;
    for (std::size_t i = 0; i < shadow.rgba.size(); i += 4) {
        shadowed += shadow.rgba[i] != 0 ? 1u : 0u;
    }
    EXPECT_EQ(shadowed, 0u);
}

TEST(RenderSun, ABadSunIsRefusedByItsField) {
    FixtureScene scene;
    build_sunny_scene(scene);
    scene.visuals.sun->direction = glm::vec3(0.0f);
    auto context = headless_context();
    Renderer renderer(*context);
    try {
        render_world(renderer, scene.world, scene.visuals, scene.camera);
        ADD_FAILURE() << "a sun without a direction was drawn";
    } catch (const RenderError& e) {
        EXPECT_NE(std::string(e.what()).find("sun.direction must be of length > 0"),
                  std::string::npos)
            << e.what();
    }
}

TEST(RenderSun, ShadowPassComesFirstAndCastersDrawDepthOnly) {
    FixtureScene scene;
    build_sunny_scene(scene);
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    EXPECT_EQ(renderer.pass_names().front(), "sun_shadows");
    const auto variants = renderer.compiled_variants();
    EXPECT_NE(std::find(variants.begin(), variants.end(), "mesh.vert+depth.frag[]"),
              variants.end());
}

TEST(RenderSun, SunnySceneShadeIsBlueAndSunlitSnowDoesNotClip) {
    const SnowLook look = measure_snow(render_sunny());
    std::printf("sunny scene: %zu snow px, %zu shadowed, %zu lit; shade B/R %.3f; clipped %.4f; "
                "lit luma %.1f ± %.2f\n",
                look.snow_pixels, look.shadowed_pixels, look.lit_pixels, look.shadow_blue_red,
                look.clipped_share, look.lit_luma_mean, look.lit_luma_stddev);
    ASSERT_GT(look.snow_pixels, 10000u);
    // The house and the shelter cast shadows of their own across the snow.
    EXPECT_GT(look.shadowed_pixels, look.snow_pixels / 50);
    EXPECT_GE(look.shadow_blue_red, 1.08);
    EXPECT_LE(look.clipped_share, 0.01);
    EXPECT_GT(look.lit_luma_mean, 180.0); // sunlit snow is bright
}

TEST(RenderSun, TurningShadowsOffChangesTheImage) {
    const MaskedFrame with = render_sunny();
    RenderSettings off;
    off.sun_shadows = false;
    const MaskedFrame without = render_sunny(off);
    const ImageComparison c = compare_images(with.color, without.color);
    const std::size_t pixels = static_cast<std::size_t>(with.color.width) * with.color.height;
    EXPECT_GT(c.pixels_over, pixels / 50) << "worst " << c.worst;
    EXPECT_GT(c.worst, 40);
    EXPECT_EQ(measure_snow(without).shadowed_pixels, 0u);
}

TEST(RenderSun, SnowMaskIsBlackOverTheSkyAndWhiteOverGroundSnow) {
    FixtureScene scene;
    build_sunny_scene(scene);
    const MaskedFrame f = render_sunny();
    // The top row is sky; the ground snow in front of the shelter is snow.
    EXPECT_EQ(f.snow.pixel(golden_width / 2, 0)[0], 0);
    const glm::ivec2 front = to_pixel(scene.camera, {2.0f, 0.06f, 4.0f});
    EXPECT_GT(f.snow.pixel(front.x, front.y)[0], 200);
    EXPECT_EQ(f.snow.width, f.color.width);
    EXPECT_EQ(f.shadow.height, f.color.height);
}

TEST(RenderSun, DetailNormalsAndGlintsShowAndHoldStillAsTheCameraTurns) {
    FixtureScene scene;
    build_sunny_scene(scene);
    auto context = headless_context();
    Renderer renderer(*context);
    const DetailLook d = measure_detail(renderer, scene.camera, [&](const ViewCamera& c) {
        render_world(renderer, scene.world, scene.visuals, c);
    });
    print_detail("sunny fixture 320x240", d);
    expect_detail_bars(d);
}

/// The ground in front of the shelter raised to 20 cm of flat snow over
/// x 0..4, z 3..5, with (`trench`) a trench 2 cm deep at the bottom along
/// z 3.75..4.25.
Image render_snow_bank(bool trench) {
    FixtureScene scene;
    build_sunny_scene(scene);
    SnowSurface& ground = scene.world.get<SnowSurface>(scene.ground_surface);
    for (std::uint32_t iz = 0; iz < ground.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < ground.nx; ++ix) {
            const float x = ground.x0 + (static_cast<float>(ix) + 0.5f) * ground.cell;
            const float z = ground.z0 + (static_cast<float>(iz) + 0.5f) * ground.cell;
            const bool bank = x > 0.0f && x < 4.0f && z > 3.0f && z < 5.0f;
            const bool floor = trench && bank && z > 3.75f && z < 4.25f;
            if (bank) {
                ground.snow[ground.index(ix, iz)] = static_cast<std::uint32_t>(
                    std::lround((floor ? 0.02f : 0.2f) / fixture_unit_height));
            }
        }
    }
    return render_image(scene.world, scene.visuals, scene.camera);
}

TEST(RenderSun, ATrenchFloorIsBluerThanLevelSnow) {
    FixtureScene scene;
    build_sunny_scene(scene);
    const glm::ivec2 floor = to_pixel(scene.camera, {2.0f, 0.02f, 4.0f});
    const glm::vec3 in_trench = mean_color(render_snow_bank(true), floor, 2);
    const glm::vec3 level = mean_color(render_snow_bank(false), floor, 2);
    const float trench_blue_red = in_trench.b / in_trench.r, level_blue_red = level.b / level.r;
    std::printf("trench floor B/R %.3f, level snow B/R %.3f\n", trench_blue_red, level_blue_red);
    EXPECT_GT(trench_blue_red, 1.05f * level_blue_red);
}

} // namespace
} // namespace snow::test
