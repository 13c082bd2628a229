// validate() for every user-facing settings struct, in one place (Box2D's
// def-struct habit): the facade and the scene loader both call these.
#include "systems/validation.hpp"

#include "systems/emitter.hpp"
#include "systems/fog.hpp"
#include "systems/limits.hpp"
#include "systems/sim_config.hpp"
#include "systems/spectral_snow.hpp"
#include "systems/units.hpp"

#include <algorithm>

namespace snow {

namespace {
bool power_of_two(std::uint32_t v) {
    return v != 0 && (v & (v - 1)) == 0;
}
} // namespace

Invalid validate(const SimConfig& c) {
    Invalid e;
    check::positive(e, "simulation.dt", c.dt);
    check::at_most(e, "simulation.dt", c.dt, max_dt);
    check::finite3(e, "simulation.gravity", c.gravity);
    check::finite3(e, "simulation.bounds.min", c.bounds.min);
    check::finite3(e, "simulation.bounds.max", c.bounds.max);
    check::ordered(e, "simulation.bounds.min.x", c.bounds.min.x, "simulation.bounds.max.x",
                   c.bounds.max.x);
    check::ordered(e, "simulation.bounds.min.y", c.bounds.min.y, "simulation.bounds.max.y",
                   c.bounds.max.y);
    check::ordered(e, "simulation.bounds.min.z", c.bounds.min.z, "simulation.bounds.max.z",
                   c.bounds.max.z);
    if (c.max_flakes == 0) {
        check::fail(e, "simulation.max_flakes", ">= 1", 0);
    }
    check::at_most(e, "simulation.max_flakes", c.max_flakes, max_flakes);
    if (c.threads == 0) {
        check::fail(e, "simulation.threads", ">= 1", 0);
    }
    check::at_most(e, "simulation.threads", c.threads, max_threads);
    if (c.smoothing_iterations == 0) {
        check::fail(e, "simulation.smoothing_iterations", ">= 1", 0);
    }
    check::at_most(e, "simulation.smoothing_iterations", c.smoothing_iterations,
                   max_smoothing_iterations);
    if (integrator_name(c.integrator) == "unknown") {
        check::fail(e, "simulation.integrator", "one of " + integrator_choices(),
                    static_cast<double>(c.integrator));
    }
    return e;
}

Invalid validate(const Emitter& m) {
    Invalid e;
    check::non_negative(e, "emitter.rate", m.rate);
    check::at_most(e, "emitter.rate", m.rate, max_emitter_rate);
    const double min_g = unit_kg * 1000.0;
    const double max_g = min_g * max_flake_units;
    check::positive(e, "emitter.mass_min_g", m.mass_min_g);
    check::positive(e, "emitter.mass_max_g", m.mass_max_g);
    if (std::isfinite(m.mass_min_g) && m.mass_min_g > 0.0f && m.mass_min_g + 1e-9 < min_g) {
        check::fail(e, "emitter.mass_min_g", ">= " + std::to_string(min_g), m.mass_min_g);
    }
    check::at_most(e, "emitter.mass_max_g", m.mass_max_g, max_g + 1e-9);
    check::ordered(e, "emitter.mass_min_g", m.mass_min_g, "emitter.mass_max_g", m.mass_max_g);
    check::positive(e, "emitter.size_min", m.size_min);
    check::positive(e, "emitter.size_max", m.size_max);
    check::at_most(e, "emitter.size_max", m.size_max, max_flake_size);
    check::ordered(e, "emitter.size_min", m.size_min, "emitter.size_max", m.size_max);
    check::positive(e, "emitter.fall_speed_min", m.fall_speed_min);
    check::positive(e, "emitter.fall_speed_max", m.fall_speed_max);
    check::at_most(e, "emitter.fall_speed_max", m.fall_speed_max, max_fall_speed);
    check::ordered(e, "emitter.fall_speed_min", m.fall_speed_min, "emitter.fall_speed_max",
                   m.fall_speed_max);
    return e;
}

Invalid validate(const Aabb& box) {
    Invalid e;
    check::finite3(e, "box.min", box.min);
    check::finite3(e, "box.max", box.max);
    check::ordered(e, "box.min.x", box.min.x, "box.max.x", box.max.x);
    check::ordered(e, "box.min.y", box.min.y, "box.max.y", box.max.y);
    check::ordered(e, "box.min.z", box.min.z, "box.max.z", box.max.z);
    return e;
}

Invalid validate(const FlakeSpec& f) {
    Invalid e;
    check::finite3(e, "flake.position", f.position);
    check::finite3(e, "flake.velocity", f.velocity);
    check::positive(e, "flake.k_over_m", f.k_over_m);
    check::non_negative(e, "flake.size", f.size);
    if (f.mass_units < 1 || f.mass_units > max_flake_units) {
        check::fail(e, "flake.mass_units", "in [1, " + std::to_string(max_flake_units) + "]",
                    f.mass_units);
    }
    return e;
}

Invalid validate(const Wind& w) {
    Invalid e;
    check::finite3(e, "wind.base", w.base);
    check::finite3(e, "wind.current", w.current);
    check::finite3(e, "wind.deviation", w.deviation);
    check::non_negative(e, "wind.walk", w.walk);
    check::non_negative(e, "wind.max_deviation", w.max_deviation);
    check::non_negative(e, "wind.gust_strength", w.gust_strength);
    check::non_negative(e, "wind.gust_rate", w.gust_rate);
    check::positive(e, "wind.gust_duration", w.gust_duration);
    check::non_negative(e, "wind.gust_left", w.gust_left);
    for (const float c : {w.base.x, w.base.y, w.base.z}) {
        check::at_most(e, "wind.base (each component's magnitude)", std::abs(c),
                       max_wind_base_component);
    }
    return e;
}

Invalid validate(const Fog& f) {
    Invalid e;
    check::finite3(e, "fog.color", f.color);
    check::non_negative(e, "fog.density", f.density);
    check::positive(e, "fog.half_distance", f.half_distance);
    check::finite(e, "fog.layer_bottom", f.layer_bottom);
    check::finite(e, "fog.layer_top", f.layer_top);
    check::ordered(e, "fog.layer_bottom", f.layer_bottom, "fog.layer_top", f.layer_top);
    check::non_negative(e, "fog.layer_density", f.layer_density);
    for (std::size_t i = 0; i < f.puffs.size(); ++i) {
        const std::string p = "fog.puffs[" + std::to_string(i) + "]";
        check::finite3(e, p + ".center", f.puffs[i].center);
        check::positive(e, p + ".sigma", f.puffs[i].sigma);
        check::non_negative(e, p + ".density", f.puffs[i].density);
        check::finite3(e, p + ".frequency", f.puffs[i].frequency);
        check::finite(e, p + ".phase", f.puffs[i].phase);
    }
    return e;
}

Invalid validate(const SpectralSnow& s) {
    Invalid e;
    const auto range = [](std::uint32_t lo, std::uint32_t hi) {
        return "a power of two in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    };
    if (!power_of_two(s.size_xy) || s.size_xy < min_spectral_size_xy ||
        s.size_xy > max_spectral_size_xy) {
        check::fail(e, "spectral.size_xy", range(min_spectral_size_xy, max_spectral_size_xy),
                    s.size_xy);
    }
    if (!power_of_two(s.size_t) || s.size_t < min_spectral_size_t ||
        s.size_t > max_spectral_size_t) {
        check::fail(e, "spectral.size_t", range(min_spectral_size_t, max_spectral_size_t),
                    s.size_t);
    }
    check::positive(e, "spectral.speed", s.speed);
    check::positive(e, "spectral.band_low", s.band_low);
    check::positive(e, "spectral.band_high", s.band_high);
    check::ordered(e, "spectral.band_low", s.band_low, "spectral.band_high", s.band_high);
    check::at_most(e, "spectral.band_high", s.band_high, s.size_xy / 2.0);
    check::non_negative(e, "spectral.opacity", s.opacity);
    check::at_most(e, "spectral.opacity", s.opacity, 1.0);
    check::non_negative(e, "spectral.start_distance", s.start_distance);
    return e;
}

Invalid validate(const BodyMotion& m) {
    Invalid e;
    if (m.waypoints.empty()) {
        e = {"motion.waypoints", "must hold at least one point (got none)"};
    }
    for (std::size_t i = 0; i < m.waypoints.size() && e.empty(); ++i) {
        check::finite3(e, "motion.waypoints[" + std::to_string(i) + "]", m.waypoints[i]);
    }
    check::non_negative(e, "motion.speed", m.speed);
    check::at_most(e, "motion.speed", m.speed, max_body_speed);
    return e;
}

Invalid validate(const BodyDef& d) {
    Invalid e;
    if (d.shape != BodyShape::sphere && d.shape != BodyShape::box &&
        d.shape != BodyShape::capsule) {
        check::fail(e, "body.shape", "sphere, box or capsule", static_cast<double>(d.shape));
    }
    check::finite3(e, "body.position", d.position);
    if (d.shape == BodyShape::box) {
        check::positive(e, "body.half_extents.x", d.half_extents.x);
        check::positive(e, "body.half_extents.y", d.half_extents.y);
        check::positive(e, "body.half_extents.z", d.half_extents.z);
        check::at_most(e, "body.half_extents (largest)",
                       std::max({d.half_extents.x, d.half_extents.y, d.half_extents.z}),
                       max_body_size);
    } else {
        check::positive(e, "body.radius", d.radius);
        check::at_most(e, "body.radius", d.radius, max_body_size);
    }
    if (d.shape == BodyShape::capsule) {
        check::non_negative(e, "body.half_height", d.half_height);
        check::at_most(e, "body.half_height", d.half_height, max_body_size);
    }
    if (e.empty() && d.snowball && d.shape != BodyShape::sphere) {
        e = {"body.snowball", "needs shape sphere"};
    }
    if (e.empty() && !d.motion.waypoints.empty()) {
        e = validate(d.motion);
    }
    return e;
}

} // namespace snow
