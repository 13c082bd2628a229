/// @file game_options.hpp
/// @brief What a snow_game run is asked to do (its command line, parsed
/// strictly): the scene and how the session starts, and where and how the
/// frames go.
#pragma once

#include "game/app/cli_args.hpp"
#include "game/play/camera_controller.hpp"
#include "game/play/game_input.hpp"

#include <snow/scene.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace snow {

struct GameOptions {
    std::optional<std::string> scene; ///< glTF file; default the built-in village
    bool headless = false;            ///< force headless rendering
    std::uint64_t frames = 0;         ///< stop after this many frames (0: no limit)
    std::string out_dir;              ///< headless: where PNG frames go
    double seconds = 0.0;             ///< stop after this much wall time (0: no limit)
    int width = 1280, height = 720;
    std::uint64_t warmup_ticks = 0; ///< ticks simulated before the first frame
    std::size_t quality = 1;        ///< index into quality_presets
    KeyScript inject;               ///< scripted key presses and holds
    bool video = false;             ///< headless: encode frames with ffmpeg if present
    /// The camera to start with; default walk where the scene has snow ground
    /// (a cover or a surface on no solid), else fly.
    std::optional<CameraMode> camera;
    std::uint32_t time_scale = 1; ///< simulated time per frame: 1, 4, 16 or 64 ×
    std::optional<float>
        snowfall; ///< every emitter's snowfall (kg/m²/h); its rate rises to carry it
    std::uint32_t contact_sheet = 0; ///< headless: moments in <out>/contact_sheet.png
    /// The player takes the place of the scene's walker (its first body with
    /// a path): it stands at the path's start until this frame, then walks
    /// the path once and stops (a trail cut once, in the player's tread).
    std::optional<std::uint64_t> walk_once_at;
    bool bare_meshes = false;   ///< meshes keep their colour: only simulated snow is white
    bool aov = false;           ///< headless: each frame's snow and sun-shadow masks beside it
    bool detail_normals = true; ///< RenderSettings::detail_normals (off: the Cycles comparison)
    bool sparkle = true;        ///< RenderSettings::sparkle
    std::optional<float> min_snow_depth; ///< renderer: thinner snow shows the bare top (m)
    std::optional<glm::vec3> look_from;  ///< replaces the scene camera's position
    std::optional<glm::vec3> look_at;    ///< replaces the scene camera's target
    SceneOverrides overrides;
    bool help = false; ///< --help: print game_usage and exit 0
};

/// snow_game's usage text.
extern const cli::Usage game_usage;

/// Reads snow_game's command line; throws cli::UsageError naming a bad flag or value.
[[nodiscard]] GameOptions parse_game_options(int argc, char** argv);

/// The settings --timelapse stands for (flags after it still override them):
/// the village's storm, headless, several simulated minutes in 120 frames.
void apply_timelapse(GameOptions& o);

} // namespace snow
