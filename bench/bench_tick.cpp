// Full-tick and per-system costs at 10k / 100k / 1M airborne flakes, 1 and 2
// threads (issue #8). ns_per_flake = time per tick / flakes.
#include "bench_scene.hpp"

#include "systems/systems.hpp"

namespace snow::bench {
namespace {

void full_tick(benchmark::State& state) {
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)), static_cast<unsigned>(state.range(1)));
    std::uint64_t i = 0;
    for (auto _ : state) {
        bw.sim->tick();
        bw.keep_load(state, i++);
    }
    report_per_flake(state, bw.flakes);
}

/// One system alone on the bench world (the others not run).
template <void (*system)(World&)>
void one_system(benchmark::State& state) {
    BenchWorld bw(static_cast<std::uint32_t>(state.range(0)), static_cast<unsigned>(state.range(1)));
    std::uint64_t i = 0;
    for (auto _ : state) {
        system(bw.sim->world());
        bw.keep_load(state, i++);
    }
    report_per_flake(state, bw.flakes);
}

void flake_args(benchmark::internal::Benchmark* b) {
    b->ArgNames({"flakes", "threads"});
    for (const int n : {10000, 100000, 1000000}) {
        for (const int t : {1, 2}) {
            b->Args({n, t});
        }
    }
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace

BENCHMARK(full_tick)->Name("BM_SimTick")->Apply(flake_args);
BENCHMARK(one_system<integrate_system>)->Name("BM_Integrate")->Apply(flake_args);
BENCHMARK(one_system<collide_system>)->Name("BM_Collide")->Apply(flake_args);
BENCHMARK(one_system<deposit_system>)->Name("BM_Deposit")->Apply(flake_args);

} // namespace snow::bench
