/// @file wind_transport.hpp
/// @brief Snow the wind moves: where the wind field blows faster than a
/// threshold just above a snow cell, part of the cell's snow leaves it
/// downwind (saltation), to the neighbouring cell or, where the surface ends,
/// as flakes. Only with a declared wind field and transport. See
/// docs/wind_field.md "Transport".
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <snow/defs.hpp>

namespace snow {

/// `wind.field.transport.*`.
inline constexpr FieldRule<WindTransportDef> wind_transport_fields[] = {
    {"threshold", &WindTransportDef::threshold, positive_up_to(max_wind_base_component)},
    {"rate", &WindTransportDef::rate, between(0, max_transport_rate)},
    {"max_fraction", &WindTransportDef::max_fraction, positive_up_to(1)},
    {"height", &WindTransportDef::height, between(0, max_transport_height)},
};

[[nodiscard]] Invalid validate(const WindTransportDef& t);

} // namespace snow
