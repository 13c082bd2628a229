// The village with the effects of [LZ] and [PE] (assets/scenes/
// village_effects.gltf: spectral far-field snow, layered fog with a puff):
// rendered headless from the scene file, and the plain village draws neither.
#include "render/renderer_internals.hpp"
#include "tests/render/render_fixture.hpp"
#include <snow/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace snow::test {
namespace {

std::string scene_path(const std::string& name) {
    return std::string(SNOW_SOURCE_DIR) + "/assets/scenes/" + name;
}

struct Frame {
    Image image;
    std::vector<std::string> passes;
};

/// Loads a scene, simulates `ticks`, renders one golden-size frame from its camera.
Frame render_scene(const std::string& name, std::uint64_t ticks) {
    SceneLoadResult r = load_scene_file(scene_path(name));
    if (r.sim == nullptr) {
        ADD_FAILURE() << r.error;
        return {};
    }
    r.sim->run(ticks);
    const ViewCamera camera = ViewCamera::from_def(r.visuals.camera);
    auto context = headless_context();
    Renderer renderer(*context);
    renderer.render(*r.sim, r.visuals, camera);
    return {renderer.read_pixels(), renderer.pass_names()};
}

TEST(RenderEffectsScene, VillageWithoutEffectsRunsOnlyTheBuiltInPasses) {
    const Frame f = render_scene("village.gltf", 1);
    // The walker is a moving body: it brings the bodies pass.
    const std::vector<std::string> builtin = {"sky", "meshes", "bodies", "snow_surfaces", "flakes"};
    EXPECT_EQ(f.passes, builtin);
}

TEST(RenderGolden, VillageEffectsScene) {
    // Four seconds of snowfall: particles near the camera, the spectral layer
    // over the sky beyond them, the layered fog low over the ground and a
    // puff, and the low sun's shadows across the snow.
    const Frame f = render_scene("village_effects.gltf", 240);
    const std::vector<std::string> passes = {"sun_shadows", "sky",           "meshes",
                                             "bodies",      "snow_surfaces", "spectral_snow",
                                             "flakes",      "fog_puffs"};
    EXPECT_EQ(f.passes, passes);
    EXPECT_TRUE(matches_golden(f.image, "village_effects"));
}

TEST(RenderPerf, DISABLED_VillageEffectsPasses) {
    // docs/effects.md: per-pass cost of the effects scene at 640x480 (timing
    // mode, median of 15 frames after the first), against the plain village;
    // docs/rendering.md: the sunny effects scene without and with the snow's
    // detail normals and sparkle.
    struct Run {
        const char* name;
        bool detail;
    };
    for (const Run run : {Run{"village.gltf", true}, Run{"village_effects.gltf", false},
                          Run{"village_effects.gltf", true}}) {
        const char* name = run.name;
        SceneLoadResult r = load_scene_file(scene_path(name));
        ASSERT_NE(r.sim, nullptr) << r.error;
        r.sim->run(240);
        const ViewCamera camera = ViewCamera::from_def(r.visuals.camera);
        auto context = headless_context(640, 480);
        RenderSettings settings;
        settings.timing_mode = true;
        settings.detail_normals = run.detail;
        settings.sparkle = run.detail;
        Renderer renderer(*context, settings);
        std::vector<std::vector<double>> ms;
        std::vector<double> frame;
        for (int i = 0; i < 16; ++i) {
            renderer.render(*r.sim, r.visuals, camera);
            const auto& passes = renderer.timings().passes;
            ms.resize(passes.size());
            for (std::size_t p = 0; i > 0 && p < passes.size(); ++p) {
                ms[p].push_back(passes[p].ran ? passes[p].cpu_ms : 0.0);
            }
            if (i > 0) {
                frame.push_back(renderer.timings().frame_ms);
            }
        }
        const auto median = [](std::vector<double> v) {
            std::sort(v.begin(), v.end());
            return v[v.size() / 2];
        };
        std::printf("%s%s at 640x480:", name, run.detail ? "" : " (no detail, no sparkle)");
        for (std::size_t p = 0; p < ms.size(); ++p) {
            std::printf(" %s %.2f ms;", renderer.timings().passes[p].name.c_str(), median(ms[p]));
        }
        std::printf(" frame %.2f ms\n", median(frame));
    }
}

} // namespace
} // namespace snow::test
