// Body shapes and the snowball's growth (validate(BodyDef) is in validation.cpp).
#include "systems/body.hpp"

#include "systems/limits.hpp"
#include "systems/units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snow {

bool Body::extent_at(float dx, float dz, float& below, float& above) const {
    if (shape == BodyShape::box) {
        if (!(std::abs(dx) <= half_extents.x && std::abs(dz) <= half_extents.z)) {
            return false;
        }
        below = above = half_extents.y;
        return true;
    }
    const float d2 = dx * dx + dz * dz;
    if (!(d2 <= radius * radius)) {
        return false;
    }
    const float cap = std::sqrt(radius * radius - d2);
    if (shape == BodyShape::capsule) {
        below = half_height + radius;
        above = half_height + cap;
    } else {
        below = above = cap;
    }
    return true;
}

float Body::reach() const {
    return shape == BodyShape::box ? std::max(half_extents.x, half_extents.z) : radius;
}

Body make_body(const BodyDef& d) {
    Body b;
    b.shape = d.shape;
    b.radius = b.bare_radius = d.radius;
    b.half_extents = d.half_extents;
    b.half_height = d.half_height;
    b.on_ground = d.on_ground;
    b.snowball = d.snowball;
    b.compaction = d.compaction;
    b.position = b.previous = d.position;
    b.motion = d.motion;
    return b;
}

float snowball_radius(float bare_radius, std::uint64_t units) {
    const double r0 = bare_radius;
    const double volume = static_cast<double>(units) * unit_kg / packed_snow_density;
    return static_cast<float>(std::cbrt(r0 * r0 * r0 + 3.0 * volume / (4.0 * std::numbers::pi)));
}

} // namespace snow
