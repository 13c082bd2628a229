/// @file wind_transport.hpp
/// @brief Snow the wind moves: a saltation flux over every surface, from the
/// field's wind just above the snow (saltation.hpp); snow is eroded and laid
/// down where the flux changes along the wind, and leaves as flakes where the
/// surface ends. Only with a declared wind field and transport. See
/// docs/wind_field.md "Transport".
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <snow/defs.hpp>

namespace snow {

/// `wind.field.transport.*`.
inline constexpr FieldRule<WindTransportDef> wind_transport_fields[] = {
    {"roughness", &WindTransportDef::roughness, positive_up_to(max_transport_roughness)},
    {"height", &WindTransportDef::height, positive_up_to(max_transport_height)},
    {"fast_forward", &WindTransportDef::fast_forward, between(1, max_transport_fast_forward)},
    {"adjustment_length", &WindTransportDef::adjustment_length,
     positive_up_to(max_transport_adjustment_length)},
};

[[nodiscard]] Invalid validate(const WindTransportDef& t);

} // namespace snow
