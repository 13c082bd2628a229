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

/// `emitter.*` (`crystal` is a choice the scene reads by name); each
/// min <= its max is checked by validate().
inline constexpr FieldRule<Emitter> emitter_fields[] = {
    {"rate", &Emitter::rate, between(0, max_emitter_rate)},
    {"snowfall_kg_m2_h", &Emitter::snowfall_kg_m2_h, between(0, max_snowfall_kg_m2_h)},
    {"size_mean", &Emitter::size_mean, positive_up_to(max_flake_size)},
    {"size_min", &Emitter::size_min, positive_up_to(max_flake_size)},
    {"size_max", &Emitter::size_max, positive_up_to(max_flake_size)},
};

[[nodiscard]] Invalid validate(const Emitter& e);

/// validate(), and that the emitter's parcels fit in a flake over `bounds`:
/// the heaviest parcel (size_max) may carry at most max_flake_units.
[[nodiscard]] Invalid validate(const Emitter& e, const Aabb& bounds);

} // namespace snow
