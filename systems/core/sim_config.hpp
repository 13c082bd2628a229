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

namespace snow {

class TaskSystem;

enum class Integrator : std::uint8_t {
    explicit_euler,      ///< v += a·dt, p += v·dt ([WF], [ZCL]); guarded when stiff
    semi_implicit_euler, ///< implicit drag, then p += v_new·dt (never overshoots)
    exponential,         ///< exact update for gravity + linear drag to constant wind
    rk4,                 ///< classical Runge-Kutta, the accuracy reference
    automatic,           ///< explicit Euler where k·dt/m <= 0.5, exponential elsewhere
};

[[nodiscard]] std::string_view integrator_name(Integrator i);
[[nodiscard]] std::optional<Integrator> parse_integrator(std::string_view name);
/// Every integrator name, comma-separated, for error messages.
[[nodiscard]] std::string integrator_choices();

struct SimConfig {
    std::uint64_t seed = 1;
    float dt = 1.0f / 60.0f;               ///< fixed tick length (s)
    glm::vec3 gravity{0.0f, -9.81f, 0.0f}; ///< m/s^2
    Integrator integrator = Integrator::explicit_euler;
    Aabb bounds{{-10.0f, -1.0f, -10.0f}, {10.0f, 12.0f, 10.0f}}; ///< flakes leaving it are removed
    std::uint32_t max_flakes = 50000;
    /// Threads of the built-in pool (the caller is one of them); ignored
    /// when the host gives its own task_system.
    unsigned threads = 1;
    /// The host's task system (not owned; it must outlive the Simulation).
    /// Null: the built-in pool. Results are the same either way.
    TaskSystem* task_system = nullptr;
    /// Smoothing sub-iterations per surface per tick [WF §3]; a pile still
    /// moving after that many continues next tick.
    std::uint32_t smoothing_iterations = 64;
};

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
};

[[nodiscard]] Invalid validate(const SimConfig& c);

} // namespace snow
