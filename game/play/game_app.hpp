/// @file game_app.hpp
/// @brief snow_game: loads a scene, runs the simulation at a fixed tick and
/// draws it, in a window (with input and HUD) or headless to PNG frames.
#pragma once

#include "game/play/game_options.hpp"

namespace snow {

/// Runs the game; returns the process exit status (0 ok, 2 bad scene, 1 other).
[[nodiscard]] int run_game(const GameOptions& options);

} // namespace snow
