/// @file game_play.hpp
/// @brief Test support: snow_game's input, session and frames without the
/// window or GL, played the way the game's loop plays them.
#pragma once

#include "game/play/game_input.hpp"
#include "game/play/game_options.hpp"
#include "game/play/game_session.hpp"
#include "game/play/input_reader.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace snow::test {

/// Options for a quick session: the built-in village at low quality (one
/// 1/30 s tick a headless frame), or the project scene `scene` (assets/).
inline GameOptions quick_game(const std::string& scene = "") {
    GameOptions o;
    o.quality = 0;
    if (!scene.empty()) {
        o.scene = std::string(SNOW_SOURCE_DIR) + "/assets/" + scene;
    }
    return o;
}

/// A session with its input: `keys` is a --inject list (empty: none).
struct GamePlay {
    std::unique_ptr<GameSession> session;
    InputReader input;
    std::uint64_t frame = 0;

    explicit GamePlay(const GameOptions& options, const std::string& keys = "")
        : session(GameSession::open(options)),
          input(nullptr, keys.empty() ? KeyScript{} : parse_key_script(keys)) {
        if (!session) {
            throw std::runtime_error("the scene does not load"); // fails the test
        }
    }

    /// `n` headless frames: each reads the input and updates the session.
    void play(int n = 1) {
        for (int i = 0; i < n; ++i) {
            session->update(input.read(frame, false), frame, std::nullopt);
            ++frame;
        }
    }
    /// One frame in which `glfw_key` goes down.
    void press(int glfw_key) {
        input.key_pressed(glfw_key);
        play();
    }
    [[nodiscard]] const Simulation& sim() const { return session->sim(); }
};

} // namespace snow::test
