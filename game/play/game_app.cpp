#include "game/play/game_app.hpp"
#include "systems/api/simulation_internals.hpp"

#include "ecs/staged_files.hpp"
#include "game/play/frame_recorder.hpp"
#include "game/play/game_session.hpp"
#include "game/play/headless_recording.hpp"
#include "game/play/hud.hpp"
#include "game/play/input_reader.hpp"
#include "game/play/quality.hpp"
#include "game/play/session_report.hpp"
#include "render/context/glfw_context.hpp"

#include <snow/render.hpp>

#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>

namespace snow {

namespace {

using Clock = std::chrono::steady_clock;

/// The renderer's settings the player changes through the session.
void follow_session(const GameSession& session, RenderSettings& settings) {
    settings.lod_distance = quality_presets[session.quality()].lod_distance;
    settings.flake_lod = quality_presets[session.quality()].lod;
    settings.show_wind_field = session.show_wind_field();
}

/// Frames per second over half-second windows (a single frame's time is noisy).
class FpsMeter {
  public:
    void frame(double seconds) {
        ++frames_;
        window_ += seconds;
        if (window_ >= 0.5) {
            fps_ = static_cast<float>(frames_ / window_);
            frames_ = 0;
            window_ = 0.0;
        }
    }
    [[nodiscard]] float fps() const { return fps_; }

  private:
    float fps_ = 0.0f;
    int frames_ = 0;
    double window_ = 0.0;
};

/// The frame loop: input -> actions -> session, then the picture of the
/// session drawn, with the HUD in a window or recorded headless.
int play(GameOptions opt) {
    const std::unique_ptr<GameSession> session = GameSession::open(opt);
    if (!session) {
        return 2;
    }
    ContextRequest req;
    req.backend = opt.headless ? ContextBackend::headless : ContextBackend::automatic;
    req.width = opt.width;
    req.height = opt.height;
    req.title = "snow";
    const std::unique_ptr<GlContext> context = make_context(req);
    GLFWwindow* window = nullptr;
    if (context->name() == "glfw") {
        window = static_cast<GlfwContext&>(*context).window();
    } else if (opt.out_dir.empty()) {
        opt.out_dir = "out/frames";
    }
    InputReader input(window, opt.inject);
    // ImGui starts before the renderer and shuts down while it still stands.
    std::unique_ptr<Renderer> renderer;
    std::unique_ptr<Hud> hud;
    std::optional<HeadlessRecording> recording;
    if (window) {
        hud = std::make_unique<Hud>(window); // after the input: it chains its callbacks
    } else {
        if (opt.frames == 0 && opt.seconds <= 0.0) {
            opt.frames = 120; // headless without a limit would never end
        }
        recording.emplace(opt);
    }
    RenderSettings settings;
    follow_session(*session, settings);
    if (opt.bare_meshes) {
        settings.mesh_snow = 0.0f;
        settings.body_snow = 0.0f;
    }
    settings.min_snow_depth = opt.min_snow_depth.value_or(settings.min_snow_depth);
    settings.detail_normals = opt.detail_normals;
    settings.sparkle = opt.sparkle;
    renderer = std::make_unique<Renderer>(*context, settings);
    std::printf("snow_game: %s, %s (%s), %s camera\n", window ? "window" : "headless",
                renderer->gl_description().c_str(), std::string(context->name()).c_str(),
                std::string(camera_mode_name(session->camera().mode())).c_str());

    FpsMeter fps;
    std::uint64_t frame = 0;
    std::uint64_t screenshots = 0;
    const auto t0 = Clock::now();
    auto last = t0;
    while (true) {
        const auto now = Clock::now();
        const double seconds = std::chrono::duration<double>(now - last).count();
        last = now;
        fps.frame(seconds);
        context->poll_events();
        if (context->should_close()) {
            break;
        }
        const PlayerActions actions = input.read(frame, hud && hud->wants_mouse());
        session->update(actions, frame, window ? std::optional<double>(seconds) : std::nullopt);
        if (session->quit()) {
            break;
        }
        follow_session(*session, renderer->settings());
        renderer->render(session->sim(), session->visuals(), session->camera().camera());
        if (session->screenshot_requested()) {
            session->say("screenshot " + save_screenshot(renderer->read_pixels(), screenshots++));
        }
        if (window) {
            hud->draw(*session, renderer->timings(), fps.fps());
            context->swap_buffers();
        } else {
            recording->add(renderer->read_pixels(), *session, frame);
            if (opt.aov) {
                // The same moment again as each mask (the renderer only reads the world).
                for (const auto& [output, suffix] : aov_masks) {
                    renderer->settings().output = output;
                    renderer->render(session->sim(), session->visuals(),
                                     session->camera().camera());
                    recording->add_mask(renderer->read_pixels(), suffix);
                }
                renderer->settings().output = RenderOutput::color;
            }
            if (opt.frames > 0 && (frame + 1) % 30 == 0) {
                std::fputs(progress_line(*session, frame, opt.frames, renderer->timings().frame_ms)
                               .c_str(),
                           stdout);
                std::fflush(stdout);
            }
        }
        ++frame;
        if ((opt.frames > 0 && frame >= opt.frames) ||
            (opt.seconds > 0.0 &&
             std::chrono::duration<double>(Clock::now() - t0).count() >= opt.seconds)) {
            break;
        }
    }
    std::fputs(session_report(*session, frame).c_str(), stdout);
    if (recording) {
        std::fputs(recording->finish().c_str(), stdout);
    }
    std::fflush(stdout);
    return session->sim().mass().balanced() ? 0 : 1;
}

} // namespace

int run_game(const GameOptions& options) {
    try {
        return play(options);
    } catch (const FileWriteError& e) { // a frame, sheet or screenshot: read-only folder, full disk
        std::fprintf(stderr, "snow_game: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "snow_game: %s\n", e.what());
        return 1;
    }
}

} // namespace snow
