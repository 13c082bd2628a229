/// @file random_streams.hpp
/// @brief The `stream` ids of snow's random draws (RngKey, ecs/rng.hpp): one
/// per purpose, so draws for different purposes never share a key. The values
/// are part of every result: changing one changes the pinned state hash.
#pragma once

#include <cstdint>

namespace snow::random_stream {

inline constexpr std::uint32_t spawn_activate = 1; ///< how many flakes an emitter starts
inline constexpr std::uint32_t spawn_position = 2; ///< where on the emitter a flake starts
inline constexpr std::uint32_t spawn_size = 3; ///< a new parcel's size (so its mass and fall speed)
inline constexpr std::uint32_t spawn_rounding = 5; ///< a new parcel's mass rounded to whole units
inline constexpr std::uint32_t wind_walk = 6;      ///< the wind's bounded random walk
inline constexpr std::uint32_t wind_gust = 7;      ///< whether a gust starts
inline constexpr std::uint32_t roll = 8;           ///< the lower neighbour a landing rolls to
inline constexpr std::uint32_t settle = 9;     ///< rounding of a cell's settling to whole levels
inline constexpr std::uint32_t transport = 10; ///< rounding of a face's flux to whole units
inline constexpr std::uint32_t test = 1000;    ///< tests placing random flakes or colliders
inline constexpr std::uint32_t spectral_volume = 2000; ///< phases and speeds of far-field snow

} // namespace snow::random_stream
