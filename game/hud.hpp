/// @file hud.hpp
/// @brief The on-screen HUD of the windowed game (Dear ImGui): fps, flakes,
/// the mass ledger, the time scale, the snow under the walking player, ms per
/// system and per render pass, and the key list.
#pragma once

#include "render/frame_timings.hpp"
#include "systems/api/simulation.hpp"

#include <cstdint>
#include <optional>
#include <string>

struct GLFWwindow;

namespace snow {

struct HudInfo {
    float fps = 0.0f;
    bool paused = false;
    bool help = true;
    bool fog_on = false;
    std::string quality;
    std::string camera_mode;
    std::string last_message;
    std::uint32_t time_scale = 1;      ///< simulated time per frame (×)
    std::uint64_t ticks_per_frame = 0; ///< ticks the last frame ran
    bool ticks_capped = false;         ///< the frame budget held them back
    std::optional<float> depth_under;  ///< walk: snow under the player (m)
    std::optional<float> depth_ahead;  ///< walk: snow 1 m ahead (m)
};

class Hud {
  public:
    /// Installs ImGui on the window (chains the app's GLFW callbacks).
    explicit Hud(GLFWwindow* window);
    ~Hud();
    Hud(const Hud&) = delete;
    Hud& operator=(const Hud&) = delete;

    /// True while ImGui wants the mouse (the camera should not move).
    [[nodiscard]] bool wants_mouse() const;
    void draw(const Simulation& sim, const FrameTimings& frame, const HudInfo& info);
};

} // namespace snow
