/// @file bench_scene.hpp
/// @brief The benchmark world of issue #8: N airborne flakes over a 512×512
/// surface with a box and a sphere collider and wind (the yard of
/// tests/scenes/sample_scenes.hpp), restored to its starting state periodically so
/// every measured tick sees about the same load.
#pragma once

#include "systems/api/simulation_internals.hpp"
#include "tests/scenes/sample_scenes.hpp"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <memory>

namespace snow::bench {

/// Where the prefilled flakes are when timing starts.
enum class Load : std::uint8_t {
    /// Spread over the whole height of the bounds, falling at terminal speed:
    /// every tick some land (deposit, rolling, redistribution, box slides and
    /// sphere hits all do work), as in steady snowfall.
    snowfall,
    /// The upper half only (sample_scenes' prefill): nothing lands within the
    /// restore period, so a tick is the per-flake passes alone.
    aloft,
};

/// Ticks between restores of the starting state.
inline constexpr std::uint64_t restore_every = 32;

/// Wall time of the measured work (the Time column's clock, less the loop
/// around the work) per flake the work served, and the CPU time of all the
/// process's threads over the same work: on a loaded machine the wall time
/// waits for other processes, the CPU time does not.
class FlakeClock {
  public:
    /// Runs work() timed; `flakes` is how many it serves (those alive before it).
    template <typename Work>
    void time(std::uint32_t flakes, Work&& work) {
        const double cpu0 = process_cpu_ns();
        const auto t0 = std::chrono::steady_clock::now();
        work();
        const auto t1 = std::chrono::steady_clock::now();
        cpu_ns_ += process_cpu_ns() - cpu0;
        ns_ += std::chrono::duration<double, std::nano>(t1 - t0).count();
        flake_ticks_ += flakes;
        ++calls_;
    }
    /// Sets the standard counters: flakes (mean per call), ns_per_flake (ns
    /// of work per flake served: time per tick / flakes alive in that tick)
    /// and cpu_ns_per_flake (the same in CPU time, all threads summed).
    void report(benchmark::State& state) const;

  private:
    static double process_cpu_ns();
    double ns_ = 0.0;
    double cpu_ns_ = 0.0;
    double flake_ticks_ = 0.0;
    std::uint64_t calls_ = 0;
};

struct BenchWorld {
    std::unique_ptr<Simulation> sim;
    std::unique_ptr<Snapshot> start;
    FlakeClock clock;

    BenchWorld(std::uint32_t flakes, unsigned threads, Load load = Load::snowfall);
    /// A ready simulation (a loaded scene, warmed up): its state now is the start.
    explicit BenchWorld(std::unique_ptr<Simulation> ready);
    /// One measured iteration: work() timed against the flakes alive before
    /// it; the starting state is restored (outside timing) every
    /// restore_every iterations.
    template <typename Work>
    void step(benchmark::State& state, Work&& work) {
        clock.time(flake_pool(*sim).alive, work);
        if (++iteration_ % restore_every == 0) {
            restore(state);
        }
    }

  private:
    void restore(benchmark::State& state);
    std::uint64_t iteration_ = 0;
};

/// Arguments flakes:N/threads:T for every N of `sizes` and T = 1, 2; ms, real time.
void flake_args(benchmark::internal::Benchmark* b, std::initializer_list<int> sizes);

} // namespace snow::bench
