/// @file input_reader.hpp
/// @brief The input part of snow_game: each frame, the window's keys and
/// mouse (when there is a window) and the key script's presses and holds
/// become one PlayerActions. Without a window only the script speaks, so a
/// headless run and a test play the way a player at the keyboard does.
#pragma once

#include "game/play/game_input.hpp"
#include "game/play/player_actions.hpp"

#include <cstdint>
#include <vector>

struct GLFWwindow;

namespace snow {

class InputReader {
  public:
    /// Listens to `window`'s keys and wheel through its GLFW callbacks, so
    /// make it before the HUD, which chains them; `window` may be null.
    InputReader(GLFWwindow* window, KeyScript script);
    // The window's callbacks point at this object: it stays where it is.
    InputReader(const InputReader&) = delete;
    InputReader& operator=(const InputReader&) = delete;

    /// A key went down (the window's key callback calls it, a test may too).
    void key_pressed(int glfw_key);
    /// The wheel turned `steps` (the window's scroll callback).
    void scrolled(double steps);

    /// Frame `frame`'s actions: the keys pressed since the last read, then the
    /// script's presses at `frame`; the keys held and the mouse now (no
    /// buttons while `hud_has_mouse`).
    [[nodiscard]] PlayerActions read(std::uint64_t frame, bool hud_has_mouse);

  private:
    [[nodiscard]] bool window_key(int glfw_key) const;

    GLFWwindow* window_;
    KeyScript script_;
    std::vector<Action> pressed_; ///< window presses not read yet
    float scroll_ = 0.0f;         ///< wheel steps not read yet
    double last_x_ = 0.0, last_y_ = 0.0;
};

} // namespace snow
