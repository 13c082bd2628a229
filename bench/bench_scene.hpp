/// @file bench_scene.hpp
/// @brief The benchmark world of issue #8: N airborne flakes over a 512×512
/// surface with a box and a sphere collider and wind, refilled to N when
/// flakes land, so every measured tick sees the same load.
#pragma once

#include "systems/sample_scenes.hpp"

#include <benchmark/benchmark.h>

#include <memory>

namespace snow::bench {

/// True when snow_bench runs with --smoke (CI: tiny sizes, one pass each).
[[nodiscard]] bool smoke();

struct BenchWorld {
    std::unique_ptr<Simulation> sim;
    std::unique_ptr<Snapshot> start;
    std::uint32_t flakes = 0;

    BenchWorld(std::uint32_t flakes, unsigned threads);
    /// Restores the starting state (outside timing) every `every` iterations.
    void keep_load(benchmark::State& state, std::uint64_t iteration, std::uint64_t every = 64);
};

/// Sets the standard counters: ns per flake per tick and flakes.
void report_per_flake(benchmark::State& state, std::uint32_t flakes);

} // namespace snow::bench
