// Fog puffs [PE]: the closed-form line integrals of Gaussian and Gabor
// puffs against numeric integration, on the CPU (double) and in the shader
// (float, through a probe that runs the pass's GLSL), and the pass itself.
#include "render/passes/fog_puffs.hpp"
#include "render/renderer_internals.hpp"
#include "tests/render/render_fixture.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

namespace snow::test {
namespace {

FogPuff gaussian(glm::vec3 c, float sigma, float density) {
    FogPuff p;
    p.center = c;
    p.sigma = sigma;
    p.density = density;
    return p;
}

FogPuff gabor(glm::vec3 c, float sigma, float density, glm::vec3 k, float phase) {
    FogPuff p = gaussian(c, sigma, density);
    p.frequency = k;
    p.phase = phase;
    return p;
}

/// Composite Simpson over the segment: the reference the closed forms must meet.
double numeric_depth(const std::vector<FogPuff>& puffs, const glm::dvec3& a, const glm::dvec3& b) {
    constexpr int steps = 40000;
    const glm::dvec3 d = (b - a) / static_cast<double>(steps);
    double sum = 0.0;
    for (int i = 0; i <= steps; ++i) {
        const double w = (i == 0 || i == steps) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
        double density = 0.0;
        for (const FogPuff& p : puffs) {
            density += puff_density(p, a + d * static_cast<double>(i));
        }
        sum += w * density;
    }
    return sum * glm::length(d) / 3.0;
}

/// Puffs and segments that cover the cases: through the centre, grazing,
/// starting or ending inside, far away, along and across the Gabor waves.
struct Case {
    std::vector<FogPuff> puffs;
    glm::vec3 a, b;
};

std::vector<Case> cases() {
    const FogPuff g = gaussian({1.0f, 2.0f, -3.0f}, 1.5f, 0.3f);
    const FogPuff wave_x = gabor({0.0f, 1.0f, 0.0f}, 1.0f, 0.8f, {3.0f, 0.0f, 0.0f}, 0.4f);
    const FogPuff wave_diag = gabor({2.0f, 0.5f, 1.0f}, 0.7f, 1.2f, {2.0f, -1.5f, 4.0f}, -1.1f);
    const FogPuff fine = gabor({-1.0f, 2.0f, 0.0f}, 2.0f, 0.5f, {0.0f, 6.0f, 2.0f}, 2.0f);
    return {
        {{g}, {1.0f, 2.0f, 10.0f}, {1.0f, 2.0f, -20.0f}},        // straight through
        {{g}, {-6.0f, 3.5f, 5.0f}, {8.0f, 1.0f, -9.0f}},         // slanted, off centre
        {{g}, {1.0f, 2.0f, 10.0f}, {1.0f, 2.3f, -3.2f}},         // ends in the middle
        {{g}, {1.2f, 2.0f, -3.0f}, {30.0f, -4.0f, 8.0f}},        // starts in the middle
        {{g}, {20.0f, 0.0f, 0.0f}, {25.0f, 9.0f, 3.0f}},         // far away: ~0
        {{wave_x}, {-8.0f, 1.0f, 0.0f}, {8.0f, 1.0f, 0.0f}},     // along the waves
        {{wave_x}, {-8.0f, 1.2f, 0.3f}, {0.4f, 1.0f, 0.0f}},     // along, ends inside
        {{wave_x}, {0.3f, 1.0f, -8.0f}, {0.3f, 1.0f, 8.0f}},     // across the waves
        {{wave_diag}, {-3.0f, 4.0f, 6.0f}, {2.2f, 0.4f, 0.9f}},  // ends inside
        {{wave_diag}, {2.1f, 0.6f, 1.1f}, {-9.0f, -2.0f, 3.0f}}, // starts inside
        {{fine}, {-1.0f, -6.0f, 0.5f}, {-1.0f, 2.4f, 0.2f}},     // fine waves, ends inside
        {{fine}, {-7.0f, 3.0f, 4.0f}, {6.0f, 1.0f, -5.0f}},      // fine waves, through
        {{g, wave_x, wave_diag, fine}, {0.0f, 4.0f, 12.0f}, {0.5f, 0.5f, -10.0f}}, // several
    };
}

TEST(FogPuffs, ClosedFormMatchesNumericIntegrationOnTheCpu) {
    for (const Case& c : cases()) {
        const double exact = puffs_optical_depth(c.puffs, c.a, c.b);
        const double numeric = numeric_depth(c.puffs, c.a, c.b);
        EXPECT_NEAR(exact, numeric, 1e-9 + 1e-7 * numeric)
            << "a=(" << c.a.x << "," << c.a.y << "," << c.a.z << ")";
        EXPECT_GE(exact, -1e-12);
    }
}

TEST(FogPuffs, WholeLineThroughAGaussianHasItsTextbookValue) {
    const FogPuff p = gaussian({0.0f, 0.0f, 0.0f}, 2.0f, 0.25f);
    const double h = 1.5; // miss distance
    const double expected =
        0.25 * 2.0 * std::sqrt(2.0 * std::numbers::pi) * std::exp(-h * h / (2.0 * 4.0));
    EXPECT_NEAR(puff_optical_depth(p, {-100.0, h, 0.0}, {100.0, h, 0.0}), expected, 1e-12);
    EXPECT_EQ(puff_optical_depth(p, {1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}), 0.0);
    // Two pieces of a segment add up to the whole.
    const glm::dvec3 a(-3.0, 0.5, 1.0), b(4.0, -0.5, -2.0);
    const glm::dvec3 m = a + 0.4 * (b - a);
    const FogPuff w = gabor({0.0f, 0.0f, 0.0f}, 1.0f, 1.0f, {1.0f, 2.0f, 0.5f}, 0.3f);
    EXPECT_NEAR(puff_optical_depth(w, a, m) + puff_optical_depth(w, m, b),
                puff_optical_depth(w, a, b), 1e-12);
}

TEST(FogPuffs, ScaledComplexErfMatchesItsTaylorSeries) {
    for (const double x : {-2.0, -0.7, 0.0, 0.3, 1.1, 2.5}) {
        for (const double y : {-2.0, -0.5, 0.0, 0.8, 1.7}) {
            // erf(z) = 2/√π Σ (−1)^n z^(2n+1) / (n!(2n+1)), fine for |z| < 3.
            const std::complex<double> z(x, y);
            std::complex<double> term = z, sum = 0.0;
            for (int n = 0; n < 80; ++n) {
                sum += term / static_cast<double>(2 * n + 1);
                term *= -z * z / static_cast<double>(n + 1);
            }
            const std::complex<double> expected =
                std::exp(-y * y) * 2.0 / std::sqrt(std::numbers::pi) * sum;
            const std::complex<double> got = scaled_complex_erf(x, y);
            EXPECT_NEAR(got.real(), expected.real(), 1e-10) << x << "," << y;
            EXPECT_NEAR(got.imag(), expected.imag(), 1e-10) << x << "," << y;
        }
    }
    EXPECT_NEAR(scaled_complex_erf(0.8, 0.0).real(), std::erf(0.8), 1e-15);
    // Large |y| stays finite (e^(−y²) is folded in): e^(−y²)·erf(iy) stays bounded.
    const std::complex<double> big = scaled_complex_erf(0.5, 12.0);
    EXPECT_TRUE(std::isfinite(big.real()) && std::isfinite(big.imag()));
    EXPECT_LT(std::abs(big), 1.0);
}

TEST(FogPuffs, ShaderIntegralsMatchNumericIntegration) {
    auto context = headless_context();
    for (const Case& c : cases()) {
        const PuffSegment segment{c.a, c.b};
        const std::vector<float> gpu = shader_puff_optical_depths(c.puffs, {&segment, 1});
        ASSERT_EQ(gpu.size(), 1u);
        const double numeric = numeric_depth(c.puffs, c.a, c.b);
        EXPECT_NEAR(gpu[0], numeric, 1e-3 * std::max(1.0, numeric))
            << "a=(" << c.a.x << "," << c.a.y << "," << c.a.z << ")";
    }
}

TEST(FogPuffs, ShaderProbeHandlesManySegmentsInBatches) {
    auto context = headless_context();
    const std::vector<FogPuff> puffs = {
        gabor({0.0f, 1.0f, 0.0f}, 1.2f, 0.6f, {1.5f, 0.5f, -2.0f}, 0.7f)};
    std::vector<PuffSegment> segments;
    for (int i = 0; i < 1500; ++i) {
        const float u = static_cast<float>(i) / 1500.0f;
        segments.push_back({{-6.0f + 12.0f * u, 3.0f, 8.0f}, {4.0f * u - 2.0f, 0.2f + u, -0.5f}});
    }
    const std::vector<float> gpu = shader_puff_optical_depths(puffs, segments);
    ASSERT_EQ(gpu.size(), segments.size());
    for (std::size_t i = 0; i < segments.size(); i += 97) {
        EXPECT_NEAR(gpu[i], puffs_optical_depth(puffs, segments[i].a, segments[i].b), 1e-3) << i;
    }
}

/// Sky black, fog white, no global fog: a pixel's grey level is 255·(1 − 0.5^depth).
struct PuffField {
    World world;
    SceneVisuals visuals;
    ViewCamera camera;
    explicit PuffField(std::vector<FogPuff> puffs) {
        visuals.environment.sky = glm::vec3(0.0f);
        Fog fog;
        fog.mode = FogMode::exponential;
        fog.density = 0.0f;
        fog.color = glm::vec3(1.0f);
        fog.puffs = std::move(puffs);
        visuals.fog = fog;
        CameraDef def;
        def.position = {0.0f, 1.0f, 8.0f};
        def.target = {0.0f, 1.0f, 0.0f};
        camera = ViewCamera::from_def(def);
    }
};

TEST(RenderFogPuffs, PixelsShowHalfToThePowerOfTheOpticalDepth) {
    const std::vector<FogPuff> puffs = {
        gaussian({0.0f, 1.0f, 0.0f}, 1.0f, 0.6f),
        gabor({2.5f, 1.5f, -1.0f}, 0.8f, 1.5f, {0.0f, 4.0f, 0.0f}, 0.0f)};
    PuffField field(puffs);
    const Image image = render_image(field.world, field.visuals, field.camera);
    const glm::mat4 inv =
        glm::inverse(field.camera.projection(static_cast<float>(golden_width) / golden_height) *
                     field.camera.view());
    int checked = 0;
    for (const glm::vec3& target :
         {glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.6f, 1.4f, 0.0f), glm::vec3(2.5f, 1.5f, -1.0f),
          glm::vec3(2.5f, 1.7f, -1.0f), glm::vec3(-3.0f, 2.5f, 0.0f)}) {
        const glm::ivec2 px = to_pixel(field.camera, target);
        // The ray through the pixel centre, from the eye to the far plane (empty depth).
        const glm::vec2 ndc((px.x + 0.5f) / golden_width * 2.0f - 1.0f,
                            1.0f - (px.y + 0.5f) / golden_height * 2.0f);
        const glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
        const double depth = puffs_optical_depth(puffs, glm::dvec3(field.camera.position),
                                                 glm::dvec3(glm::vec3(far) / far.w));
        const double expected = 255.0 * (1.0 - std::pow(0.5, depth));
        EXPECT_NEAR(image.pixel(px.x, px.y)[0], expected, 2.0) << target.x << "," << target.y;
        ++checked;
    }
    EXPECT_EQ(checked, 5);
}

TEST(RenderFogPuffs, OpaqueSurfacesCutTheRayShort) {
    // A wall in front of the puff's centre hides its far half: less fog there.
    const std::vector<FogPuff> puffs = {gaussian({0.0f, 1.0f, 0.0f}, 1.0f, 0.6f)};
    PuffField open(puffs);
    PuffField walled(puffs);
    walled.visuals.meshes.push_back(
        box_mesh({{-3.0f, -2.0f, 0.0f}, {3.0f, 4.0f, 0.1f}}, glm::vec3(0.0f)));
    const glm::ivec2 px = to_pixel(open.camera, {0.0f, 1.0f, 0.0f});
    const float full = render_image(open.world, open.visuals, open.camera).pixel(px.x, px.y)[0];
    const float half =
        render_image(walled.world, walled.visuals, walled.camera).pixel(px.x, px.y)[0];
    // Through the whole puff 0.6·√(2π) ≈ 1.5 halvings; to the wall (z = 0.1) just under half.
    const double to_wall = puff_optical_depth(puffs[0], {0.0, 1.0, 8.0}, {0.0, 1.0, 0.1});
    EXPECT_NEAR(half, 255.0 * (1.0 - std::pow(0.5, to_wall)), 3.0);
    EXPECT_GT(full, half + 40.0f);
}

/// A Gaussian puff in front of the fixture's house wall, a striped Gabor one in the shelter.
std::vector<FogPuff> fixture_puffs() {
    return {gaussian({-2.5f, 1.0f, 2.0f}, 0.7f, 1.2f),
            gabor({2.0f, 1.0f, 0.0f}, 1.0f, 1.5f, {5.0f, 0.0f, 0.0f}, 0.0f)};
}

TEST(RenderGolden, FixtureWithLayeredFogAndPuffs) {
    FixtureScene scene;
    build_fixture(scene);
    Fog fog;
    fog.mode = FogMode::layered;
    fog.layer_bottom = 0.0f;
    fog.layer_top = 1.5f;
    fog.layer_density = 0.2f;
    fog.puffs = fixture_puffs();
    scene.visuals.fog = fog;
    EXPECT_TRUE(
        matches_golden(render_image(scene.world, scene.visuals, scene.camera), "scene_fog_puffs"));
}

TEST(RenderPerf, DISABLED_FogPuffPass) {
    // Cost table of docs/effects.md: the puff pass at 640×480 in timing mode.
    FixtureScene scene;
    build_fixture(scene);
    Fog fog;
    fog.mode = FogMode::layered;
    fog.puffs = fixture_puffs();
    scene.visuals.fog = fog;
    auto context = headless_context(640, 480);
    RenderSettings settings;
    settings.timing_mode = true;
    Renderer renderer(*context, settings);
    std::vector<double> pass_ms;
    for (int i = 0; i < 16; ++i) {
        render_world(renderer, scene.world, scene.visuals, scene.camera);
        for (const PassTiming& p : renderer.timings().passes) {
            if (p.name == "fog_puffs" && i > 0) {
                pass_ms.push_back(p.cpu_ms);
            }
        }
    }
    std::sort(pass_ms.begin(), pass_ms.end());
    std::printf("fog_puffs pass at 640x480 (the golden fixture: 1 Gaussian + 1 Gabor puff): median "
                "%.2f ms\n",
                pass_ms[pass_ms.size() / 2]);
}

} // namespace
} // namespace snow::test
