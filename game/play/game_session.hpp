/// @file game_session.hpp
/// @brief The session part of snow_game: owns the Simulation of the loaded
/// scene and carries out what the player asked for (game/play/player_actions.hpp):
/// simulation edits, the camera, the walking player, pause and the time
/// scale, and the view wishes the renderer follows (wind arrows, key list,
/// screenshot). It draws nothing and opens no window, so tests drive it
/// directly; the HUD and the recording only read it.
#pragma once

#include "game/play/camera_controller.hpp"
#include "game/play/game_options.hpp"
#include "game/play/player_actions.hpp"
#include "game/play/time_scale.hpp"
#include "game/play/walker.hpp"

#include <snow/render.hpp>

#include "systems/api/simulation_internals.hpp"

#include <snow/snow.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace snow {

class GameSession {
  public:
    /// Loads the scene `options` name (default the built-in village) with
    /// its quality preset, places the camera and the player, runs the
    /// warm-up ticks and saves the state R returns to. Nothing, after saying
    /// why on stderr, when the scene does not load or the options do not fit it.
    [[nodiscard]] static std::unique_ptr<GameSession> open(const GameOptions& options);

    /// One frame: the presses in order (none after one that quits), then the
    /// camera input, then the frame's ticks, the player walking in each.
    /// `wall_seconds`: a window's frame time, which the ticks follow within
    /// the frame budget; nothing for a headless frame, always 1/30 s of
    /// simulated time (× the time scale). `frame` counts from 0 (walk_once_at).
    void update(const PlayerActions& actions, std::uint64_t frame,
                std::optional<double> wall_seconds);
    /// Prints `message` and keeps it for the HUD.
    void say(const std::string& message);

    [[nodiscard]] const Simulation& sim() const { return *sim_; }
    [[nodiscard]] const SceneVisuals& visuals() const { return visuals_; }
    [[nodiscard]] const CameraController& camera() const { return *camera_; }
    /// The player in the world, if there is one.
    [[nodiscard]] const Walker* walker() const;
    /// The tick the session started (and resets) at: after the warm-up.
    [[nodiscard]] std::uint64_t start_tick() const { return start_tick_; }
    [[nodiscard]] std::size_t quality() const { return quality_; }
    [[nodiscard]] const TimeScale& time_scale() const { return time_scale_; }
    /// Ticks the last frame ran, and whether the frame budget held them back.
    [[nodiscard]] std::uint64_t ticks_last_frame() const { return ticks_last_frame_; }
    [[nodiscard]] bool ticks_capped() const { return ticks_capped_; }
    [[nodiscard]] bool paused() const { return paused_; }
    [[nodiscard]] bool help() const { return help_; }
    [[nodiscard]] bool show_wind_field() const { return show_wind_field_; }
    /// C or F12 in the last frame: take a screenshot of it.
    [[nodiscard]] bool screenshot_requested() const { return screenshot_requested_; }
    /// Esc, or a quality change whose scene did not load: the run ends.
    [[nodiscard]] bool quit() const { return quit_; }
    [[nodiscard]] const std::string& message() const { return message_; }

  private:
    explicit GameSession(const GameOptions& options);

    [[nodiscard]] bool load();
    void apply(Action a, const PlayerActions& actions, std::uint64_t frame);
    /// R: back to the start state. The bodies added since the start (the
    /// snowball B makes, a player made when the walk camera came later) are
    /// removed first: the start holds only the bodies it was saved with.
    void reset_to_start();
    void next_camera();
    /// Every emitter's snowfall becomes `snowfall(emitter)` (kg/m²/h, within
    /// the limits), its rate raised to carry it; returns the last emitter.
    Emitter set_snowfall(const std::function<float(const Emitter&)>& snowfall);
    void change_snowfall(float factor);
    void change_wind(Action a);
    /// The walk camera's player, made where the camera stands if there is none.
    void ensure_walker();
    /// walk_once_at: the player replaces the scene's first path body, standing
    /// at its path's start until that frame, then walking the path once.
    void take_over_walker();
    void look(const PlayerActions& actions, float seconds);
    void advance(std::uint64_t frame, std::optional<double> wall_seconds, const glm::vec2& walk);
    /// The player's walk: `move` relative to the view (zero outside the walk
    /// camera), at most unit length.
    [[nodiscard]] glm::vec2 walk_input(const glm::vec3& move) const;
    /// One tick as the player has it, run or stepped: the walker (and its
    /// snowball) moves, along its route once that has started, then the world.
    void tick_once(std::uint64_t frame, const glm::vec2& walk);

    GameOptions opt_;
    std::size_t quality_;
    std::unique_ptr<Simulation> sim_;
    SceneVisuals visuals_;
    FixedStep step_{1.0 / 60.0}; ///< window frames; load() sets it to the scene's dt
    std::unique_ptr<Snapshot> start_;
    std::vector<BodyId> added_bodies_; ///< reset_to_start's list, kept to reuse its memory
    std::uint64_t start_tick_ = 0;
    std::optional<Fog> fog_; ///< the scene's fog, kept while toggled off
    std::optional<CameraController> camera_;
    std::optional<Walker> walker_;
    /// walk_once_at: the scene walker's path, which the player walks once.
    std::optional<WalkRoute> route_;
    TimeScale time_scale_;
    std::uint64_t ticks_last_frame_ = 0;
    bool ticks_capped_ = false;
    bool paused_ = false;
    bool help_ = false;
    bool show_wind_field_ = RenderSettings{}.show_wind_field;
    bool screenshot_requested_ = false;
    bool quit_ = false;
    std::string message_;
};

} // namespace snow
