// Timing of the flake pass on this machine's GL (not a pass/fail test: timing
// asserts are not allowed). Run it with
//   snow_tests --gtest_also_run_disabled_tests --gtest_filter='RenderPerf.*'
// The numbers in docs/rendering.md come from here.
#include "render/renderer_internals.hpp"
#include "render_fixture.hpp"
#include "systems/flakes/flake_pool.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

namespace snow::test {
namespace {

/// Median over `frames` timed frames (after one warm-up) of the frame and flake pass.
void report(Renderer& renderer, FixtureScene& scene, const char* label) {
    constexpr int frames = 15;
    std::vector<double> frame_ms, flake_ms;
    render_world(renderer, scene.world, scene.visuals, scene.camera);
    for (int i = 0; i < frames; ++i) {
        render_world(renderer, scene.world, scene.visuals, scene.camera);
        const FrameTimings& t = renderer.timings();
        frame_ms.push_back(t.frame_ms);
        for (const PassTiming& p : t.passes) {
            if (p.name == "flakes") {
                flake_ms.push_back(p.cpu_ms);
            }
        }
    }
    std::sort(frame_ms.begin(), frame_ms.end());
    std::sort(flake_ms.begin(), flake_ms.end());
    std::printf("%-30s alive %6u drawn %6u  frame %7.2f ms  flakes %7.2f ms (median of %d)\n",
                label, renderer.timings().flakes_alive, renderer.timings().flakes_drawn,
                frame_ms[frames / 2], flake_ms.empty() ? 0.0 : flake_ms[frames / 2], frames);
    std::printf("   last frame:");
    for (const PassTiming& p : renderer.timings().passes) {
        std::printf(" %s %.2f%s", p.name.c_str(), p.cpu_ms, p.ran ? "" : "(skipped)");
    }
    std::printf("\n");
}

TEST(RenderPerf, DISABLED_SixtyThousandFlakesAt640x480) {
    FixtureScene scene;
    build_fixture(scene);
    FlakePool& pool = scene.world.resource<FlakePool>();
    pool.reset(60000);
    for (std::uint32_t i = 0; i < 60000; ++i) {
        std::uint32_t slot = 0;
        ASSERT_TRUE(pool.acquire(slot));
        // Fixed quasi-random fill of the default simulation bounds (20 × 12 × 20 m).
        pool.px[slot] = -10.0f + 20.0f * static_cast<float>(std::fmod(i * 0.6180339887, 1.0));
        pool.py[slot] = 12.0f * static_cast<float>(std::fmod(i * 0.7548776662, 1.0));
        pool.pz[slot] = -10.0f + 20.0f * static_cast<float>(std::fmod(i * 0.5698402910, 1.0));
        pool.size[slot] = 0.02f;
        pool.mass_units[slot] = 1;
    }
    auto context = headless_context(640, 480);
    RenderSettings settings;
    settings.timing_mode = true;
    Renderer renderer(*context, settings);
    std::printf("GL: %s\n", renderer.gl_description().c_str());
    renderer.settings().flake_lod = FlakeLod::never;
    const ViewCamera inside = scene.camera;
    CameraDef outside;
    outside.position = {0.0f, 6.0f, 26.0f};
    outside.target = {0.0f, 5.0f, 0.0f};
    for (const bool all_in_view : {false, true}) {
        scene.camera = all_in_view ? ViewCamera::from_def(outside) : inside;
        std::printf("-- camera %s\n", all_in_view ? "outside the snow volume (all flakes in view)"
                                                  : "of the fixture (inside the volume)");
        renderer.settings().flake_lod = FlakeLod::never;
        report(renderer, scene, "60k flakes, no LOD");
        renderer.settings().flake_lod = FlakeLod::always;
        for (const float d : {30.0f, 20.0f, 12.0f}) {
            renderer.settings().lod_distance = d;
            char label[64];
            std::snprintf(label, sizeof label, "60k flakes, LOD from %.0f m",
                          static_cast<double>(d));
            report(renderer, scene, label);
        }
    }
    scene.camera = inside;
    pool.reset(1);
    report(renderer, scene, "no flakes (scene only)");
}

} // namespace
} // namespace snow::test
