/// @file hud_info.hpp
/// @brief What the HUD shows besides the simulation's own numbers, read off
/// the session: kept apart from the drawing (Dear ImGui, game/play/hud.hpp) so it
/// is built, and tested, without a window.
#pragma once

#include "game/play/game_session.hpp"

#include <cstdint>
#include <optional>
#include <string>

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

/// The session's state for the HUD; `fps` is the app's frame rate.
[[nodiscard]] HudInfo hud_info(const GameSession& session, float fps);

} // namespace snow
