// Loading a scene (docs/reliability.md "Bounded work"): any input loads or
// is refused within 1 s in Release. BM_SceneLoad parses and builds (the file
// is read before timing) a shipped scene and the scene that declares all the
// work the default WorkBudget allows at once (assets/testdata/
// at_default_budget.gltf, fuzz/make_budget_scenes.py); BM_SceneRefuse refuses
// that scene under a budget one flake short.
// Built only when snow_scene is (SNOW_BENCH_SCENE).
#ifdef SNOW_BENCH_SCENE

#include <snow/scene.hpp>

#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <string>

namespace snow::bench {
namespace {

const char* const scenes[] = {SNOW_SOURCE_DIR "/assets/scenes/village_effects.gltf",
                              SNOW_SOURCE_DIR "/assets/testdata/at_default_budget.gltf"};

std::string file_bytes(const char* path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

void scene_load(benchmark::State& state) {
    const std::string bytes = file_bytes(scenes[state.range(0)]);
    for (auto _ : state) {
        SceneLoadResult r = load_scene_memory(bytes, "bench");
        if (r.sim == nullptr) {
            state.SkipWithError(r.error.c_str());
            return;
        }
        benchmark::DoNotOptimize(r.sim.get());
    }
}

void scene_refuse(benchmark::State& state) {
    const std::string bytes = file_bytes(scenes[1]);
    SceneOverrides o;
    o.budget.flakes = (1u << 20) - 1; // the scene declares 2^20
    for (auto _ : state) {
        SceneLoadResult r = load_scene_memory(bytes, "bench", o);
        if (r.sim != nullptr) {
            state.SkipWithError("the scene past the budget loaded");
            return;
        }
        benchmark::DoNotOptimize(r.error.data());
    }
}

} // namespace

BENCHMARK(scene_load)
    ->Name("BM_SceneLoad")
    ->ArgNames({"scene"}) // 0 village_effects, 1 at the default budget
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(scene_refuse)->Name("BM_SceneRefuse")->Unit(benchmark::kMillisecond)->UseRealTime();

} // namespace snow::bench

#endif // SNOW_BENCH_SCENE
