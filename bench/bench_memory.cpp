// Copy bandwidth of this machine, measured next to the simulation so
// docs/performance.md can state each tick's distance from the memory bound
// (bytes a tick must touch per flake / this bandwidth). bytes_per_second
// counts read plus written bytes of all threads together.
#include "bench_scene.hpp"

#include <cstring>
#include <vector>

namespace snow::bench {
namespace {

void memory_copy(benchmark::State& state) {
    const auto bytes = static_cast<std::size_t>(state.range(0)) << 20;
    std::vector<unsigned char> from(bytes, 1), to(bytes, 0);
    for (auto _ : state) {
        std::memcpy(to.data(), from.data(), bytes);
        benchmark::DoNotOptimize(to.data());
        benchmark::ClobberMemory();
    }
    state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) *
                            static_cast<std::int64_t>(2 * bytes));
}

} // namespace

// 256 MiB per buffer is far past the 32 MiB L3: main memory alone.
BENCHMARK(memory_copy)
    ->Name("BM_MemoryCopy")
    ->ArgNames({"mib"})
    ->Arg(64)
    ->Arg(256)
    ->Threads(1)
    ->Threads(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

} // namespace snow::bench
