/// @file emitter.hpp
/// @brief Where and how flakes are born ([WF §3–4], [ZCL §III]).
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <snow/defs.hpp>

namespace snow {

class StateHasher;
/// Every setting of the emitter (the host may change its rate).
void hash_state(StateHasher& h, const Emitter& m);

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
