#include "systems/core/sim_config.hpp"

#include "systems/core/state_bytes.hpp"

#include <array>
#include <string>
#include <utility>

namespace snow {

namespace {
constexpr std::array<std::pair<Integrator, std::string_view>, 5> integrator_names{{
    {Integrator::explicit_euler, "euler"},
    {Integrator::semi_implicit_euler, "semi_implicit"},
    {Integrator::exponential, "exponential"},
    {Integrator::rk4, "rk4"},
    {Integrator::automatic, "auto"},
}};
} // namespace

std::string_view integrator_name(Integrator i) {
    for (const auto& [value, name] : integrator_names) {
        if (value == i) {
            return name;
        }
    }
    return "unknown";
}

std::string integrator_choices() {
    std::string s;
    for (const auto& [value, name] : integrator_names) {
        s += (s.empty() ? "" : ", ") + std::string(name);
    }
    return s;
}

std::optional<Integrator> parse_integrator(std::string_view name) {
    for (const auto& [value, n] : integrator_names) {
        if (n == name) {
            return value;
        }
    }
    return std::nullopt;
}

Invalid validate(const SimConfig& c) {
    Invalid e = check_fields("simulation", sim_config_fields, c);
    check_box(e, "simulation.bounds", c.bounds);
    if (integrator_name(c.integrator) == "unknown") {
        check::fail(e, "simulation.integrator", "one of " + integrator_choices(),
                    static_cast<double>(c.integrator));
    }
    return e;
}

void hash_state(StateHasher& h, const SimConfig& c) {
    ByteWriter out(h);
    out(c.seed);
    out(c.dt);
    out(c.gravity);
    out(c.integrator);
    out(c.bounds.min);
    out(c.bounds.max);
    out(c.max_flakes);
    out(c.smoothing_iterations);
    out(c.air_temperature);
    out(c.settle_interval);
}

} // namespace snow
