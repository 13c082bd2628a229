// narrow_phase: segment against open box and open sphere, the exact tests
// behind collide's slides, landings and sphere removals [WF §4], and the
// flake-against-moving-body test.
#include "systems/narrow_phase.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

bool strictly_inside(const Aabb& b, const glm::vec3& p) {
    return p.x > b.min.x && p.x < b.max.x && p.y > b.min.y && p.y < b.max.y && p.z > b.min.z &&
           p.z < b.max.z;
}

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

namespace {

/// The path's bounding box misses the open box: the usual case, no divisions.
bool bounds_miss(const Aabb& b, const glm::vec3& p0, const glm::vec3& p1) {
    const glm::vec3 lo = glm::min(p0, p1), hi = glm::max(p0, p1);
    return (hi.x <= b.min.x) | (lo.x >= b.max.x) | (hi.y <= b.min.y) | (lo.y >= b.max.y) |
           (hi.z <= b.min.z) | (lo.z >= b.max.z);
}

/// p0 and p1 both inside: the face nearest to p1; the top is tried first so a
/// tie lands the flake.
void nearest_face(const Aabb& b, const glm::vec3& p1, BoxContact& k) {
    const float dist[6] = {b.max.y - p1.y, p1.x - b.min.x, b.max.x - p1.x,
                           p1.z - b.min.z, b.max.z - p1.z, p1.y - b.min.y};
    const int axes[6] = {1, 0, 0, 2, 2, 1};
    const bool maxes[6] = {true, false, true, false, true, false};
    int best = 0;
    for (int f = 1; f < 6; ++f) {
        best = dist[f] < dist[best] ? f : best;
    }
    k.axis = axes[best];
    k.max_side = maxes[best];
    k.at = p1;
    k.at[k.axis] = k.max_side ? b.max[k.axis] : b.min[k.axis];
    k.t = 0.0f;
}

} // namespace

bool box_contact(const Aabb& b, const glm::vec3& p0, const glm::vec3& p1, BoxContact& k) {
    if (bounds_miss(b, p0, p1)) {
        return false;
    }
    if (strictly_inside(b, p0)) {
        if (!strictly_inside(b, p1)) {
            return false;
        }
        nearest_face(b, p1, k);
        return true;
    }
    float enter = -std::numeric_limits<float>::infinity();
    float exit = std::numeric_limits<float>::infinity();
    int axis = -1;
    bool max_side = false;
    for (const int a : {1, 0, 2}) { // y first: a corner hit counts as a top hit
        const float d = p1[a] - p0[a];
        if (d == 0.0f) {
            if (!(p0[a] > b.min[a] && p0[a] < b.max[a])) {
                return false;
            }
            continue;
        }
        const float t_min = (b.min[a] - p0[a]) / d;
        const float t_max = (b.max[a] - p0[a]) / d;
        const float near = d > 0.0f ? t_min : t_max;
        const float far = d > 0.0f ? t_max : t_min;
        if (near > enter) {
            enter = near;
            axis = a;
            max_side = d < 0.0f;
        }
        exit = std::min(exit, far);
    }
    if (axis < 0 || !(enter < exit) || !(enter < 1.0f) || !(exit > 0.0f)) {
        return false;
    }
    k.axis = axis;
    k.max_side = max_side;
    k.at = p0 + (p1 - p0) * enter;
    for (int a = 0; a < 3; ++a) {
        k.at[a] = std::clamp(k.at[a], b.min[a], b.max[a]);
    }
    k.at[axis] = max_side ? b.max[axis] : b.min[axis];
    k.t = enter;
    return true;
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
