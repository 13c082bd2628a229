// Body shapes and the snowball's growth (validate(BodyDef) is in validation.cpp).
#include "systems/bodies/body.hpp"

#include "systems/core/limits.hpp"
#include "systems/core/state_bytes.hpp"
#include "systems/core/units.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <string>

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
    b.motion = body_path(d.motion);
    return b;
}

BodyPath body_path(const BodyMotion& motion) {
    return {Vector<glm::vec3>(motion.waypoints.begin(), motion.waypoints.end()), motion.speed,
            motion.loop};
}

float snowball_radius(float bare_radius, std::uint64_t units) {
    const double r0 = bare_radius;
    const double volume = static_cast<double>(units) * unit_kg / packed_snow_density;
    return static_cast<float>(std::cbrt(r0 * r0 * r0 + 3.0 * volume / (4.0 * std::numbers::pi)));
}

namespace {

template <typename Io, typename B>
void body_record(Io& io, B& b) {
    io(b.shape);
    for (auto* v :
         {&b.radius, &b.half_height, &b.bare_radius, &b.compaction, &b.along, &b.motion.speed}) {
        io(*v);
    }
    for (auto* v : {&b.half_extents, &b.position, &b.previous, &b.velocity, &b.target}) {
        io(*v);
    }
    for (auto* v : {&b.on_ground, &b.snowball, &b.has_target, &b.motion.loop}) {
        io(*v);
    }
    io(b.motion.waypoints);
    io(b.segment);
    io(b.carried);
}

bool finite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

void save_state(ByteWriter& out, const Body& b) {
    body_record(out, b);
}

void load_state(ByteReader& in, Body& b) {
    body_record(in, b);
    in.require_below(b.shape, BodyShape{3});
    bool ok = true;
    for (const float v :
         {b.radius, b.half_height, b.bare_radius, b.compaction, b.along, b.motion.speed}) {
        ok = ok && std::isfinite(v) && v >= 0.0f;
    }
    for (const glm::vec3& v : {b.half_extents, b.position, b.previous, b.velocity, b.target}) {
        ok = ok && finite(v);
    }
    for (const glm::vec3& v : b.motion.waypoints) {
        ok = ok && finite(v);
    }
    in.require(ok, "has a negative or non-finite size, speed or position");
    in.require(b.motion.waypoints.empty() ? b.segment == 0 : b.segment < b.motion.waypoints.size(),
               "heads from a waypoint its path does not have");
}

Invalid validate(const BodyMotion& m) {
    Invalid e;
    if (m.waypoints.empty()) {
        e = {"motion.waypoints", "must hold at least one point (got none)"};
    }
    check::finite_each(e, "motion.waypoints", m.waypoints);
    check_fields(e, "motion", motion_fields, m);
    return e;
}

Invalid validate(const BodyDef& d) {
    Invalid e;
    if (d.shape != BodyShape::sphere && d.shape != BodyShape::box &&
        d.shape != BodyShape::capsule) {
        check::fail(e, "body.shape", "sphere, box or capsule", static_cast<double>(d.shape));
    }
    check_fields(e, "body", body_fields, d);
    if (d.shape == BodyShape::box) {
        check_fields(e, "body", box_body_fields, d);
    } else if (d.shape == BodyShape::sphere) {
        check_fields(e, "body", sphere_body_fields, d);
    } else if (d.shape == BodyShape::capsule) {
        check_fields(e, "body", capsule_body_fields, d);
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
