/// @file bench_scene.hpp
/// @brief The benchmark world of issue #8: N airborne flakes over a 512×512
/// surface with a box and a sphere collider and wind (the yard of
/// systems/sample_scenes.hpp), restored to its starting state periodically so
/// every measured tick sees about the same load.
#pragma once

#include "systems/sample_scenes.hpp"

#include <benchmark/benchmark.h>

#include <cstdint>
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

struct BenchWorld {
    std::unique_ptr<Simulation> sim;
    std::unique_ptr<Snapshot> start;
    std::uint64_t flake_ticks = 0; ///< alive flakes summed over the measured ticks

    BenchWorld(std::uint32_t flakes, unsigned threads, Load load = Load::snowfall);
    /// Call once per measured iteration, after the work: counts the alive
    /// flakes the work saw and restores the starting state (outside timing)
    /// every restore_every iterations.
    void step_done(benchmark::State& state, std::uint64_t& iteration, std::uint32_t alive_before);
};

/// Sets the standard counters: flakes (mean alive per tick) and ns_per_flake
/// (time per tick divided by the flakes alive in that tick; seconds in JSON).
void report_per_flake(benchmark::State& state, const BenchWorld& world);

} // namespace snow::bench
