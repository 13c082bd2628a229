#include "game/play/game_options.hpp"

#include "game/play/quality.hpp"
#include "game/play/time_scale.hpp"
#include "systems/core/limits.hpp"

#include <stdexcept>
#include <string>

namespace snow {

namespace {

constexpr const char* game_usage_head = R"(usage: snow_game [options]
  --scene FILE        glTF scene (default: the built-in village scene)
  --headless          render without a window (OSMesa) to PNG frames
  --frames N          stop after N frames (headless default 120)
  --out DIR           headless: folder for the PNG frames (default out/frames)
  --seconds S         stop after S seconds of wall time
  --size WxH          window / image size (default 1280x720)
  --quality NAME      low | medium | high (default medium)
  --warmup N          simulate N ticks before the first frame
  --camera MODE       walk | fly | orbit (default walk where the scene has a cover
                      or a ground surface, else fly)
  --time-scale N      simulated time per frame: 1, 4, 16 or 64 times (key T)
  --snowfall KG       every emitter's snowfall, kg/m²/h (0 < KG <= 10000): 3 is
                      heavy snow, 15 a storm's heaviest hour; more fast-forwards
  --walk-once-at F    the player takes the scene walker's place: it waits at its
                      path's start until frame F, then walks the path once
  --bare-meshes       meshes keep their colour: only the simulated snow is white
  --no-detail-normals the snow without its world-anchored detail normals
  --no-sparkle        the snow without glints of the sun
  --aov               headless: beside each frame_N.png also frame_N_snow.png (white
                      where snow covers the pixel) and frame_N_shadow.png (white
                      where the sun's shadow falls; black without a sun)
  --min-snow-depth M  snow thinner than M metres fades to the bare top (default 0.002)
  --look-from X,Y,Z   the camera's start position (default: the scene's camera)
  --look-at X,Y,Z     the point it looks at (default: the scene's camera)
  --contact-sheet N   headless: N moments (2..16) of the run in DIR/contact_sheet.png
  --timelapse         the village storm as a headless time-lapse: --headless
                      --frames 120 --size 640x360 --quality low --time-scale 64
                      --snowfall 200 --max-flakes 400000 --wind 0,0,-2.5
                      --camera fly --look-from 0,4.5,8.5 --look-at 1.8,1,-1
                      --walk-once-at 55 --contact-sheet 8 --video --bare-meshes
                      --min-snow-depth 0.008 --out out/timelapse (flags after it
                      override these)
)";
constexpr const char* game_usage_tail =
    R"(  --inject LIST       scripted keys: FRAME:KEY presses and FRAME:MOVE:FRAMES holds
                      of W A S D, e.g. "0:W:60,10:B,80:ESC"
  --video             headless: also encode DIR/snow.mp4 if ffmpeg is installed
  --help              this text
In the window press H for the key list.
)";

/// Reads one of snow_game's own flags into `o`; false for a flag it does not take.
bool read_flag(std::string_view f, cli::ArgReader& args, GameOptions& o) {
    using namespace cli;
    if (f == "--headless") {
        o.headless = true;
    } else if (f == "--frames") {
        o.frames = parse_uint(f, args.value(), 1, 10'000'000);
    } else if (f == "--out") {
        o.out_dir = std::string(args.value());
    } else if (f == "--seconds") {
        o.seconds = parse_positive(f, args.value(), 1.0e7);
    } else if (f == "--size") {
        const std::string_view v = args.value();
        const std::size_t x = v.find('x');
        if (x == std::string_view::npos) {
            throw UsageError{"--size: expected WxH, e.g. 1280x720, got '" + std::string(v) + "'"};
        }
        o.width = static_cast<int>(parse_uint(f, v.substr(0, x), 16, 8192));
        o.height = static_cast<int>(parse_uint(f, v.substr(x + 1), 16, 8192));
    } else if (f == "--quality") {
        const std::string_view q = args.value();
        const auto i = find_quality(q);
        if (!i) {
            throw UsageError{"--quality: expected low, medium or high, got '" + std::string(q) +
                             "'"};
        }
        o.quality = *i;
    } else if (f == "--warmup") {
        o.warmup_ticks = parse_uint(f, args.value(), 0, 100'000'000);
    } else if (f == "--inject") {
        try {
            o.inject = parse_key_script(args.value());
        } catch (const std::invalid_argument& e) {
            throw UsageError{e.what()};
        }
    } else if (f == "--video") {
        o.video = true;
    } else if (f == "--camera") {
        const std::string_view m = args.value();
        o.camera = find_camera_mode(m);
        if (!o.camera) {
            throw UsageError{"--camera: expected walk, fly or orbit, got '" + std::string(m) + "'"};
        }
    } else if (f == "--time-scale") {
        const std::string_view v = args.value();
        const auto n = static_cast<std::uint32_t>(parse_uint(f, v, 1, 64));
        if (!TimeScale().set(n)) {
            throw UsageError{"--time-scale: expected 1, 4, 16 or 64, got " + std::string(v)};
        }
        o.time_scale = n;
    } else if (f == "--snowfall") {
        o.snowfall = static_cast<float>(parse_positive(f, args.value(), max_snowfall_kg_m2_h));
    } else if (f == "--walk-once-at") {
        o.walk_once_at = parse_uint(f, args.value(), 0, 10'000'000);
    } else if (f == "--aov") {
        o.aov = true;
    } else if (f == "--bare-meshes") {
        o.bare_meshes = true;
    } else if (f == "--no-detail-normals") {
        o.detail_normals = false;
    } else if (f == "--no-sparkle") {
        o.sparkle = false;
    } else if (f == "--min-snow-depth") {
        o.min_snow_depth = static_cast<float>(parse_positive(f, args.value(), 10.0));
    } else if (f == "--look-from") {
        o.look_from = parse_vec3(f, args.value(), 1.0e4);
    } else if (f == "--look-at") {
        o.look_at = parse_vec3(f, args.value(), 1.0e4);
    } else if (f == "--contact-sheet") {
        o.contact_sheet = static_cast<std::uint32_t>(parse_uint(f, args.value(), 2, 16));
    } else if (f == "--timelapse") {
        apply_timelapse(o);
    } else {
        return false;
    }
    return true;
}

} // namespace

const cli::Usage game_usage{game_usage_head, game_usage_tail};

GameOptions parse_game_options(int argc, char** argv) {
    GameOptions o;
    cli::read_command_line(
        argc, argv, {o.scene, o.overrides, o.help},
        [&](std::string_view f, cli::ArgReader& args) { return read_flag(f, args, o); });
    if (o.aov && !o.headless && !o.help) {
        throw cli::UsageError{"--aov: needs --headless (the masks go beside the PNG frames)"};
    }
    return o;
}

void apply_timelapse(GameOptions& o) {
    o.headless = true;
    o.frames = 120;
    o.width = 640;
    o.height = 360;
    o.quality = 0;     // low: 30 ticks a second, coarse cells
    o.time_scale = 64; // 64 × 1/30 s: 2.1 simulated seconds a frame, 4.3 minutes in all
    // Weather fast-forwarded: 200 kg/m²/h, 13 times the village's storm, so
    // that 4 minutes lay what a long storm does.
    o.snowfall = 200.0f;
    o.overrides.max_flakes = 400000;
    // The storm blows from the south, towards the buildings' camera-facing
    // sides: drifts grow at the garage's windward face, in view; the house's
    // east roof slides off its eave onto the porch, which no building shelters.
    o.overrides.wind = glm::vec3{0.0f, 0.0f, -2.5f};
    o.camera = CameraMode::fly;
    o.look_from = glm::vec3{0.0f, 4.5f, 8.5f};
    o.look_at = glm::vec3{1.8f, 1.0f, -1.0f};
    o.walk_once_at = 55; // the walker cuts its trail through 3 cm of snow
    o.contact_sheet = 8;
    o.video = true;
    o.bare_meshes = true; // white is only the simulated snow ...
    // ... from 8 mm on: the porch's and roofs' thinner snow shows, the trail
    // reads dark until it refills.
    o.min_snow_depth = 0.008f;
    o.out_dir = "out/timelapse";
}

} // namespace snow
