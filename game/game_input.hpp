/// @file game_input.hpp
/// @brief What the player can do in snow_game, the keys for it, and scripted
/// key injection (--inject) used by tests and demos.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

enum class Action : std::uint8_t {
    pause,        ///< P: pause / resume the simulation
    step,         ///< N: advance one tick while paused
    reset,        ///< R: back to the scene's first tick
    rate_up,      ///< +: more snowfall
    rate_down,    ///< -: less snowfall
    wind_left,    ///< left arrow: rotate wind 15° counter-clockwise (seen from above)
    wind_right,   ///< right arrow: rotate wind 15° clockwise
    wind_up,      ///< up arrow: stronger wind
    wind_down,    ///< down arrow: weaker wind
    toggle_fog,   ///< F: fog on / off
    quality_next, ///< Q: next quality preset (reloads the scene)
    screenshot,   ///< F12 or C: write a PNG
    toggle_orbit, ///< O: fly camera <-> orbit camera
    toggle_help,  ///< H: show / hide the key list
    quit,         ///< Esc
};

/// The key name and description of every action, for the help overlay.
struct KeyHelp {
    const char* key;
    const char* what;
};
[[nodiscard]] const std::vector<KeyHelp>& key_help();

/// The action bound to a GLFW key code, if any.
[[nodiscard]] std::optional<Action> action_for_key(int glfw_key);

/// A key press scheduled at a frame number.
struct InjectedKey {
    std::uint64_t frame = 0;
    Action action = Action::pause;
};

/// Parses "FRAME:KEY,FRAME:KEY,..." with KEY one of P N R + - LEFT RIGHT UP
/// DOWN F Q C O H ESC; throws std::invalid_argument naming the bad item.
[[nodiscard]] std::vector<InjectedKey> parse_injected_keys(std::string_view text);

} // namespace snow
