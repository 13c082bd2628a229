// Full-tick and per-system costs at 10k / 100k / 1M airborne flakes, 1 and 2
// threads (issue #8). ns_per_flake = time per tick / flakes alive that tick.
#include "bench_scene.hpp"

#include "systems/api/simulation_internals.hpp"

namespace snow::bench {
namespace {

template <Load load>
void full_tick(benchmark::State& state) {
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)), static_cast<unsigned>(state.range(1)),
                  load);
    for (auto _ : state) {
        bw.step(state, [&] { bw.sim->tick(); });
    }
    bw.clock.report(state);
}

/// One system alone on the snowfall world (the others not run).
template <void (*system)(World&)>
void one_system(benchmark::State& state) {
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)),
                  static_cast<unsigned>(state.range(1)));
    for (auto _ : state) {
        bw.step(state, [&] { system(InternalAccess::world(*bw.sim)); });
    }
    bw.clock.report(state);
}

/// The sizes of the issue; the full tick also gets points between them for the scaling plot.
void system_args(benchmark::internal::Benchmark* b) {
    flake_args(b, {10000, 100000, 1000000});
}
void scaling_args(benchmark::internal::Benchmark* b) {
    flake_args(b, {10000, 30000, 100000, 300000, 1000000, 3000000});
}

} // namespace

BENCHMARK(full_tick<Load::snowfall>)->Name("BM_SimTick")->Apply(scaling_args);
BENCHMARK(full_tick<Load::aloft>)->Name("BM_SimTickAloft")->Apply(system_args);
BENCHMARK(one_system<integrate_system>)->Name("BM_Integrate")->Apply(system_args);
BENCHMARK(one_system<collide_system>)->Name("BM_Collide")->Apply(system_args);
BENCHMARK(one_system<deposit_system>)->Name("BM_Deposit")->Apply(system_args);

} // namespace snow::bench
