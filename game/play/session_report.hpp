/// @file session_report.hpp
/// @brief What snow_game prints about a session, read off it: the moment a
/// frame shows (simulated time, ground snow), the headless progress line and
/// the report at the end of a run (mass ledger, the player's trail).
#pragma once

#include "game/play/game_session.hpp"

#include <cstdint>
#include <string>

namespace snow {

/// "m:ss" of a simulated time.
[[nodiscard]] std::string clock_text(double seconds);

/// The simulated time since the session's start and the mean snow depth of
/// the ground, e.g. "t 1:05  2.4 cm" (a contact sheet's label).
[[nodiscard]] std::string moment_label(const GameSession& session);

/// Headless: where the run is after frame `frame` (from 0) of `frames`,
/// with the last frame's render time.
[[nodiscard]] std::string progress_line(const GameSession& session, std::uint64_t frame,
                                        std::uint64_t frames, double render_ms);

/// After `frames` frames: the mass ledger, and the player's walk if there is one.
[[nodiscard]] std::string session_report(const GameSession& session, std::uint64_t frames);

} // namespace snow
