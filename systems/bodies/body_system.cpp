// bodies: every body takes this tick's pose, in pool order: the host's
// target (move_body), else along its path, else by its velocity. A walker
// or rolling ball then stands on the bare ground under its centre: the
// highest within a step of its feet, so it passes under roofs.
#include "systems/api/systems.hpp"
#include "systems/bodies/body.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/snowpack/snow_surface.hpp"

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

/// The bare top (m) a body whose feet may reach `reach` stands on at (x, z):
/// the highest of any surface or cover cell at or below it (so it passes
/// under a roof), else the lowest above it (it climbs out of what buried it).
bool ground_under(const World& w, float x, float z, float reach, float& y) {
    float below = -std::numeric_limits<float>::infinity();
    float above = std::numeric_limits<float>::infinity();
    w.each<SnowSurface>([&](Entity, const SnowSurface& s) {
        std::uint32_t ix = 0, iz = 0;
        if (s.cell_at(x, z, ix, iz) && !s.is_void(s.index(ix, iz))) {
            const float base = s.height(s.base_level[s.index(ix, iz)]);
            if (base <= reach) {
                below = std::max(below, base);
            } else {
                above = std::min(above, base);
            }
        }
    });
    y = below > -std::numeric_limits<float>::infinity() ? below : above;
    return y != std::numeric_limits<float>::infinity();
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
        // It steps up by at most its own radius from where it stood.
        const float reach = b.previous.y - centre_height(b) + b.reach();
        float ground = 0.0f;
        if (b.on_ground && ground_under(w, p.x, p.z, reach, ground)) {
            p.y = ground + centre_height(b);
        }
        b.position = p;
    }
}

} // namespace snow
