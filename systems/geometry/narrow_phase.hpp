/// @file narrow_phase.hpp
/// @brief Exact tests of one flake's path this tick, the segment p0→p1,
/// against one collider shape [WF §4] or moving body. Swept, so a fast flake cannot
/// jump over a shape in one tick. The collide system picks the shapes near
/// the path (collider_grid.hpp) and calls these.
#pragma once

#include "systems/bodies/body.hpp"
#include "systems/geometry/geometry.hpp"

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <limits>

namespace snow {

/// p lies in the open box (on a face is outside).
[[nodiscard]] inline bool strictly_inside(const Aabb& b, const glm::vec3& p) {
    return p.x > b.min.x && p.x < b.max.x && p.y > b.min.y && p.y < b.max.y && p.z > b.min.z &&
           p.z < b.max.z;
}

/// Where along p0→p1 (t in [0, 1)) the segment enters the open sphere: 0 if
/// p0 is already inside; false if it never does (still, grazing, or moving away).
[[nodiscard]] bool sphere_entry(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& center,
                                float radius, float& t);

/// A face of a box that a path met, and the point on it.
struct BoxContact {
    int axis = 0;          ///< 0 x, 1 y, 2 z
    bool max_side = false; ///< the face at box.max[axis] (outward normal +axis)
    glm::vec3 at{0.0f};    ///< entry point (swept hit) or nearest face point
    float t = 0.0f;        ///< where along the path: 0 when it started inside
};

namespace narrow_phase_detail {

/// The path's bounding box misses the open box: the usual case, no divisions.
inline bool bounds_miss(const Aabb& b, const glm::vec3& p0, const glm::vec3& p1) {
    const glm::vec3 lo = glm::min(p0, p1), hi = glm::max(p0, p1);
    return (hi.x <= b.min.x) | (lo.x >= b.max.x) | (hi.y <= b.min.y) | (lo.y >= b.max.y) |
           (hi.z <= b.min.z) | (lo.z >= b.max.z);
}

/// p0 and p1 both inside: the face nearest to p1; the top is tried first so a
/// tie lands the flake.
inline void nearest_face(const Aabb& b, const glm::vec3& p1, BoxContact& k) {
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
    k.at = with_component(p1, k.axis, k.max_side ? b.max[k.axis] : b.min[k.axis]);
    k.t = 0.0f;
}

} // namespace narrow_phase_detail

/// The face through which the segment p0→p1 enters the open box (slab test;
/// a corner hit counts as a top hit), or, when p0 is already inside and p1
/// still is, the face nearest to p1 (the top on a tie). False when the
/// segment never reaches the interior or is leaving it.
/// Inline: collide calls it for every box near a low path, and a call
/// returns the contact through memory the caller then reloads whole.
[[nodiscard, gnu::always_inline]] inline bool box_contact(const Aabb& b, const glm::vec3& p0,
                                                          const glm::vec3& p1, BoxContact& k) {
    if (narrow_phase_detail::bounds_miss(b, p0, p1)) {
        return false;
    }
    if (strictly_inside(b, p0)) {
        if (!strictly_inside(b, p1)) {
            return false;
        }
        narrow_phase_detail::nearest_face(b, p1, k);
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
    k.at = with_component(k.at, axis, max_side ? b.max[axis] : b.min[axis]);
    k.t = enter;
    return true;
}

/// Where the relative path a→e (a flake's path in a moving body's frame,
/// the body's centre at the origin) meets the body: the point on its surface
/// the flake is put on. Spheres are swept; boxes by the slab test above;
/// capsules test the path's end.
[[nodiscard]] bool body_contact(const Body& b, const glm::vec3& a, const glm::vec3& e,
                                glm::vec3& out);

} // namespace snow
