#include "game/play/camera_controller.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace snow {

namespace {
constexpr float look_radians_per_pixel = 0.0035f;
constexpr std::array<std::string_view, 3> mode_names{"walk", "fly", "orbit"};
} // namespace

std::string_view camera_mode_name(CameraMode m) {
    return mode_names[static_cast<std::size_t>(m)];
}

std::optional<CameraMode> find_camera_mode(std::string_view name) {
    for (std::size_t i = 0; i < mode_names.size(); ++i) {
        if (mode_names[i] == name) {
            return static_cast<CameraMode>(i);
        }
    }
    return std::nullopt;
}

CameraController::CameraController(const ViewCamera& start, const glm::vec3& orbit_target)
    : camera_(start), target_(orbit_target) {
    distance_ = std::max(1.0f, glm::length(start.position - orbit_target));
}

void CameraController::set_mode(CameraMode m) {
    mode_ = m;
    if (mode_ == CameraMode::orbit) {
        distance_ = std::max(1.0f, glm::length(camera_.position - target_));
        camera_.look_at(target_);
        place_on_orbit();
    } else if (mode_ == CameraMode::walk) {
        camera_.pitch = std::clamp(camera_.pitch, -0.3f, 0.1f); // look ahead, not at the sky
    }
}

void CameraController::place_on_orbit() {
    camera_.position = target_ - camera_.forward() * distance_;
}

glm::vec2 CameraController::facing() const {
    return {std::sin(camera_.yaw), -std::cos(camera_.yaw)}; // yaw 0 looks along -z
}

void CameraController::update(const CameraInput& in, float seconds) {
    camera_.turn(in.look.x * look_radians_per_pixel, -in.look.y * look_radians_per_pixel);
    switch (mode_) {
    case CameraMode::walk:
        return;
    case CameraMode::orbit:
        distance_ = std::clamp(distance_ * std::pow(0.9f, in.scroll), 1.0f, 150.0f);
        place_on_orbit();
        return;
    case CameraMode::fly:
        break;
    }
    speed_ = std::clamp(speed_ * std::pow(1.2f, in.scroll), 0.25f, 100.0f);
    const glm::vec3 up{0.0f, 1.0f, 0.0f};
    camera_.position +=
        (camera_.right() * in.move.x + up * in.move.y + camera_.forward() * in.move.z) *
        (speed_ * seconds);
}

} // namespace snow
