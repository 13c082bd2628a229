/// @file box_world.hpp
/// @brief Test support: a still-air 10 × 10 × 10 m box to snow into.
#pragma once

#include <snow/snow.hpp>

#include <cstdint>

namespace snow::test {

/// Side (m) of box_world's floor.
inline constexpr float box_world_side = 10.0f;

/// Bounds x, z in [−5, 5], y in [0, 10]; no surfaces, no wind.
inline SimConfig box_world(std::uint32_t max_flakes) {
    SimConfig c;
    c.max_flakes = max_flakes;
    c.bounds = {{-5.0f, 0.0f, -5.0f}, {5.0f, 10.0f, 5.0f}};
    return c;
}

} // namespace snow::test
