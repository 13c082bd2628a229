#include <snow/render.hpp>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>

namespace snow {

namespace {
constexpr float max_pitch = 1.5533430f; // 89°: keeps look-at away from the up vector
}

ViewCamera ViewCamera::from_def(const CameraDef& def) {
    ViewCamera c;
    c.position = def.position;
    c.fov_y_deg = def.fov_y_deg;
    c.near_plane = def.near_plane;
    c.far_plane = def.far_plane;
    c.look_at(def.target);
    return c;
}

void ViewCamera::look_at(const glm::vec3& target) {
    const glm::vec3 d = target - position;
    const float horizontal = std::sqrt(d.x * d.x + d.z * d.z);
    if (horizontal == 0.0f && d.y == 0.0f) {
        return;
    }
    yaw = std::atan2(d.x, -d.z);
    pitch = std::clamp(std::atan2(d.y, horizontal), -max_pitch, max_pitch);
}

void ViewCamera::turn(float d_yaw, float d_pitch) {
    yaw += d_yaw;
    pitch = std::clamp(pitch + d_pitch, -max_pitch, max_pitch);
}

glm::vec3 ViewCamera::forward() const {
    const float cp = std::cos(pitch);
    return {cp * std::sin(yaw), std::sin(pitch), -cp * std::cos(yaw)};
}

glm::vec3 ViewCamera::right() const {
    return {std::cos(yaw), 0.0f, std::sin(yaw)};
}

glm::mat4 ViewCamera::view() const {
    return glm::lookAt(position, position + forward(), glm::vec3(0.0f, 1.0f, 0.0f));
}

glm::mat4 ViewCamera::projection(float aspect) const {
    return glm::perspective(glm::radians(fov_y_deg), aspect, near_plane, far_plane);
}

} // namespace snow
