/// @file rng.hpp
/// @brief Counter-based random numbers keyed by (seed, tick, slot, stream).
/// A draw depends only on its key, never on how many draws happened before,
/// so results are independent of thread count and order of work.
#pragma once

#include <cstdint>

namespace snow {

/// SplitMix64 finaliser: a strong 64-bit mixing bijection.
[[nodiscard]] constexpr std::uint64_t mix64(std::uint64_t x) {
    x ^= x >> 30;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 27;
    x *= 0x94D049BB133111EBull;
    x ^= x >> 31;
    return x;
}

/// A draw's key. `stream` keeps draws of different purposes apart; ecs/ gives
/// the ids no meaning, the caller names its own.
struct RngKey {
    std::uint64_t seed = 0;
    std::uint64_t tick = 0;
    std::uint32_t slot = 0;
    std::uint32_t stream = 0;
};

/// 64 random bits for key + draw index `n` (several draws under one key).
[[nodiscard]] constexpr std::uint64_t rng_bits(const RngKey& k, std::uint32_t n = 0) {
    std::uint64_t h = mix64(k.seed ^ 0x9E3779B97F4A7C15ull);
    h = mix64(h ^ k.tick);
    h = mix64(h ^ ((static_cast<std::uint64_t>(k.slot) << 32) | k.stream));
    return mix64(h + n);
}

/// Uniform float in [0, 1) with 24 random bits (exact, no rounding to 1).
[[nodiscard]] constexpr float rng_uniform(const RngKey& k, std::uint32_t n = 0) {
    return static_cast<float>(rng_bits(k, n) >> 40) * (1.0f / 16777216.0f);
}

/// Uniform float in [lo, hi).
[[nodiscard]] constexpr float rng_range(const RngKey& k, std::uint32_t n, float lo, float hi) {
    return lo + (hi - lo) * rng_uniform(k, n);
}

/// Uniform integer in [0, n) (n > 0), by 64-bit multiply-shift (Lemire).
[[nodiscard]] constexpr std::uint32_t rng_below(const RngKey& k, std::uint32_t draw,
                                                std::uint32_t n) {
    const std::uint64_t r = rng_bits(k, draw) >> 32;
    return static_cast<std::uint32_t>((r * n) >> 32);
}

} // namespace snow
