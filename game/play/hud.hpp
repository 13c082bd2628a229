/// @file hud.hpp
/// @brief The on-screen HUD of the windowed game (Dear ImGui): fps, flakes,
/// the mass ledger, the time scale, the snow under the walking player, ms per
/// system and per render pass, and the key list.
#pragma once

#include "game/play/game_session.hpp"
#include <snow/render.hpp>

struct GLFWwindow;

namespace snow {

class Hud {
  public:
    /// Installs ImGui on the window (chains the GLFW callbacks of the
    /// InputReader made before it).
    explicit Hud(GLFWwindow* window);
    ~Hud();
    Hud(const Hud&) = delete;
    Hud& operator=(const Hud&) = delete;

    /// True while ImGui wants the mouse (the camera should not move).
    [[nodiscard]] bool wants_mouse() const;
    /// Draws the session's state (reads it only), `frame`'s render timings and `fps`.
    void draw(const GameSession& session, const FrameTimings& frame, float fps);
};

} // namespace snow
