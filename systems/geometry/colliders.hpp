/// @file colliders.hpp
/// @brief Collider shapes [WF §4]. An entity with a collider and a
/// SnowSurface keeps the snow that lands on its top.
#pragma once

#include "ecs/host_memory.hpp"
#include "systems/geometry/geometry.hpp"

#include <glm/vec3.hpp>

namespace snow {

/// Box: a flake inside is moved to the nearest point outside and slides
/// along the face (builds drifts at windward bases, [WF §4]).
struct BoxCollider {
    Aabb box;
    /// Share of its area open to the air (a slat fence: 0.5); 0 = solid. The
    /// wind field lets air through a porous box against a pressure loss
    /// (docs/wind_field.md "Porous fences"); flakes meet it as a box.
    float porosity = 0.0f;
};

/// Sphere: a flake that enters is eliminated ([WF §4], the snowman).
struct SphereCollider {
    glm::vec3 center{0.0f};
    float radius = 0.5f;
};

/// Triangle mesh in world space (3 vertices per triangle). Flakes meet its
/// top through the occlusion map, never by per-triangle tests [SKY].
struct MeshCollider {
    Vector<glm::vec3> triangles;
};

} // namespace snow
