#include "bench_scene.hpp"

namespace snow::bench {

BenchWorld::BenchWorld(std::uint32_t n, unsigned threads) : flakes(n) {
    YardOptions o;
    o.threads = threads;
    o.ground_cells = 512;
    o.max_flakes = n + n / 8;
    o.emitter_rate = 0.0f; // the load is the prefilled flakes, restored periodically
    o.prefill = n;
    sim = make_yard(o);
    start = sim->save();
}

void BenchWorld::keep_load(benchmark::State& state, std::uint64_t iteration, std::uint64_t every) {
    if (iteration % every == every - 1) {
        state.PauseTiming();
        sim->restore(*start);
        state.ResumeTiming();
    }
}

void report_per_flake(benchmark::State& state, std::uint32_t flakes) {
    state.counters["flakes"] = flakes;
    state.counters["ns_per_flake"] = benchmark::Counter(
        static_cast<double>(state.iterations()) * flakes,
        benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace snow::bench
