// Snow cover (issue 13): a tick with a cover costs by the flakes that land and
// the cells they dirty, not by the cover's size. One fixed 12.8 m yard
// (ground mesh, four houses, a snowman, a ramp) with about 90k flakes in the
// air in steady snowfall, under covers of 5 cm cells that are 256², 1024²
// and 2048² cells large (the larger ones reach far past the yard).
#include "systems/api/simulation_internals.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace snow::bench {
namespace {

constexpr float half = 6.4f;
constexpr float cell = 0.05f;
/// Ticks of snowfall before timing: the air fills to its steady ~100k flakes.
constexpr std::uint64_t warmup_ticks = 600;
/// Ticks between restores of the starting state (outside the timing).
constexpr std::uint64_t restore_every = 32;

std::unique_ptr<Simulation> make_covered_yard(std::uint32_t side, unsigned threads) {
    SimConfig c;
    c.seed = 13;
    c.bounds = {{-half, -1.0f, -half}, {half, 8.0f, half}};
    c.max_flakes = 130000;
    c.threads = threads;
    auto sim = std::make_unique<Simulation>(c);
    const float reach = 0.5f * cell * static_cast<float>(side); // the cover's half extent
    const float g = std::max(half, reach);
    sim->add_mesh_collider(
        {{-g, 0.0f, -g}, {g, 0.0f, -g}, {g, 0.0f, g}, {-g, 0.0f, -g}, {g, 0.0f, g}, {-g, 0.0f, g}});
    for (int k = 0; k < 4; ++k) {
        const float x = -5.5f + 2.8f * static_cast<float>(k);
        sim->add_box({{x, 0.0f, -5.0f}, {x + 2.0f, 2.0f + 0.5f * static_cast<float>(k), -2.5f}});
    }
    sim->add_sphere({2.5f, 0.6f, 3.0f}, 0.6f);
    sim->add_sphere({2.5f, 1.5f, 3.0f}, 0.4f);
    sim->add_mesh_collider({{-5.0f, 0.0f, 1.0f},
                            {-2.0f, 1.5f, 1.0f},
                            {-2.0f, 1.5f, 5.0f},
                            {-5.0f, 0.0f, 1.0f},
                            {-2.0f, 1.5f, 5.0f},
                            {-5.0f, 0.0f, 5.0f}});
    Emitter e;
    e.rate = 18500.0f;
    sim->add_emitter(e);
    Wind w;
    w.base = w.current = {1.0f, 0.0f, 0.0f};
    sim->set_wind(w);
    CoverDef d;
    d.min_x = d.min_z = -reach;
    d.max_x = d.max_z = reach;
    d.cell = cell;
    sim->add_cover(d);
    sim->run(warmup_ticks);
    return sim;
}

void BM_CoverTick(benchmark::State& state) {
    const auto side = static_cast<std::uint32_t>(state.range(0));
    const auto threads = static_cast<unsigned>(state.range(1));
    const auto sim = make_covered_yard(side, threads);
    const auto start = save_snapshot(*sim);
    std::uint64_t iteration = 0, flake_ticks = 0;
    std::uint64_t landed = 0;
    for (auto _ : state) {
        flake_ticks += flake_pool(*sim).alive;
        const std::uint64_t before = sim->counters().landed;
        sim->tick();
        landed += sim->counters().landed - before;
        if (++iteration % restore_every == 0) {
            state.PauseTiming();
            restore_snapshot(*sim, *start);
            state.ResumeTiming();
        }
    }
    const double iters = static_cast<double>(state.iterations());
    state.counters["cells"] = static_cast<double>(side) * side;
    state.counters["flakes"] = static_cast<double>(flake_ticks) / iters;
    state.counters["landed_per_tick"] = static_cast<double>(landed) / iters;
}
BENCHMARK(BM_CoverTick)
    ->ArgNames({"side", "threads"})
    ->Args({256, 1})
    ->Args({1024, 1})
    ->Args({2048, 1})
    ->Args({1024, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace
} // namespace snow::bench
