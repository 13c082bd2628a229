/// @file emitter.hpp
/// @brief Where and how flakes are born ([WF §3–4], [ZCL §III]).
#pragma once

#include <string>

namespace snow {

/// Component. Flakes appear on the top and the upwind sides of the
/// simulation bounds [WF §5], with mass and size drawn uniformly.
struct Emitter {
    float rate = 2000.0f;        ///< expected flakes per second
    float mass_min_g = 0.005f;   ///< [WF §3]: 0.005 g ..
    float mass_max_g = 5.0f;     ///< .. 5 g
    float size_min = 0.002f;     ///< diameter (m)
    float size_max = 0.0254f;    ///< [WF §3]: common 0.0254 m
    float fall_speed_min = 0.5f; ///< terminal speed in still air (m/s); sets k/m = g / v
    float fall_speed_max = 1.5f;
};

/// Returns an error naming the bad field, or an empty string.
[[nodiscard]] std::string validate(const Emitter& e);

} // namespace snow
