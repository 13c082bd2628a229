/// @file scene_visuals.hpp
/// @brief What a scene looks like beyond the simulation: meshes, lights, the
/// camera it starts with, ambient and sky. The scene loader returns it beside
/// the Simulation and the renderer reads it; the simulation never does, so it
/// holds no GL and no simulation state (plain data, header only).
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace snow {

/// A triangle mesh in world space.
struct MeshRenderable {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; ///< per vertex, same count as positions
    std::vector<std::uint32_t> indices;
    glm::vec3 color{0.6f, 0.6f, 0.6f};
};

/// A coloured point light ([WF §5] uses three).
struct PointLight {
    glm::vec3 position{0.0f, 5.0f, 0.0f};
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    float intensity = 1.0f;
};

/// The view the scene starts with.
struct CameraDef {
    glm::vec3 position{0.0f, 4.0f, 14.0f};
    glm::vec3 target{0.0f, 1.5f, 0.0f};
    float fov_y_deg = 50.0f;
    float near_plane = 0.05f, far_plane = 200.0f;
};

/// Ambient light and sky colour.
struct Environment {
    glm::vec3 ambient{0.18f, 0.2f, 0.24f};
    glm::vec3 sky{0.55f, 0.62f, 0.7f};
};

/// Everything the renderer draws besides the simulation's own state, in draw order.
struct SceneVisuals {
    std::vector<MeshRenderable> meshes;
    std::vector<PointLight> lights; ///< the renderer uses the first 8
    CameraDef camera;
    Environment environment;
};

} // namespace snow
