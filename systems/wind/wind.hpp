/// @file wind.hpp
/// @brief One global wind vector with a bounded random walk [WF §6].
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <glm/vec3.hpp>

namespace snow {

class ByteWriter;
class ByteReader;

/// World resource. Without it there is no wind system and air is still.
struct Wind {
    glm::vec3 base{2.0f, 0.0f, 0.0f};    ///< mean wind (m/s)
    glm::vec3 current{2.0f, 0.0f, 0.0f}; ///< this tick's wind (state)
    glm::vec3 deviation{0.0f};           ///< state: random-walk offset from base
    float walk = 0.2f;                   ///< random-walk step size (m/s per sqrt(s))
    float max_deviation = 1.0f;          ///< |current - base| stays below this (m/s)
    float gust_strength = 0.0f;          ///< extra speed of a gust along base (m/s)
    float gust_rate = 0.0f;              ///< gusts started per second
    float gust_duration = 1.5f;          ///< seconds
    float gust_left = 0.0f;              ///< state: seconds of the running gust
};

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
