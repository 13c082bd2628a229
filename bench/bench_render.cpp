// Render upload (issue #8): the CPU half of the flake upload (selection and
// compaction into the staging array) at every bench size, and whole frames of
// the bench world on a small headless OSMesa (llvmpipe) context. Built only
// when snow_render is (SNOW_BENCH_RENDER).
#ifdef SNOW_BENCH_RENDER

#include "bench_scene.hpp"

#include "render/flake_selection.hpp"

#include <snow/render.hpp>

#include <cstdlib>
#include <vector>

namespace snow::bench {
namespace {

constexpr int frame_width = 320;
constexpr int frame_height = 240;

/// The default view camera, looking at the yard from its +z side.
ViewCamera yard_camera() {
    ViewCamera cam;
    cam.look_at({0.0f, 2.0f, 0.0f});
    return cam;
}

void flake_selection(benchmark::State& state) {
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)), 1);
    const FlakePool& pool = bw.sim->flakes();
    const ViewCamera cam = yard_camera();
    FlakeSelection sel;
    sel.view_proj = cam.projection(static_cast<float>(frame_width) / frame_height) * cam.view();
    sel.eye = cam.position;
    std::vector<float> staging(static_cast<std::size_t>(pool.capacity()) * 4);
    std::uint64_t drawn = 0;
    for (auto _ : state) {
        drawn += select_flakes(pool, sel, staging);
        benchmark::DoNotOptimize(staging.data());
    }
    state.counters["drawn"] = static_cast<double>(drawn) / static_cast<double>(state.iterations());
    state.counters["ns_per_flake"] =
        benchmark::Counter(static_cast<double>(state.iterations()) * pool.alive,
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void render_frame(benchmark::State& state) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)), 1);
    OsMesaContext context(frame_width, frame_height);
    Renderer renderer(context);
    const ViewCamera cam = yard_camera();
    const SceneVisuals no_meshes;
    renderer.render(bw.sim->world(), no_meshes, cam); // compiles shaders, uploads surfaces
    double flake_ms = 0.0;
    for (auto _ : state) {
        renderer.render(bw.sim->world(), no_meshes, cam);
        for (const PassTiming& p : renderer.timings().passes) {
            flake_ms += p.name == "flakes" ? p.cpu_ms : 0.0;
        }
    }
    state.counters["flake_pass_ms"] = flake_ms / static_cast<double>(state.iterations());
    state.counters["drawn"] = renderer.timings().flakes_drawn;
}

} // namespace

BENCHMARK(flake_selection)
    ->Name("BM_FlakeSelection")
    ->ArgNames({"flakes"})
    ->Arg(10000)
    ->Arg(100000)
    ->Arg(1000000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(render_frame)
    ->Name("BM_RenderUpload")
    ->ArgNames({"flakes"})
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace snow::bench

#endif // SNOW_BENCH_RENDER
