/// @file emitter.hpp
/// @brief Where and how flakes are born ([WF §3–4], [ZCL §III]).
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

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

/// `emitter.*`; each min <= its max is checked by validate().
inline constexpr FieldRule<Emitter> emitter_fields[] = {
    {"rate", &Emitter::rate, between(0, max_emitter_rate)},
    {"mass_min_g", &Emitter::mass_min_g, between(min_flake_mass_g, max_flake_mass_g)},
    {"mass_max_g", &Emitter::mass_max_g, between(min_flake_mass_g, max_flake_mass_g)},
    {"size_min", &Emitter::size_min, positive_up_to(max_flake_size)},
    {"size_max", &Emitter::size_max, positive_up_to(max_flake_size)},
    {"fall_speed_min", &Emitter::fall_speed_min, positive_up_to(max_fall_speed)},
    {"fall_speed_max", &Emitter::fall_speed_max, positive_up_to(max_fall_speed)},
};

[[nodiscard]] Invalid validate(const Emitter& e);

} // namespace snow
