/// @file sim_config.hpp
/// @brief Global simulation settings and the tick clock (World resources).
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"
#include "systems/geometry/geometry.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include <snow/defs.hpp>

namespace snow {

[[nodiscard]] std::string_view integrator_name(Integrator i);
[[nodiscard]] std::optional<Integrator> parse_integrator(std::string_view name);
/// Every integrator name, comma-separated, for error messages.
[[nodiscard]] std::string integrator_choices();

struct SimClock {
    std::uint64_t tick = 0; ///< ticks completed
};

/// `simulation.*` (bounds and the integrator are checked by validate()).
inline constexpr FieldRule<SimConfig> sim_config_fields[] = {
    {"seed", &SimConfig::seed},
    {"dt", &SimConfig::dt, positive_up_to(max_dt)},
    {"gravity", &SimConfig::gravity},
    {"max_flakes", &SimConfig::max_flakes, between(1, max_flakes)},
    {"threads", &SimConfig::threads, between(1, max_threads)},
    {"smoothing_iterations", &SimConfig::smoothing_iterations,
     between(1, max_smoothing_iterations)},
    {"air_temperature", &SimConfig::air_temperature,
     between(min_air_temperature, max_air_temperature)},
    {"settle_interval", &SimConfig::settle_interval, positive_up_to(max_settle_interval)},
};

[[nodiscard]] Invalid validate(const SimConfig& c);

/// The density (kg/m³) snow lands at in this run: one level of every surface
/// is one unit at it (SnowSurface::unit_height).
[[nodiscard]] inline double fresh_snow_density(const SimConfig& c) {
    return fresh_snow_density(c.air_temperature);
}

class StateHasher;
/// Field by field, so no padding byte enters the hash. Not the thread count
/// or task system: they change no result.
void hash_state(StateHasher& h, const SimConfig& c);

} // namespace snow
