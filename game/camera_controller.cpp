#include "game/camera_controller.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace snow {

namespace {
constexpr float look_radians_per_pixel = 0.0035f;
}

CameraController::CameraController(const ViewCamera& start, const glm::vec3& orbit_target)
    : camera_(start), target_(orbit_target) {
    distance_ = std::max(1.0f, glm::length(start.position - orbit_target));
}

void CameraController::set_orbit(bool on) {
    orbit_ = on;
    if (orbit_) {
        distance_ = std::max(1.0f, glm::length(camera_.position - target_));
        camera_.look_at(target_);
        place_on_orbit();
    }
}

void CameraController::place_on_orbit() {
    camera_.position = target_ - camera_.forward() * distance_;
}

void CameraController::update(const CameraInput& in, float seconds) {
    camera_.turn(in.look.x * look_radians_per_pixel, -in.look.y * look_radians_per_pixel);
    if (orbit_) {
        distance_ = std::clamp(distance_ * std::pow(0.9f, in.scroll), 1.0f, 150.0f);
        place_on_orbit();
        return;
    }
    speed_ = std::clamp(speed_ * std::pow(1.2f, in.scroll), 0.25f, 100.0f);
    const glm::vec3 up{0.0f, 1.0f, 0.0f};
    camera_.position +=
        (camera_.right() * in.move.x + up * in.move.y + camera_.forward() * in.move.z) *
        (speed_ * seconds);
}

} // namespace snow
