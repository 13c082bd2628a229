// Render upload (issue #8): the CPU half of the flake upload (selection and
// compaction into the staging array) at every bench size, and whole frames of
// the bench world on a small headless OSMesa (llvmpipe) context. Snow cover
// (issue #13): the snow-surface pass alone for a big, irregular surface at
// 640×480. Built only when snow_render is (SNOW_BENCH_RENDER).
#ifdef SNOW_BENCH_RENDER

#include "bench_scene.hpp"
#include "render/context/osmesa_context.hpp"
#include "render/renderer_internals.hpp"
#include "systems/api/simulation_internals.hpp"

#include "render/passes/flake_selection.hpp"

#include <snow/render.hpp>

#include "systems/core/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <ctime>
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
    const FlakePool& pool = flake_pool(*bw.sim);
    const ViewCamera cam = yard_camera();
    FlakeSelection sel;
    sel.view_proj = cam.projection(static_cast<float>(frame_width) / frame_height) * cam.view();
    sel.eye = cam.position;
    std::vector<float> staging(static_cast<std::size_t>(pool.capacity()) * 4);
    std::uint64_t drawn = 0;
    FlakeClock clock;
    for (auto _ : state) {
        clock.time(pool.alive, [&] { drawn += select_flakes(pool, sel, staging); });
        benchmark::DoNotOptimize(staging.data());
    }
    clock.report(state);
    state.counters["drawn"] = static_cast<double>(drawn) / static_cast<double>(state.iterations());
}

void render_frame(benchmark::State& state) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)), 1);
    OsMesaContext context(frame_width, frame_height);
    Renderer renderer(context);
    const ViewCamera cam = yard_camera();
    const SceneVisuals no_meshes;
    renderer.render(*bw.sim, no_meshes, cam); // compiles shaders, uploads surfaces
    double flake_ms = 0.0;
    for (auto _ : state) {
        renderer.render(*bw.sim, no_meshes, cam);
        for (const PassTiming& p : renderer.timings().passes) {
            flake_ms += p.name == "flakes" ? p.cpu_ms : 0.0;
        }
    }
    state.counters["flake_pass_ms"] = flake_ms / static_cast<double>(state.iterations());
    state.counters["drawn"] = renderer.timings().flakes_drawn;
}

/// Bare top (m) of a cover over rolling terrain with houses (pitched roofs,
/// sharp eaves) and spheres every 12 m: the highest geometry of each column.
double cover_base(double x, double z) {
    double y = 0.6 * std::sin(0.25 * x) * std::cos(0.2 * z) + 0.3 * std::sin(0.07 * (x + z));
    const double hx = std::remainder(x, 12.0), hz = std::remainder(z - 3.0, 12.0);
    if (std::abs(hx) < 2.5 && std::abs(hz) < 2.0) { // house: 3 m walls, ridge along z
        y = std::max(y, 4.2 - 0.58 * std::abs(hx));
    }
    const double sx = std::remainder(x - 6.0, 12.0), sz = std::remainder(z + 3.0, 12.0);
    if (const double d2 = sx * sx + sz * sz; d2 < 1.0) { // sphere of 1 m radius at 1 m
        y = std::max(y, 1.0 + std::sqrt(1.0 - d2));
    }
    return y;
}

/// A cells × cells snow cover of 5 cm cells centred on the origin: the base
/// above, 2 to 18 cm of wavy snow with drifts, none on the spheres' sides.
SnowSurface snow_cover(std::uint32_t cells) {
    SnowSurface s;
    s.cell = 0.05f;
    s.nx = s.nz = cells;
    s.x0 = s.z0 = -0.5f * s.cell * static_cast<float>(cells);
    s.unit_height = static_cast<float>(
        unit_kg / (fresh_snow_density(SimConfig{}.air_temperature) * s.cell * s.cell));
    s.base_level.resize(static_cast<std::size_t>(cells) * cells);
    s.snow.resize(s.base_level.size());
    for (std::uint32_t iz = 0; iz < cells; ++iz) {
        for (std::uint32_t ix = 0; ix < cells; ++ix) {
            const double x = s.x0 + (ix + 0.5) * s.cell, z = s.z0 + (iz + 0.5) * s.cell;
            const double base = cover_base(x, z);
            const double slope = std::abs(cover_base(x + s.cell, z) - base) / s.cell;
            const double depth = slope > 1.5 ? 0.0
                                             : 0.1 + 0.05 * std::sin(1.3 * x) * std::cos(0.9 * z) +
                                                   0.03 * std::sin(0.4 * z + 0.2 * x);
            s.base_level[s.index(ix, iz)] = std::llround(base / s.unit_height);
            s.snow[s.index(ix, iz)] =
                static_cast<std::uint32_t>(std::lround(depth / s.unit_height));
        }
    }
    return s;
}

/// The snow-surface pass (timing mode: GPU work included) for one cover at
/// 640×480, from view 0 (above, the whole cover in sight) or 1 (a walker's
/// view across it to the horizon); `changed` cells in scattered tiles gain a
/// unit every frame, as when snow lands, and are re-uploaded.
void render_snow_cover(benchmark::State& state) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 0);
    World world;
    const Entity cover = world.create();
    world.add<SnowSurface>(cover, snow_cover(static_cast<std::uint32_t>(state.range(0))));
    const SceneVisuals visuals; // no meshes: the snow-surface pass alone
    OsMesaContext context(640, 480);
    RenderSettings settings;
    settings.timing_mode = true;
    Renderer renderer(context, settings);
    ViewCamera cam;
    if (state.range(1) == 0) {
        cam.position = {0.0f, 14.0f, 30.0f};
        cam.look_at({0.0f, 0.0f, 0.0f});
    } else {
        cam.position = {3.0f, 2.2f, 10.0f};
        cam.look_at({3.0f, 1.0f, -20.0f});
    }
    render_world(renderer, world, visuals, cam); // compiles shaders, uploads every tile
    SnowSurface& s = world.get<SnowSurface>(cover);
    const auto changed = static_cast<std::uint32_t>(state.range(2));
    double pass_ms = 0.0, frame_ms = 0.0;
    std::uint64_t frame = 0, uploaded = 0;
    const std::clock_t cpu_start = std::clock(); // every thread of the process: llvmpipe's too
    for (auto _ : state) {
        for (std::uint32_t k = 0; k < changed; ++k) { // a fixed walk over the grid
            s.snow[(static_cast<std::size_t>(frame * changed + k) * 104729u) % s.snow.size()] += 1;
        }
        ++frame;
        render_world(renderer, world, visuals, cam);
        for (const PassTiming& p : renderer.timings().passes) {
            pass_ms += p.name == "snow_surfaces" ? p.cpu_ms : 0.0;
        }
        frame_ms += renderer.timings().frame_ms;
        uploaded += renderer.timings().surface_tiles_uploaded;
    }
    const auto n = static_cast<double>(state.iterations());
    // CPU time of all threads per frame: on a loaded machine wall time waits
    // for other processes, this does not.
    state.counters["cpu_ms"] =
        1000.0 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC / n;
    state.counters["surface_pass_ms"] = pass_ms / n;
    state.counters["frame_ms"] = frame_ms / n;
    state.counters["tiles_drawn"] = renderer.timings().surface_tiles_drawn;
    state.counters["tiles_uploaded"] = static_cast<double>(uploaded) / n;
    state.counters["samples"] = renderer.timings().surface_samples;
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
BENCHMARK(render_snow_cover)
    ->Name("BM_RenderSnowCover")
    ->ArgNames({"cells", "view", "changed"})
    ->ArgsProduct({{256, 1024, 2048}, {0, 1}, {0}})
    ->ArgsProduct({{1024}, {0, 1}, {64}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace snow::bench

#endif // SNOW_BENCH_RENDER
