// narrow_phase: segment against open box and open sphere, the exact tests
// behind collide's slides, landings and sphere removals [WF §4], and the
// flake-against-moving-body test.
#include "systems/geometry/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

bool sphere_entry(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& center, float radius,
                  float& t) {
    const glm::vec3 d = p1 - p0;
    const glm::vec3 w = p0 - center;
    const float c = w.x * w.x + w.y * w.y + w.z * w.z - radius * radius;
    if (c < 0.0f) {
        t = 0.0f;
        return true;
    }
    const float a = d.x * d.x + d.y * d.y + d.z * d.z;
    const float b = w.x * d.x + w.y * d.y + w.z * d.z; // half the linear coefficient
    const float disc = b * b - a * c;
    if (!(a > 0.0f) || !(disc > 0.0f) || !(b < 0.0f)) {
        return false; // still, grazing, or moving away
    }
    t = (-b - std::sqrt(disc)) / a;
    return t < 1.0f;
}

bool body_contact(const Body& b, const glm::vec3& a, const glm::vec3& e, glm::vec3& out) {
    switch (b.shape) {
    case BodyShape::box: {
        BoxContact k;
        if (!box_contact(Aabb{-b.half_extents, b.half_extents}, a, e, k)) {
            return false;
        }
        out = k.at;
        return true;
    }
    case BodyShape::capsule: {
        const glm::vec3 core{0.0f, std::clamp(e.y, -b.half_height, b.half_height), 0.0f};
        const glm::vec3 d = e - core;
        const float len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (!(len < b.radius)) {
            return false;
        }
        out = core + (len > 0.0f ? d / len : glm::vec3{1.0f, 0.0f, 0.0f}) * b.radius;
        return true;
    }
    case BodyShape::sphere:
        break;
    }
    float t = 0.0f;
    if (!sphere_entry(a, e, glm::vec3{0.0f}, b.radius, t)) {
        return false;
    }
    const glm::vec3 q = a + (e - a) * t;
    const float len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    out = (len > 0.0f ? q / len : glm::vec3{0.0f, 1.0f, 0.0f}) * b.radius;
    return true;
}

} // namespace snow
