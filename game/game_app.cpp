#include "game/game_app.hpp"

#include "game/builtin_scene.hpp"
#include "game/camera_controller.hpp"
#include "game/frame_recorder.hpp"
#include "game/hud.hpp"
#include "game/quality.hpp"

#include <snow/render.hpp>

#include <GLFW/glfw3.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <utility>
#include <vector>

namespace snow {

namespace {

using Clock = std::chrono::steady_clock;

/// Rotates a horizontal vector about +y by `radians`.
glm::vec3 rotate_y(const glm::vec3& v, float radians) {
    const float c = std::cos(radians), s = std::sin(radians);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

class Game {
  public:
    explicit Game(const GameOptions& o) : opt_(o), quality_(o.quality) {}

    int run();

  private:
    [[nodiscard]] bool load();
    void apply(Action a);
    void read_window_input(float seconds);
    void advance(double seconds);
    void frame_output();
    void say(const std::string& message);

    GameOptions opt_;
    std::size_t quality_;
    std::unique_ptr<Simulation> sim_;
    SceneVisuals visuals_;
    FixedStep step_{1.0 / 60.0}; ///< window mode; load() sets it to the scene's dt
    std::unique_ptr<Snapshot> start_;
    std::optional<Fog> fog_;                ///< the scene's fog, kept while toggled off
    std::optional<FrameRecorder> recorder_; ///< headless: where frames are written
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<CameraController> camera_;
    std::unique_ptr<Hud> hud_;
    GLFWwindow* window_ = nullptr;
    std::deque<Action> pending_;
    bool paused_ = false;
    bool screenshot_requested_ = false;
    bool help_ = false;
    bool quit_ = false;
    std::uint64_t frame_ = 0;
    std::uint64_t screenshots_ = 0;
    double last_mouse_x_ = 0.0, last_mouse_y_ = 0.0;
    float scroll_ = 0.0f;
    float fps_ = 0.0f;
    int fps_frames_ = 0;
    double fps_window_ = 0.0;
    std::string message_;
};

bool Game::load() {
    SceneOverrides ov = opt_.overrides;
    apply_quality(quality_presets[quality_], ov);
    SceneLoadResult r = opt_.scene
                            ? load_scene_file(*opt_.scene, ov)
                            : load_scene_memory(builtin_village_gltf(), "builtin:village", ov);
    if (!r.sim) {
        std::fprintf(stderr, "snow_game: %s\n", r.error.c_str());
        return false;
    }
    sim_ = std::move(r.sim);
    visuals_ = std::move(r.visuals);
    step_ = FixedStep(sim_->config().dt);
    if (const Fog* f = sim_->world().try_resource<Fog>()) {
        fog_ = *f;
    }
    if (opt_.warmup_ticks > 0) {
        std::printf("snow_game: simulating %llu warm-up ticks ...\n",
                    static_cast<unsigned long long>(opt_.warmup_ticks));
        std::fflush(stdout);
        sim_->run(opt_.warmup_ticks);
    }
    start_ = sim_->save();
    return true;
}

void Game::say(const std::string& message) {
    message_ = message;
    std::printf("snow_game: %s\n", message.c_str());
    std::fflush(stdout);
}

void Game::apply(Action a) {
    const World& w = sim_->world();
    switch (a) {
    case Action::pause:
        paused_ = !paused_;
        say(std::string(paused_ ? "paused" : "resumed") + " at tick " +
            std::to_string(sim_->tick_count()));
        break;
    case Action::step:
        if (paused_) {
            sim_->tick();
            say("stepped to tick " + std::to_string(sim_->tick_count()));
        }
        break;
    case Action::reset:
        sim_->restore(*start_);
        say("reset to tick " + std::to_string(sim_->tick_count()));
        break;
    case Action::rate_up:
    case Action::rate_down: {
        const float factor = a == Action::rate_up ? 1.5f : 1.0f / 1.5f;
        std::vector<std::pair<Entity, float>> rates;
        w.each<Emitter>([&](Entity e, const Emitter& em) {
            rates.emplace_back(e, std::clamp(em.rate * factor, 10.0f, 1.0e6f));
        });
        float rate = 0.0f;
        for (const auto& [emitter, new_rate] : rates) {
            sim_->set_emitter_rate(emitter, new_rate);
            rate = new_rate;
        }
        say("snowfall " + std::to_string(static_cast<int>(rate)) + " flakes/s");
        break;
    }
    case Action::wind_left:
    case Action::wind_right:
    case Action::wind_up:
    case Action::wind_down: {
        Wind wind = w.has_resource<Wind>() ? w.resource<Wind>() : Wind{};
        const glm::vec3 old_base = wind.base;
        if (a == Action::wind_left || a == Action::wind_right) {
            wind.base = rotate_y(wind.base, a == Action::wind_left ? 0.2618f : -0.2618f);
        } else {
            wind.base *= a == Action::wind_up ? 1.25f : 0.8f;
        }
        wind.current += wind.base - old_base;
        sim_->set_wind(wind);
        say("wind " + std::to_string(glm::length(wind.base)).substr(0, 4) + " m/s");
        break;
    }
    case Action::toggle_fog:
        if (!fog_) {
            say("this scene declares no fog");
        } else if (w.has_resource<Fog>()) {
            sim_->clear_fog();
            say("fog off");
        } else {
            sim_->set_fog(*fog_);
            say("fog on");
        }
        break;
    case Action::quality_next:
        quality_ = (quality_ + 1) % quality_presets.size();
        if (load()) {
            renderer_->settings().lod_distance = quality_presets[quality_].lod_distance;
            renderer_->settings().flake_lod = quality_presets[quality_].lod;
            say(std::string("quality ") + std::string(quality_presets[quality_].name));
        } else {
            quit_ = true;
        }
        break;
    case Action::screenshot:
        screenshot_requested_ = true; // taken right after this frame's scene is drawn
        break;
    case Action::toggle_orbit:
        camera_->set_orbit(!camera_->orbit());
        say(camera_->orbit() ? "orbit camera" : "fly camera");
        break;
    case Action::toggle_help:
        help_ = !help_;
        break;
    case Action::quit:
        quit_ = true;
        break;
    }
}

void Game::read_window_input(float seconds) {
    CameraInput in;
    const auto down = [&](int key) { return glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f; };
    in.move = {down(GLFW_KEY_D) - down(GLFW_KEY_A),
               down(GLFW_KEY_SPACE) - down(GLFW_KEY_LEFT_SHIFT),
               down(GLFW_KEY_W) - down(GLFW_KEY_S)};
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_, &x, &y);
    const bool looking =
        glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
        (camera_->orbit() && glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS);
    if (looking && !(hud_ && hud_->wants_mouse())) {
        in.look = {static_cast<float>(x - last_mouse_x_), static_cast<float>(y - last_mouse_y_)};
    }
    last_mouse_x_ = x;
    last_mouse_y_ = y;
    in.scroll = scroll_;
    scroll_ = 0.0f;
    camera_->update(in, seconds);
}

void Game::advance(double seconds) {
    if (paused_) {
        return;
    }
    if (!window_) {
        // Headless frames are 1/30 s of simulated time each, whatever the wall clock.
        const double dt = sim_->config().dt;
        sim_->run(static_cast<std::uint64_t>(std::max(1l, std::lround(1.0 / (30.0 * dt)))));
        return;
    }
    sim_->run(step_.advance(seconds));
}

void Game::frame_output() {
    if (window_) {
        if (hud_) {
            hud_->draw(*sim_, renderer_->timings(),
                       HudInfo{fps_, paused_, help_, sim_->world().has_resource<Fog>(),
                               std::string(quality_presets[quality_].name),
                               camera_->orbit() ? "orbit" : "fly", message_});
        }
        context_->swap_buffers();
        return;
    }
    if (recorder_) {
        recorder_->write(renderer_->read_pixels());
    }
    if (opt_.frames > 0 && (frame_ + 1) % 30 == 0) {
        const MassReport m = sim_->mass();
        std::printf("snow_game: frame %llu/%llu, tick %llu, %u flakes, settled %llu units, %.1f "
                    "ms/frame render\n",
                    static_cast<unsigned long long>(frame_ + 1),
                    static_cast<unsigned long long>(opt_.frames),
                    static_cast<unsigned long long>(sim_->tick_count()), sim_->flakes().alive,
                    static_cast<unsigned long long>(m.settled), renderer_->timings().frame_ms);
        std::fflush(stdout);
    }
}

int Game::run() {
    if (!load()) {
        return 2;
    }
    ContextRequest req;
    req.backend = opt_.headless ? ContextBackend::headless : ContextBackend::automatic;
    req.width = opt_.width;
    req.height = opt_.height;
    req.title = "snow";
    context_ = make_context(req);
    if (context_->name() == "glfw") {
        window_ = static_cast<GlfwContext&>(*context_).window();
        glfwSetWindowUserPointer(window_, this);
        glfwSetKeyCallback(window_, [](GLFWwindow* win, int key, int, int action, int) {
            if (action == GLFW_PRESS) {
                if (const auto a = action_for_key(key)) {
                    static_cast<Game*>(glfwGetWindowUserPointer(win))->pending_.push_back(*a);
                }
            }
        });
        glfwSetScrollCallback(window_, [](GLFWwindow* win, double, double dy) {
            static_cast<Game*>(glfwGetWindowUserPointer(win))->scroll_ += static_cast<float>(dy);
        });
        hud_ = std::make_unique<Hud>(window_);
    } else if (opt_.out_dir.empty()) {
        opt_.out_dir = "out/frames";
    }
    if (!window_ && opt_.frames == 0 && opt_.seconds <= 0.0) {
        opt_.frames = 120; // headless without a limit would never end
    }
    if (!opt_.out_dir.empty() && !window_) {
        recorder_.emplace(opt_.out_dir);
    }
    RenderSettings settings;
    settings.lod_distance = quality_presets[quality_].lod_distance;
    settings.flake_lod = quality_presets[quality_].lod;
    renderer_ = std::make_unique<Renderer>(*context_, settings);
    const CameraDef& def = visuals_.camera;
    camera_ = std::make_unique<CameraController>(ViewCamera::from_def(def), def.target);
    std::printf("snow_game: %s, %s (%s)\n", window_ ? "window" : "headless",
                renderer_->gl_description().c_str(), std::string(context_->name()).c_str());

    const auto t0 = Clock::now();
    auto last = t0;
    while (!quit_) {
        const auto now = Clock::now();
        const double seconds = std::chrono::duration<double>(now - last).count();
        last = now;
        // Frames per second over half-second windows (a single frame's time is noisy).
        ++fps_frames_;
        fps_window_ += seconds;
        if (fps_window_ >= 0.5) {
            fps_ = static_cast<float>(fps_frames_ / fps_window_);
            fps_frames_ = 0;
            fps_window_ = 0.0;
        }
        context_->poll_events();
        if (context_->should_close()) {
            break;
        }
        for (const InjectedKey& k : opt_.inject) {
            if (k.frame == frame_) {
                pending_.push_back(k.action);
            }
        }
        while (!pending_.empty() && !quit_) {
            const Action a = pending_.front();
            pending_.pop_front();
            apply(a);
        }
        if (quit_) {
            break;
        }
        if (window_) {
            read_window_input(static_cast<float>(seconds));
        }
        advance(seconds);
        renderer_->render(sim_->world(), visuals_, camera_->camera());
        if (screenshot_requested_) {
            screenshot_requested_ = false;
            say("screenshot " + save_screenshot(renderer_->read_pixels(), screenshots_++));
        }
        frame_output();
        ++frame_;
        if ((opt_.frames > 0 && frame_ >= opt_.frames) ||
            (opt_.seconds > 0.0 &&
             std::chrono::duration<double>(Clock::now() - t0).count() >= opt_.seconds)) {
            break;
        }
    }
    const MassReport m = sim_->mass();
    std::printf(
        "snow_game: done after %llu frames, tick %llu; mass units spawned %llu = airborne "
        "%llu + settled %llu + removed %llu\n",
        static_cast<unsigned long long>(frame_),
        static_cast<unsigned long long>(sim_->tick_count()),
        static_cast<unsigned long long>(m.spawned), static_cast<unsigned long long>(m.airborne),
        static_cast<unsigned long long>(m.settled), static_cast<unsigned long long>(m.removed));
    if (recorder_) {
        std::printf("snow_game: wrote %llu frames to %s\n",
                    static_cast<unsigned long long>(recorder_->frames()),
                    std::filesystem::absolute(recorder_->dir()).c_str());
        if (opt_.video) {
            if (const auto video = recorder_->encode_video()) {
                std::printf("snow_game: video %s\n", video->c_str());
            }
        }
    }
    return m.balanced() ? 0 : 1;
}

} // namespace

int run_game(const GameOptions& options) {
    try {
        Game game(options);
        return game.run();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "snow_game: %s\n", e.what());
        return 1;
    }
}

} // namespace snow
