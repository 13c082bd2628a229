/// @file player_actions.hpp
/// @brief What the player asked for in one frame, as plain data: the input
/// part (game/play/input_reader.hpp) fills it from the window and the key script,
/// the session (game/play/game_session.hpp) carries it out. Neither side needs the
/// other: tests write these by hand.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace snow {

/// Keys that act once per press.
enum class Action : std::uint8_t {
    pause,         ///< P: pause / resume the simulation
    step,          ///< N: advance one tick while paused
    reset,         ///< R: back to the scene's first tick
    rate_up,       ///< +: more snowfall
    rate_down,     ///< -: less snowfall
    wind_left,     ///< left arrow: rotate wind 15° counter-clockwise (seen from above)
    wind_right,    ///< right arrow: rotate wind 15° clockwise
    wind_up,       ///< up arrow: stronger wind
    wind_down,     ///< down arrow: weaker wind
    toggle_fog,    ///< F: fog on / off
    toggle_wind,   ///< V: draw the wind field as arrows, on / off
    quality_next,  ///< Q: next quality preset (reloads the scene)
    screenshot,    ///< F12 or C: write a PNG
    next_camera,   ///< O: walk -> fly -> orbit camera
    time_scale,    ///< T: simulated time per frame x1, x4, x16, x64
    push_snowball, ///< B: push the snowball ahead (make one if there is none)
    toggle_help,   ///< H: show / hide the key list
    quit,          ///< Esc
};

/// One frame of the player's wishes: the presses in the order they came, and
/// what was held. The mouse buttons are reported, not interpreted, because
/// which one looks depends on the camera mode, which the session knows.
struct PlayerActions {
    std::vector<Action> presses;
    glm::vec3 move{0.0f};  ///< held keys: x right, y up, z forward, each -1..1
    glm::vec2 mouse{0.0f}; ///< cursor movement since the last frame (pixels)
    /// The buttons, both false while the HUD has the mouse (a click on it moves no camera).
    bool look_button = false; ///< right button held (looks in every mode)
    bool drag_button = false; ///< left button held (circles the orbit camera)
    float scroll = 0.0f;      ///< wheel steps since the last frame
};

} // namespace snow
