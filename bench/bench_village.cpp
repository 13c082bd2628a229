// The village scene's tick (issue 16: 2 threads are never slower than 1):
// assets/scenes/village.gltf as shipped, warmed up until its snowfall is
// steady, then ticked from that state (restored every restore_every ticks,
// outside the timing). Built only when snow_scene is (SNOW_BENCH_SCENE).
#ifdef SNOW_BENCH_SCENE

#include "bench_scene.hpp"

#include <snow/scene.hpp>

#include <utility>

namespace snow::bench {
namespace {

/// Ticks before timing (20 s of snow at 60 Hz): the flakes aloft are as many
/// as land and the ground carries snow.
constexpr std::uint64_t warm_ticks = 1200;

void village_tick(benchmark::State& state) {
    SceneOverrides o;
    o.threads = static_cast<unsigned>(state.range(0));
    SceneLoadResult scene = load_scene_file(SNOW_SOURCE_DIR "/assets/scenes/village.gltf", o);
    if (scene.sim == nullptr) {
        state.SkipWithError(scene.error.c_str());
        return;
    }
    scene.sim->run(warm_ticks);
    BenchWorld bw(std::move(scene.sim));
    for (auto _ : state) {
        bw.step(state, [&] { bw.sim->tick(); });
    }
    bw.clock.report(state);
}

} // namespace

BENCHMARK(village_tick)
    ->Name("BM_VillageTick")
    ->ArgNames({"threads"})
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace snow::bench

#endif // SNOW_BENCH_SCENE
