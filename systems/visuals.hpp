/// @file visuals.hpp
/// @brief Plain data the renderer reads: meshes, lights, the camera. The
/// simulation never reads these; they live here so a scene is one World.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace snow {

/// Component: a triangle mesh in world space.
struct MeshRenderable {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; ///< per vertex, same count as positions
    std::vector<std::uint32_t> indices;
    glm::vec3 color{0.6f, 0.6f, 0.6f};
};

/// Component: a coloured point light ([WF §5] uses three).
struct PointLight {
    glm::vec3 position{0.0f, 5.0f, 0.0f};
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    float intensity = 1.0f;
};

/// World resource: the view the scene starts with.
struct CameraDef {
    glm::vec3 position{0.0f, 4.0f, 14.0f};
    glm::vec3 target{0.0f, 1.5f, 0.0f};
    float fov_y_deg = 50.0f;
    float near_plane = 0.05f, far_plane = 200.0f;
};

/// World resource: ambient light and sky colour.
struct Environment {
    glm::vec3 ambient{0.18f, 0.2f, 0.24f};
    glm::vec3 sky{0.55f, 0.62f, 0.7f};
};

} // namespace snow
