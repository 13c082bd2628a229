/// @file camera_controller.hpp
/// @brief The camera of snow_game over render's ViewCamera: walk (the eye of
/// the player, placed by the game; the mouse looks), fly (WASD + mouse,
/// scroll for speed) and orbit (drag to circle a target, scroll to zoom).
#pragma once

#include <snow/render.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string_view>

namespace snow {

enum class CameraMode : std::uint8_t { walk, fly, orbit };

[[nodiscard]] std::string_view camera_mode_name(CameraMode m);
/// The mode named `name` ("walk", "fly", "orbit"), if any.
[[nodiscard]] std::optional<CameraMode> find_camera_mode(std::string_view name);

/// Input sampled once per frame.
struct CameraInput {
    glm::vec3 move{0.0f}; ///< x: right, y: up, z: forward, each -1..1
    glm::vec2 look{0.0f}; ///< mouse delta in pixels while looking/dragging
    float scroll = 0.0f;  ///< wheel steps this frame
};

class CameraController {
  public:
    explicit CameraController(const ViewCamera& start, const glm::vec3& orbit_target);

    void set_mode(CameraMode m);
    [[nodiscard]] CameraMode mode() const { return mode_; }
    [[nodiscard]] float speed() const { return speed_; }
    /// Applies one frame of input over `seconds` of wall time (walk: looking only).
    void update(const CameraInput& in, float seconds);
    /// Walk: puts the eye at `eye` (the game follows the player with it).
    void place(const glm::vec3& eye) { camera_.position = eye; }
    [[nodiscard]] const ViewCamera& camera() const { return camera_; }
    /// The horizontal unit vector the camera faces (walking forward).
    [[nodiscard]] glm::vec2 facing() const;

  private:
    void place_on_orbit();

    ViewCamera camera_;
    glm::vec3 target_;
    CameraMode mode_ = CameraMode::fly;
    float speed_ = 4.0f; ///< fly speed (m/s)
    float distance_ = 10.0f;
};

} // namespace snow
