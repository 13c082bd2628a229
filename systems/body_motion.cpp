// bodies: every body takes this tick's pose, in pool order: the host's
// target (move_body), else along its path, else by its velocity. A walker
// or rolling ball then stands on the highest bare ground under its centre.
#include "systems/body.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace snow {

namespace {

/// The point `speed`·dt further along the path; updates segment / along.
glm::vec3 advance(Body& b, float dt) {
    const auto& wp = b.motion.waypoints;
    const auto n = static_cast<std::uint32_t>(wp.size());
    if (n < 2) {
        return wp.front();
    }
    float left = b.motion.speed * dt;
    // A lap of zero-length segments must not spin forever: at most n steps a tick.
    for (std::uint32_t steps = 0; steps <= n; ++steps) {
        const std::uint32_t next = (b.segment + 1) % n;
        const bool last = b.segment + 1 == n;
        if (last && !b.motion.loop) {
            b.along = 0.0f;
            return wp.back(); // the path's end: it stays
        }
        const glm::vec3 d = wp[next] - wp[b.segment];
        const float length = glm::length(d);
        if (b.along + left < length) {
            b.along += left;
            return wp[b.segment] + d * (b.along / length);
        }
        left -= length - b.along;
        b.segment = next;
        b.along = 0.0f;
    }
    return wp[b.segment];
}

/// Highest bare top (m) of any surface or cover cell under (x, z).
bool ground_under(const World& w, float x, float z, float& y) {
    bool found = false;
    y = -std::numeric_limits<float>::infinity();
    w.each<SnowSurface>([&](Entity, const SnowSurface& s) {
        std::uint32_t ix = 0, iz = 0;
        if (s.cell_at(x, z, ix, iz) && !s.is_void(s.index(ix, iz))) {
            y = std::max(y, s.height(s.base_level[s.index(ix, iz)]));
            found = true;
        }
    });
    return found;
}

/// Distance (m) from the centre down to the lowest point.
float centre_height(const Body& b) {
    switch (b.shape) {
    case BodyShape::box:
        return b.half_extents.y;
    case BodyShape::capsule:
        return b.half_height + b.radius;
    case BodyShape::sphere:
        break;
    }
    return b.radius;
}

} // namespace

void body_system(World& w) {
    const float dt = w.resource<SimConfig>().dt;
    for (Body& b : w.pool<Body>().components()) {
        b.previous = b.position;
        glm::vec3 p = b.position;
        if (b.has_target) {
            p = b.target;
            b.has_target = false;
        } else if (!b.motion.waypoints.empty()) {
            p = advance(b, dt);
        } else {
            p += b.velocity * dt;
        }
        float ground = 0.0f;
        if (b.on_ground && ground_under(w, p.x, p.z, ground)) {
            p.y = ground + centre_height(b);
        }
        b.position = p;
    }
}

} // namespace snow
