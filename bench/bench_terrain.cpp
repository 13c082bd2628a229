// A terrain's collider (docs/world.md): the mesh built from a height map of
// n × n samples over 4 × 4 km, the collider added through the facade, and the
// first tick, whose sky-map refresh rasterises every triangle. The samples
// are made in memory (no PNG), so this is the collider's cost alone; the
// counters give the memory the triangles take. Built only when snow_scene is
// (SNOW_BENCH_SCENE).
#ifdef SNOW_BENCH_SCENE

#include "game/scene/scene_terrain.hpp"
#include <snow/snow.hpp>

#include <benchmark/benchmark.h>

#include <cmath>

namespace snow::bench {
namespace {

/// n × n samples of smooth hills (sums of sines), deterministic.
HeightSamples hills(std::uint32_t n) {
    HeightSamples s;
    s.width = s.height = n;
    s.values.resize(std::size_t{n} * n);
    for (std::uint32_t j = 0; j < n; ++j) {
        for (std::uint32_t i = 0; i < n; ++i) {
            const double x = 4000.0 * i / (n - 1), z = 4000.0 * j / (n - 1);
            const double h = 0.5 + 0.3 * std::sin(x / 310.0) * std::cos(z / 270.0) +
                             0.15 * std::sin((x + z) / 190.0);
            s.values[std::size_t{j} * n + i] = static_cast<std::uint16_t>(65535.0 * h);
        }
    }
    return s;
}

const WorldDef world{"bench.png", {4000.0, 4000.0}, {0.0, 400.0}};

void terrain_mesh_build(benchmark::State& state) {
    const HeightSamples s = hills(static_cast<std::uint32_t>(state.range(0)));
    std::size_t triangles = 0;
    for (auto _ : state) {
        const TerrainMesh m = terrain_mesh(world, s);
        const std::vector<glm::vec3> t = terrain_triangles(m);
        triangles = t.size() / 3;
        benchmark::DoNotOptimize(t.data());
    }
    state.counters["triangles"] = static_cast<double>(triangles);
    // The collider's copy (3 vertices a triangle) and the drawn mesh.
    state.counters["collider_MiB"] = static_cast<double>(triangles * 36) / (1 << 20);
    state.counters["render_MiB"] =
        static_cast<double>(s.values.size() * 24 + triangles * 12) / (1 << 20);
}

void terrain_collider(benchmark::State& state) {
    const HeightSamples s = hills(static_cast<std::uint32_t>(state.range(0)));
    const std::vector<glm::vec3> t = terrain_triangles(terrain_mesh(world, s));
    SimConfig c;
    c.bounds = {{-80.0f, 0.0f, -80.0f}, {80.0f, 400.0f, 80.0f}};
    for (auto _ : state) {
        Simulation sim(c);
        sim.add_mesh_collider(t);
        sim.tick(); // the first sky-map refresh
        benchmark::DoNotOptimize(sim.tick_count());
    }
}

/// Height maps of 257², 513² and 1025² samples, in wall-clock ms.
void sample_counts(benchmark::internal::Benchmark* b) {
    b->ArgNames({"samples"})
        ->Arg(257)
        ->Arg(513)
        ->Arg(1025)
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
}

} // namespace

BENCHMARK(terrain_mesh_build)->Name("BM_TerrainMesh")->Apply(sample_counts);
BENCHMARK(terrain_collider)->Name("BM_TerrainCollider")->Apply(sample_counts);

} // namespace snow::bench

#endif // SNOW_BENCH_SCENE
