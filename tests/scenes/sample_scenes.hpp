/// @file sample_scenes.hpp
/// @brief Scenes built in code, shared by tests, benchmarks and examples
/// (as Box2D's samples and benchmarks share theirs), so they all measure the
/// same thing.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <cstdint>
#include <memory>

namespace snow {

struct YardOptions {
    std::uint64_t seed = 7;
    unsigned threads = 1;
    TaskSystem* task_system = nullptr; ///< the host's (SimConfig::task_system)
    float dt = 1.0f / 60.0f;
    Integrator integrator = Integrator::explicit_euler;
    std::uint32_t ground_cells = 128; ///< ground surface is ground_cells² cells
    std::uint32_t max_flakes = 20000;
    float emitter_rate = 3000.0f;  ///< parcels per second; 0 = no emitter
    float snowfall_kg_m2_h = 0.0f; ///< 0: the heaviest snowfall emitter_rate carries
    bool wind = true;
    std::uint32_t prefill = 0; ///< flakes placed airborne before tick 0
};

/// A 16 m × 16 m yard: ground surface, a garage box with a snow-holding flat
/// roof, a sphere (snowman), steady wind along +x, an emitter.
[[nodiscard]] std::unique_ptr<Simulation> make_yard(const YardOptions& o = {});

/// The yard Determinism.PinnedHashHoldsInEveryBuild pins: 40000 flakes
/// prefilled (more than two chunks of flake_grain, so threads share work) in
/// a pool of 60000, and a heavy emitter.
[[nodiscard]] YardOptions busy_yard(unsigned threads);

/// The yard with every kind of hidden state switched on, for the tests of
/// snapshots and allocation: 40000 prefilled flakes (more than two chunks, so
/// two threads share the work) and a heavy emitter; a walking, gusting wind;
/// a mesh shelter whose snow-holding roof spills almost at once and a bare
/// mesh tent, both seen through a tilted sky camera whose lean follows the
/// wind; a snow cover over a boulder; a snowball and a capsule walker doing
/// laps through the ground's snow; a coarse wind field that moves snow.
/// `task_system`, when given, runs it instead of the built-in pool.
[[nodiscard]] std::unique_ptr<Simulation> make_stormy_yard(unsigned threads,
                                                           TaskSystem* task_system = nullptr);

/// Flake number `n` of prefill_flakes: uniform in the upper half of the
/// bounds, falling at 1 m/s, mass and place deterministic in the seed.
[[nodiscard]] FlakeSpec prefill_flake(const SimConfig& config, std::uint32_t n);

/// Places `count` airborne flakes (prefill_flake 0, 1, ...) until the pool is
/// full; for benchmarks at a fixed flake count.
void prefill_flakes(Simulation& sim, std::uint32_t count);

} // namespace snow
