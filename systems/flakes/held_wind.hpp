/// @file held_wind.hpp
/// @brief How a flake holds the wind field's wind between two samples
/// (docs/wind_field.md "Sampling"): each 512-slot block samples one
/// contiguous run of its slots a tick, run number tick mod
/// WindFieldDef::sample_every, and a new flake samples on its first tick; in
/// between a flake drags towards the sample it holds. Held as whole steps of 1/256 m/s in 16 bits:
/// 6 bytes a flake to stream each tick instead of 12.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace snow {

inline constexpr float held_wind_steps_per_mps = 256.0f;
/// Largest held step; a wind beyond ±128 m/s is held at ±128 m/s.
inline constexpr float held_wind_max_step = 32767.0f;
/// A held x that no sample produces: the slot samples on its next tick.
inline constexpr std::int16_t held_wind_unset = std::numeric_limits<std::int16_t>::min();

/// A wind component given in steps (m/s × 256) as held: the nearest step
/// (ties to even, the default rounding), clamped; NaN holds as the lowest
/// step (std::max and std::min keep their first argument for NaN).
inline std::int16_t hold_steps(float steps) {
    const float clamped = std::min(std::max(-held_wind_max_step, steps), held_wind_max_step);
    return static_cast<std::int16_t>(std::nearbyint(clamped)); // inlines, unlike lround
}

/// A wind component (m/s) as held (exact scaling: the step is a power of two).
inline std::int16_t hold_wind_component(float w) {
    return hold_steps(w * held_wind_steps_per_mps);
}

/// A held component back in m/s: exact (the step is a power of two).
inline float held_wind_component(std::int16_t held) {
    return static_cast<float>(held) * (1.0f / held_wind_steps_per_mps);
}

} // namespace snow
