// The village in sunshine (assets/scenes/village_effects.gltf declares a
// sun), measured on the image at 1280×720 with its masks: shaded snow is
// blue, sunlit snow does not clip, the shadows are there to see, the detail
// normals and glints show and the glints hold still as the camera turns.
#include "tests/render/detail_bars.hpp"
#include "tests/render/render_fixture.hpp"
#include "tests/render/snow_image_measures.hpp"
#include <snow/scene.hpp>

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace snow::test {
namespace {

constexpr int village_width = 1280;
constexpr int village_height = 720;

SceneLoadResult village_after_240_ticks() {
    SceneLoadResult r =
        load_scene_file(std::string(SNOW_SOURCE_DIR) + "/assets/scenes/village_effects.gltf");
    if (r.sim != nullptr) {
        r.sim->run(240);
    }
    return r;
}

TEST(RenderSunlitVillage, ShadeIsBlueAndSunlitSnowDoesNotClip) {
    SceneLoadResult r = village_after_240_ticks();
    ASSERT_NE(r.sim, nullptr) << r.error;
    ASSERT_TRUE(r.visuals.sun.has_value());
    const ViewCamera camera = ViewCamera::from_def(r.visuals.camera);
    auto context = headless_context(village_width, village_height);
    Renderer renderer(*context);
    const MaskedFrame sunny =
        render_masked(renderer, [&] { renderer.render(*r.sim, r.visuals, camera); });
    const SnowLook look = measure_snow(sunny);

    // The same moment as the renderer drew it before it knew the sun, seen
    // through the sunny frame's masks.
    SceneVisuals sunless = r.visuals;
    sunless.sun.reset();
    renderer.render(*r.sim, sunless, camera);
    const SnowLook before =
        measure_snow(MaskedFrame{renderer.read_pixels(), sunny.snow, sunny.shadow});

    std::printf("village 1280x720: %zu snow px, %zu shadowed, %zu lit; shade B/R %.3f; "
                "clipped %.4f; lit luma %.1f ± %.2f (without the sun: %.1f ± %.2f)\n",
                look.snow_pixels, look.shadowed_pixels, look.lit_pixels, look.shadow_blue_red,
                look.clipped_share, look.lit_luma_mean, look.lit_luma_stddev, before.lit_luma_mean,
                before.lit_luma_stddev);
    ASSERT_GT(look.snow_pixels, 100000u);
    EXPECT_GT(look.shadowed_pixels, look.snow_pixels / 50); // the houses' shadows
    EXPECT_GE(look.shadow_blue_red, 1.08);
    EXPECT_LE(look.clipped_share, 0.01);
}

TEST(RenderSunlitVillage, DetailNormalsAndGlintsShowAndHoldStillAsTheCameraTurns) {
    SceneLoadResult r = village_after_240_ticks();
    ASSERT_NE(r.sim, nullptr) << r.error;
    auto context = headless_context(village_width, village_height);
    Renderer renderer(*context);
    const DetailLook d =
        measure_detail(renderer, ViewCamera::from_def(r.visuals.camera),
                       [&](const ViewCamera& c) { renderer.render(*r.sim, r.visuals, c); });
    print_detail("village 1280x720", d);
    expect_detail_bars(d);
    // Half as much again as before the sun, when the lamps' falloff spread
    // it 15.09 (docs/rendering.md).
    EXPECT_GE(d.look.lit_luma_stddev, 1.5 * 15.09);
}

} // namespace
} // namespace snow::test
