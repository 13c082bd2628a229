// Body shapes, validation and the snowball's growth.
#include "systems/body.hpp"

#include "systems/limits.hpp"
#include "systems/units.hpp"
#include "systems/validation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snow {

bool Body::bottom_at(float centre_y, float dx, float dz, float& y) const {
    if (shape == BodyShape::box) {
        if (!(std::abs(dx) <= half_extents.x && std::abs(dz) <= half_extents.z)) {
            return false;
        }
        y = centre_y - half_extents.y;
        return true;
    }
    const float d2 = dx * dx + dz * dz;
    if (!(d2 <= radius * radius)) {
        return false;
    }
    const float core = shape == BodyShape::capsule ? half_height : 0.0f;
    y = centre_y - core - std::sqrt(radius * radius - d2);
    return true;
}

float Body::reach() const {
    return shape == BodyShape::box ? std::max(half_extents.x, half_extents.z) : radius;
}

std::string validate(const BodyMotion& m) {
    std::string e;
    if (m.waypoints.empty()) {
        e = "motion.waypoints must hold at least one point (got none)";
    }
    for (std::size_t i = 0; i < m.waypoints.size() && e.empty(); ++i) {
        check::finite3(e, "motion.waypoints[" + std::to_string(i) + "]", m.waypoints[i]);
    }
    check::non_negative(e, "motion.speed", m.speed);
    check::at_most(e, "motion.speed", m.speed, max_body_speed);
    return e;
}

std::string validate(const BodyDef& d) {
    std::string e;
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
    if (d.snowball && d.shape != BodyShape::sphere) {
        e = e.empty() ? "body.snowball needs shape sphere" : e;
    }
    if (e.empty() && !d.motion.waypoints.empty()) {
        e = validate(d.motion);
    }
    return e;
}

Body make_body(const BodyDef& d) {
    Body b;
    b.shape = d.shape;
    b.radius = b.bare_radius = d.radius;
    b.half_extents = d.half_extents;
    b.half_height = d.half_height;
    b.on_ground = d.on_ground;
    b.snowball = d.snowball;
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
