/// @file game_app.hpp
/// @brief snow_game: loads a scene, runs the simulation at a fixed tick and
/// draws it, in a window (with input and HUD) or headless to PNG frames.
#pragma once

#include "game/game_input.hpp"
#include "game/scene/scene_loader.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace snow {

struct GameOptions {
    std::optional<std::string> scene; ///< glTF file; default the built-in village
    bool headless = false;            ///< force headless rendering
    std::uint64_t frames = 0;         ///< stop after this many frames (0: no limit)
    std::string out_dir;              ///< headless: where PNG frames go
    double seconds = 0.0;             ///< stop after this much wall time (0: no limit)
    int width = 1280, height = 720;
    std::uint64_t warmup_ticks = 0;  ///< ticks simulated before the first frame
    std::size_t quality = 1;         ///< index into quality_presets
    std::vector<InjectedKey> inject; ///< scripted key presses
    bool video = false;              ///< headless: encode frames with ffmpeg if present
    SceneOverrides overrides;
};

/// Runs the game; returns the process exit status (0 ok, 2 bad scene, 1 other).
[[nodiscard]] int run_game(const GameOptions& options);

} // namespace snow
