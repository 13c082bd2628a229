/// @file wind.hpp
/// @brief One global wind vector with a bounded random walk [WF §6].
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <glm/vec3.hpp>

#include <snow/defs.hpp>

namespace snow {

class ByteWriter;
class ByteReader;

/// The wind's snapshot record: its settings and its walk and gust state.
void save_state(ByteWriter& out, const Wind& w);
/// Reads a record of save_state into `w` (its values are validated by the caller).
void load_state(ByteReader& in, Wind& w);

/// `wind.*`; current, deviation and gust_left are its running state.
inline constexpr FieldRule<Wind> wind_fields[] = {
    {"base", &Wind::base, between(-max_wind_base_component, max_wind_base_component)},
    {"current", &Wind::current},
    {"deviation", &Wind::deviation},
    {"walk", &Wind::walk, non_negative},
    {"max_deviation", &Wind::max_deviation, non_negative},
    {"gust_strength", &Wind::gust_strength, non_negative},
    {"gust_rate", &Wind::gust_rate, non_negative},
    {"gust_duration", &Wind::gust_duration, positive},
    {"gust_left", &Wind::gust_left, non_negative},
};

[[nodiscard]] Invalid validate(const Wind& w);

} // namespace snow
