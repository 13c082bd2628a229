/// @file geometry.hpp
/// @brief Plain geometric value types shared by components.
#pragma once

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

} // namespace snow
