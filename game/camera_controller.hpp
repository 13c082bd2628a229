/// @file camera_controller.hpp
/// @brief Fly camera (WASD + mouse, scroll for speed) and orbit camera
/// (drag to circle a target, scroll to zoom) over render's ViewCamera.
#pragma once

#include "render/camera.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace snow {

/// Input sampled once per frame.
struct CameraInput {
    glm::vec3 move{0.0f}; ///< x: right, y: up, z: forward, each -1..1
    glm::vec2 look{0.0f}; ///< mouse delta in pixels while looking/dragging
    float scroll = 0.0f;  ///< wheel steps this frame
};

class CameraController {
  public:
    explicit CameraController(const ViewCamera& start, const glm::vec3& orbit_target);

    void set_orbit(bool on);
    [[nodiscard]] bool orbit() const { return orbit_; }
    [[nodiscard]] float speed() const { return speed_; }
    /// Applies one frame of input over `seconds` of wall time.
    void update(const CameraInput& in, float seconds);
    [[nodiscard]] const ViewCamera& camera() const { return camera_; }

  private:
    void place_on_orbit();

    ViewCamera camera_;
    glm::vec3 target_;
    bool orbit_ = false;
    float speed_ = 4.0f; ///< fly speed (m/s)
    float distance_ = 10.0f;
};

} // namespace snow
