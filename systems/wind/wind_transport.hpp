/// @file wind_transport.hpp
/// @brief Snow the wind moves: where the wind field blows faster than a
/// threshold just above a snow cell, part of the cell's snow leaves it
/// downwind (saltation), to the neighbouring cell or, where the surface ends,
/// as flakes. Only with a declared wind field and transport. See
/// docs/wind_field.md "Transport".
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

namespace snow {

/// Settings of the transport; see Simulation::set_wind_transport().
struct WindTransportDef {
    /// Horizontal wind speed (m/s) below which snow stays put. Dry, loose
    /// snow starts to drift at about 4–5 m/s measured a little above it.
    float threshold = 5.0f;
    /// Fraction of a cell's snow that leaves per second per m/s of wind above
    /// the threshold (1/(m/s·s)).
    float rate = 0.02f;
    /// Most of a cell's snow that leaves in one field step (0..1]: keeps a
    /// gale from emptying cells faster than the step resolves.
    float max_fraction = 0.25f;
    /// Height (m) above the snow top at which the wind is read.
    float height = 0.25f;
};

/// `wind.field.transport.*`.
inline constexpr FieldRule<WindTransportDef> wind_transport_fields[] = {
    {"threshold", &WindTransportDef::threshold, positive_up_to(max_wind_base_component)},
    {"rate", &WindTransportDef::rate, between(0, max_transport_rate)},
    {"max_fraction", &WindTransportDef::max_fraction, positive_up_to(1)},
    {"height", &WindTransportDef::height, between(0, max_transport_height)},
};

[[nodiscard]] Invalid validate(const WindTransportDef& t);

} // namespace snow
