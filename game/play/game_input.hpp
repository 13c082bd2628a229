/// @file game_input.hpp
/// @brief The keys of snow_game's actions (game/play/player_actions.hpp), and
/// scripted key injection (--inject) used by tests and demos.
#pragma once

#include "game/play/player_actions.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

/// Keys that act while held: walking (walk camera) or flying (fly camera).
enum class MoveKey : std::uint8_t { forward, back, left, right };
inline constexpr std::size_t move_key_count = 4;

/// The key name and description of every action, for the help overlay.
struct KeyHelp {
    const char* key;
    const char* what;
};
[[nodiscard]] const std::vector<KeyHelp>& key_help();

/// The action bound to a GLFW key code, if any.
[[nodiscard]] std::optional<Action> action_for_key(int glfw_key);
/// The GLFW key code of a movement key.
[[nodiscard]] int glfw_key_of(MoveKey k);

/// A key press scheduled at a frame number.
struct InjectedKey {
    std::uint64_t frame = 0;
    Action action = Action::pause;
};

/// A movement key held from `frame` for `frames` frames.
struct InjectedHold {
    std::uint64_t frame = 0;
    std::uint64_t frames = 1;
    MoveKey key = MoveKey::forward;
};

/// A parsed --inject list.
struct KeyScript {
    std::vector<InjectedKey> presses;
    std::vector<InjectedHold> holds;
    /// True while a hold of `key` covers `frame`.
    [[nodiscard]] bool held(MoveKey key, std::uint64_t frame) const;
};

/// Parses "ITEM,ITEM,..." with ITEM either FRAME:KEY (a press; KEY one of P
/// N R + - LEFT RIGHT UP DOWN F V Q C O T B H ESC) or FRAME:MOVE[:FRAMES] (W A
/// S D held for FRAMES frames, default 1). Throws std::invalid_argument
/// naming the bad item; a list or item naming no key is an error.
[[nodiscard]] KeyScript parse_key_script(std::string_view text);

} // namespace snow
