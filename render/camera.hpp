/// @file camera.hpp
/// @brief The view camera: position, yaw/pitch and a perspective lens.
#pragma once

#include "render/scene_visuals.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace snow {

/// A free-look camera. yaw = 0 looks along −z, positive yaw turns toward +x;
/// pitch > 0 looks up. Angles in radians, pitch kept inside ±89°.
struct ViewCamera {
    glm::vec3 position{0.0f, 4.0f, 14.0f};
    float yaw = 0.0f;
    float pitch = 0.0f;
    float fov_y_deg = 50.0f;
    float near_plane = 0.05f;
    float far_plane = 200.0f;

    /// The camera a scene starts with (position, look-at target, lens).
    [[nodiscard]] static ViewCamera from_def(const CameraDef& def);
    /// Turns the camera to look at `target` (no change if target == position).
    void look_at(const glm::vec3& target);
    /// Adds to yaw/pitch, clamping pitch.
    void turn(float d_yaw, float d_pitch);
    [[nodiscard]] glm::vec3 forward() const;
    [[nodiscard]] glm::vec3 right() const;
    [[nodiscard]] glm::mat4 view() const;
    [[nodiscard]] glm::mat4 projection(float aspect) const;
};

} // namespace snow
