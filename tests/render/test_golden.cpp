// Golden images of the fixture scene on OSMesa/llvmpipe at 320x240 (output is
// bit-identical across thread counts: docs/toolchain.md). Regenerate with
// SNOW_UPDATE_GOLDEN=1 after an intended change, and look at the images.
#include "render_fixture.hpp"

#include <gtest/gtest.h>

#include <optional>

namespace snow::test {
namespace {

Image render_fixture(const std::optional<Fog>& fog) {
    FixtureScene scene;
    build_fixture(scene);
    scene.visuals.fog = fog;
    return render_image(scene.world, scene.visuals, scene.camera);
}

TEST(RenderGolden, SceneWithoutFog) {
    EXPECT_TRUE(matches_golden(render_fixture(std::nullopt), "scene_nofog"));
}

TEST(RenderGolden, SceneExponentialFog) {
    Fog fog;
    fog.mode = FogMode::exponential;
    fog.density = 0.06f;
    EXPECT_TRUE(matches_golden(render_fixture(fog), "scene_fog_exponential"));
}

TEST(RenderGolden, SceneHalfLifeFog) {
    Fog fog;
    fog.mode = FogMode::half_life;
    fog.half_distance = 9.0f;
    EXPECT_TRUE(matches_golden(render_fixture(fog), "scene_fog_half_life"));
}

TEST(RenderGolden, SceneLayeredFog) {
    Fog fog;
    fog.mode = FogMode::layered;
    fog.layer_bottom = 0.0f;
    fog.layer_top = 1.5f;
    fog.layer_density = 0.35f;
    EXPECT_TRUE(matches_golden(render_fixture(fog), "scene_fog_layered"));
}

} // namespace
} // namespace snow::test
