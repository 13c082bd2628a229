// Fog ([PE], [SKY]): the E(y) table, where fog changes the image, and that a
// world without Fog compiles and runs no fog code.
#include "render/passes/fog_table.hpp"
#include "render/renderer_internals.hpp"
#include "tests/render/render_fixture.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace snow::test {
namespace {

Fog layer(float bottom, float top, float density) {
    Fog f;
    f.mode = FogMode::layered;
    f.layer_bottom = bottom;
    f.layer_top = top;
    f.layer_density = density;
    return f;
}

/// Mean absolute channel difference between two images over a square.
float mean_diff(const Image& a, const Image& b, glm::ivec2 px, int r) {
    const glm::vec3 d = glm::abs(mean_color(a, px, r) - mean_color(b, px, r));
    return (d.x + d.y + d.z) / 3.0f;
}

TEST(RenderFog, LayeredTableMatchesClosedForm) {
    const Fog f = layer(-1.0f, 3.0f, 0.4f);
    const auto table = layered_fog_table(f, fog_table_size);
    ASSERT_EQ(table.size(), fog_table_size);
    const double h = 4.0;
    for (std::size_t i = 0; i < table.size(); ++i) {
        const double t = static_cast<double>(i) / (table.size() - 1);
        // density = p(1 − 3t² + 2t³)  →  E = p·h·(t − t³ + t⁴/2)
        const double expected = 0.4 * h * (t - t * t * t + 0.5 * t * t * t * t);
        EXPECT_NEAR(table[i].x, expected, 1e-5) << "i=" << i;
        EXPECT_NEAR(table[i].y, 0.4 * (1.0 - 3.0 * t * t + 2.0 * t * t * t), 1e-5);
    }
    EXPECT_NEAR(table.back().x, 0.4 * h / 2.0, 1e-5); // whole layer: p·h/2
}

TEST(RenderFog, LayerDensityIsZeroOutsideAndTableEmptyForNoLayer) {
    const Fog f = layer(0.0f, 2.0f, 0.5f);
    EXPECT_EQ(layered_fog_density(f, -0.01f), 0.0f);
    EXPECT_EQ(layered_fog_density(f, 2.01f), 0.0f);
    EXPECT_FLOAT_EQ(layered_fog_density(f, 0.0f), 0.5f);
    EXPECT_TRUE(layered_fog_table(layer(1.0f, 1.0f, 0.5f), 16).empty());
    EXPECT_TRUE(layered_fog_table(layer(2.0f, 1.0f, 0.5f), 16).empty());
    EXPECT_TRUE(layered_fog_table(layer(0.0f, INFINITY, 0.5f), 16).empty());
    EXPECT_TRUE(layered_fog_table(layer(0.0f, 1.0f, NAN), 16).empty());
}

/// A plain snowless ground plane seen from `eye_y`, looking along −z, 10° down.
struct OpenField {
    World world;
    SceneVisuals visuals;
    ViewCamera camera;
    RenderSettings settings;
    explicit OpenField(float eye_y) {
        MeshRenderable ground;
        ground.positions = {{-200, 0, -200}, {200, 0, -200}, {200, 0, 200}, {-200, 0, 200}};
        ground.normals.assign(4, {0.0f, 1.0f, 0.0f});
        ground.indices = {0, 2, 1, 0, 3, 2};
        ground.color = {0.8f, 0.8f, 0.8f};
        visuals.meshes.push_back(ground);
        camera.position = {0.0f, eye_y, 0.0f};
        camera.pitch = -0.1745f;
        settings.mesh_snow = 0.0f;
    }
    [[nodiscard]] Image render() const { return render_image(world, visuals, camera, settings); }
};

TEST(RenderFog, NonFiniteFogNumbersGiveNoFogNotGarbage) {
    OpenField field(1.5f);
    const Image clear = field.render();
    Fog exponential;
    exponential.density = NAN;
    Fog half_life;
    half_life.mode = FogMode::half_life;
    half_life.half_distance = -INFINITY;
    for (const Fog& bad :
         {exponential, half_life, layer(NAN, 1.0f, 0.5f), layer(0.0f, 1.0f, NAN)}) {
        field.visuals.fog = bad;
        const ImageComparison c = compare_images(field.render(), clear);
        EXPECT_EQ(c.pixels_over, 0u) << "fog mode " << static_cast<int>(bad.mode);
    }
}

TEST(RenderFog, ExponentialFogChangesFarPixelsMuchMoreThanNear) {
    OpenField field(1.5f);
    const Image clear = field.render();
    Fog fog;
    fog.mode = FogMode::exponential;
    fog.density = 0.02f;
    fog.color = {0.0f, 0.0f, 0.0f};
    field.visuals.fog = fog;
    const Image fogged = field.render();
    // Near: the bottom of the image (~2.6 m away); far: ground 40 m away.
    const glm::ivec2 near_px{golden_width / 2, golden_height - 3};
    const glm::ivec2 far_px = to_pixel(field.camera, {0.0f, 0.0f, -40.0f});
    const float near = mean_diff(clear, fogged, near_px, 2);
    const float far = mean_diff(clear, fogged, far_px, 2);
    EXPECT_LT(near, 0.08f * mean_color(clear, near_px, 2).x); // e^(−0.02·2.6) ≈ 0.95
    EXPECT_GT(far, 0.4f * mean_color(clear, far_px, 2).x);    // e^(−0.02·40) ≈ 0.45
    EXPECT_GT(far, 5.0f * near);
}

TEST(RenderFog, LayeredFogLeavesRaysAboveTheLayerUntouched) {
    OpenField field(3.0f);
    const Image clear = field.render();
    Fog fog = layer(0.0f, 1.0f, 0.5f);
    fog.color = {0.0f, 0.0f, 0.0f};
    field.visuals.fog = fog;
    const Image fogged = field.render();
    // The eye is above the layer: rays that go up never enter it.
    EXPECT_LT(mean_diff(clear, fogged, {golden_width / 2, 4}, 3), 0.5f);
    // Ground rays cross the whole layer, slanted: (E(top) − E(0)) / cos θ grows with distance.
    const float near = mean_diff(clear, fogged, {golden_width / 2, golden_height - 3}, 2);
    const float far = mean_diff(clear, fogged, to_pixel(field.camera, {0.0f, 0.0f, -40.0f}), 2);
    EXPECT_GT(near, 0.15f * mean_color(clear, {golden_width / 2, golden_height - 3}, 2).x);
    EXPECT_GT(far, 2.0f * near);
}

TEST(RenderFog, WorldWithoutFogCompilesAndRunsNoFogCode) {
    FixtureScene scene;
    build_fixture(scene);
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    for (const std::string& v : renderer.compiled_variants()) {
        EXPECT_EQ(v.find("FOG"), std::string::npos) << v;
    }
    EXPECT_FALSE(renderer.timings().passes.at(1).ran) << "the fogged sky pass ran";
    EXPECT_EQ(renderer.timings().passes.at(1).name, "sky");

    scene.visuals.fog = layer(0.0f, 1.0f, 0.5f);
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    EXPECT_TRUE(renderer.timings().passes.at(1).ran);
    std::size_t fog_variants = 0;
    for (const std::string& v : renderer.compiled_variants()) {
        fog_variants += v.find("FOG_LAYERED") != std::string::npos ? 1u : 0u;
    }
    EXPECT_EQ(fog_variants, 4u); // sky, meshes, snow surfaces, flakes
}

} // namespace
} // namespace snow::test
