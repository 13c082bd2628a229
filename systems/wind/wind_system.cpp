// wind: one global vector doing a bounded random walk around its base
// ([WF §6] "allowed to change by small random amounts"), plus optional gusts.
#include "ecs/rng.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/wind/wind.hpp"

#include <cmath>

namespace snow {

void wind_system(World& w) {
    const auto& cfg = w.resource<SimConfig>();
    const std::uint64_t tick = w.resource<SimClock>().tick;
    Wind& wind = w.resource<Wind>();
    const RngKey walk_key{cfg.seed, tick, 0, random_stream::wind_walk};

    glm::vec3 dev = wind.deviation;
    const float base_speed = std::sqrt(wind.base.x * wind.base.x + wind.base.z * wind.base.z);
    const glm::vec3 base_dir = base_speed > 0.0f
                                   ? glm::vec3(wind.base.x, 0.0f, wind.base.z) / base_speed
                                   : glm::vec3(0.0f);

    // Uniform steps of unit variance (±√3), scaled by walk·√dt: a Wiener-like walk.
    const float step = wind.walk * std::sqrt(cfg.dt) * 1.7320508f;
    dev.x += step * (2.0f * rng_uniform(walk_key, 0) - 1.0f);
    dev.z += step * (2.0f * rng_uniform(walk_key, 1) - 1.0f);
    dev.y += 0.25f * step * (2.0f * rng_uniform(walk_key, 2) - 1.0f);
    const float len = std::sqrt(dev.x * dev.x + dev.y * dev.y + dev.z * dev.z);
    if (len > wind.max_deviation && len > 0.0f) {
        dev *= wind.max_deviation / len; // bounded walk
    }

    float gust = 0.0f;
    if (wind.gust_strength > 0.0f) {
        const RngKey gust_key{cfg.seed, tick, 0, random_stream::wind_gust};
        if (wind.gust_left <= 0.0f && rng_uniform(gust_key) < wind.gust_rate * cfg.dt) {
            wind.gust_left = wind.gust_duration;
        }
        if (wind.gust_left > 0.0f) {
            // Smooth rise and fall over the gust: sin(π·phase).
            const float phase = 1.0f - wind.gust_left / wind.gust_duration;
            gust = wind.gust_strength * std::sin(3.14159265f * phase);
            wind.gust_left = std::max(0.0f, wind.gust_left - cfg.dt);
        }
    }
    wind.deviation = dev;
    wind.current = wind.base + dev + base_dir * gust;
}

} // namespace snow
