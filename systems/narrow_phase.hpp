/// @file narrow_phase.hpp
/// @brief Exact tests of one flake's path this tick, the segment p0→p1,
/// against one collider shape [WF §4] or moving body. Swept, so a fast flake cannot
/// jump over a shape in one tick. The collide system picks the shapes near
/// the path (collider_grid.hpp) and calls these.
#pragma once

#include "systems/body.hpp"
#include "systems/geometry.hpp"

#include <glm/vec3.hpp>

namespace snow {

/// p lies in the open box (on a face is outside).
[[nodiscard]] bool strictly_inside(const Aabb& b, const glm::vec3& p);

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

/// The face through which the segment p0→p1 enters the open box (slab test;
/// a corner hit counts as a top hit), or, when p0 is already inside and p1
/// still is, the face nearest to p1 (the top on a tie). False when the
/// segment never reaches the interior or is leaving it.
[[nodiscard]] bool box_contact(const Aabb& b, const glm::vec3& p0, const glm::vec3& p1,
                               BoxContact& k);

/// Where the relative path a→e (a flake's path in a moving body's frame,
/// the body's centre at the origin) meets the body: the point on its surface
/// the flake is put on. Spheres are swept; boxes by the slab test above;
/// capsules test the path's end.
[[nodiscard]] bool body_contact(const Body& b, const glm::vec3& a, const glm::vec3& e,
                                glm::vec3& out);

} // namespace snow
