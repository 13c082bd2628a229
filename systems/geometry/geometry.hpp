/// @file geometry.hpp
/// @brief Plain geometric value types shared by components.
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <glm/vec3.hpp>

namespace snow {

/// Axis-aligned box, min <= max on every axis.
struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    [[nodiscard]] bool contains(const glm::vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
               p.z <= max.z;
    }
    [[nodiscard]] glm::vec3 size() const { return max - min; }
};

/// u with component `axis` (0 x, 1 y, 2 z) set to s. By selects, not an
/// indexed store: an indexed store keeps the vector in memory, and its next
/// whole read then waits for that store to land.
[[nodiscard]] inline glm::vec3 with_component(const glm::vec3& u, int axis, float s) {
    return {axis == 0 ? s : u.x, axis == 1 ? s : u.y, axis == 2 ? s : u.z};
}

/// A box's corners (min <= max per axis is checked by validate()).
inline constexpr FieldRule<Aabb> aabb_fields[] = {
    {"min", &Aabb::min},
    {"max", &Aabb::max},
};

/// The corners of `box` finite and min <= max on every axis ("prefix.max.x", ...).
void check_box(Invalid& e, std::string_view prefix, const Aabb& box);
/// A box collider's extent (fields "box.min", "box.max").
[[nodiscard]] Invalid validate(const Aabb& box);

} // namespace snow
