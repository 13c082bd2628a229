/// @file geometry.hpp
/// @brief Plain geometric value types shared by components.
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <glm/vec3.hpp>

#include <snow/defs.hpp>

namespace snow {

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
/// `box.porosity` in [0, 1): a porous box still stops some air.
[[nodiscard]] Invalid validate_porosity(float porosity);

} // namespace snow
