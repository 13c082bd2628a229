#include "game/game_app.hpp"

#include "game/builtin_scene.hpp"
#include "game/contact_sheet.hpp"
#include "game/frame_recorder.hpp"
#include "game/hud.hpp"
#include "game/quality.hpp"
#include "game/snow_readout.hpp"
#include "game/time_scale.hpp"
#include "game/walker.hpp"

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

/// "m:ss" of a simulated time.
std::string clock_text(double seconds) {
    const auto s = static_cast<long long>(std::lround(seconds));
    char text[32];
    std::snprintf(text, sizeof text, "%lld:%02lld", s / 60, s % 60);
    return text;
}

class Game {
  public:
    explicit Game(const GameOptions& o) : opt_(o), quality_(o.quality) {
        (void)time_scale_.set(o.time_scale); // snow_game's parser checked the value
    }

    int run();

  private:
    [[nodiscard]] bool load();
    void apply(Action a);
    void next_camera();
    /// The walk camera's player, made where the scene camera stands if there is none.
    void ensure_walker();
    /// walk_once_at: the player replaces the scene's first path body, standing
    /// at its path's start until that frame, then walking the path once.
    void take_over_walker();
    [[nodiscard]] glm::vec3 move_input() const;
    void read_input(float seconds);
    void advance(double seconds);
    /// The player's walk this frame: W A S D relative to the view (zero
    /// outside the walk camera), at most unit length.
    [[nodiscard]] glm::vec2 walk_input() const;
    /// One tick as the player has it, run or stepped: the walker (and its
    /// snowball) moves, along its route once that has started, then the world.
    void tick_once(const glm::vec2& walk);
    void frame_output();
    void report();
    void say(const std::string& message);
    [[nodiscard]] std::string moment_label() const;

    GameOptions opt_;
    std::size_t quality_;
    std::unique_ptr<Simulation> sim_;
    SceneVisuals visuals_;
    FixedStep step_{1.0 / 60.0}; ///< window mode; load() sets it to the scene's dt
    std::unique_ptr<Snapshot> start_;
    std::uint64_t start_tick_ = 0;
    std::optional<Fog> fog_;                ///< the scene's fog, kept while toggled off
    std::optional<FrameRecorder> recorder_; ///< headless: where frames are written
    std::optional<ContactSheet> sheet_;     ///< headless: chosen moments of the run
    std::unique_ptr<GlContext> context_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<CameraController> camera_;
    CameraMode mode_ = CameraMode::fly;
    std::optional<Walker> walker_;
    /// walk_once_at: the scene walker's path, which the player walks once.
    std::optional<WalkRoute> route_;
    TimeScale time_scale_;
    std::uint64_t ticks_last_frame_ = 0;
    bool ticks_capped_ = false;
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
    visuals_.camera.position = opt_.look_from.value_or(visuals_.camera.position);
    visuals_.camera.target = opt_.look_at.value_or(visuals_.camera.target);
    if (visuals_.camera.position == visuals_.camera.target) {
        std::fprintf(stderr, "snow_game: --look-from/--look-at: the camera's position and target "
                             "must differ\n");
        return false;
    }
    walker_.reset();
    step_ = FixedStep(sim_->config().dt);
    const World& w = sim_->world();
    if (const Fog* f = w.try_resource<Fog>()) {
        fog_ = *f;
    }
    const bool walkable = ground_surface(w) != nullptr;
    if (opt_.camera == CameraMode::walk && !walkable) {
        std::fprintf(stderr, "snow_game: --camera walk: the scene has no cover and no ground "
                             "surface to walk on\n");
        return false;
    }
    if (!camera_) {
        mode_ = opt_.camera.value_or(walkable ? CameraMode::walk : CameraMode::fly);
    }
    if (opt_.snowfall) {
        std::vector<Entity> emitters;
        w.each<Emitter>([&](Entity e, const Emitter&) { emitters.push_back(e); });
        for (const Entity e : emitters) {
            sim_->set_emitter_rate(e, *opt_.snowfall);
        }
    }
    route_.reset();
    if (opt_.walk_once_at) {
        take_over_walker();
    }
    if (mode_ == CameraMode::walk) {
        ensure_walker(); // before the snapshot: a reset puts the player back too
    }
    if (opt_.warmup_ticks > 0) {
        std::printf("snow_game: simulating %llu warm-up ticks ...\n",
                    static_cast<unsigned long long>(opt_.warmup_ticks));
        std::fflush(stdout);
        sim_->run(opt_.warmup_ticks);
    }
    start_ = sim_->save();
    start_tick_ = sim_->tick_count();
    return true;
}

void Game::ensure_walker() {
    if (!walker_ || !walker_->alive(*sim_)) {
        walker_.emplace(*sim_, camera_ ? camera_->camera().position : visuals_.camera.position);
    }
}

void Game::take_over_walker() {
    const World& w = sim_->world();
    Entity scene_walker;
    w.each<Body>([&](Entity e, const Body& b) {
        if (scene_walker.is_null() && b.motion.waypoints.size() > 1) {
            scene_walker = e;
        }
    });
    if (scene_walker.is_null() || ground_surface(w) == nullptr) {
        return;
    }
    const Body& b = sim_->body(scene_walker);
    std::vector<glm::vec2> points;
    for (const glm::vec3& p : b.motion.waypoints) {
        points.emplace_back(p.x, p.z);
    }
    if (b.motion.loop) {
        points.push_back(points.front());
    }
    route_.emplace(points, b.motion.speed);
    const glm::vec3 start = b.motion.waypoints.front();
    sim_->remove(scene_walker);
    walker_.emplace(*sim_, start);
}

void Game::say(const std::string& message) {
    message_ = message;
    std::printf("snow_game: %s\n", message.c_str());
    std::fflush(stdout);
}

void Game::next_camera() {
    const bool walkable = ground_surface(sim_->world()) != nullptr;
    do {
        mode_ = static_cast<CameraMode>((static_cast<int>(mode_) + 1) % 3);
    } while (mode_ == CameraMode::walk && !walkable);
    if (mode_ == CameraMode::walk) {
        ensure_walker();
        camera_->place(walker_->eye(*sim_));
    }
    camera_->set_mode(mode_);
    say(std::string(camera_mode_name(mode_)) + " camera");
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
            tick_once(walk_input());
            say("stepped to tick " + std::to_string(sim_->tick_count()));
        }
        break;
    case Action::reset:
        sim_->restore(*start_);
        if (walker_ && walker_->alive(*sim_)) {
            walker_->restart(*sim_);
        } else {
            walker_.reset(); // it was added after the snapshot
            if (mode_ == CameraMode::walk) {
                ensure_walker();
            }
        }
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
    case Action::toggle_wind: {
        bool& shown = renderer_->settings().show_wind_field;
        if (!w.has_resource<WindField>()) {
            say("this scene declares no wind field");
        } else {
            shown = !shown;
            say(shown ? "wind field arrows on (blue still, red fastest)" : "wind field arrows off");
        }
        break;
    }
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
    case Action::next_camera:
        next_camera();
        break;
    case Action::time_scale:
        time_scale_.cycle();
        say("time x" + std::to_string(time_scale_.factor()));
        break;
    case Action::push_snowball:
        if (mode_ == CameraMode::walk && walker_) {
            say(walker_->push_snowball(*sim_, camera_->facing()));
        } else {
            say("snowballs are pushed in the walk camera (O)");
        }
        break;
    case Action::toggle_help:
        help_ = !help_;
        break;
    case Action::quit:
        quit_ = true;
        break;
    }
}

glm::vec3 Game::move_input() const {
    const auto down = [&](MoveKey k) {
        const bool key = window_ && glfwGetKey(window_, glfw_key_of(k)) == GLFW_PRESS;
        return key || opt_.inject.held(k, frame_) ? 1.0f : 0.0f;
    };
    const auto window_key = [&](int key) {
        return window_ && glfwGetKey(window_, key) == GLFW_PRESS ? 1.0f : 0.0f;
    };
    return {down(MoveKey::right) - down(MoveKey::left),
            window_key(GLFW_KEY_SPACE) - window_key(GLFW_KEY_LEFT_SHIFT),
            down(MoveKey::forward) - down(MoveKey::back)};
}

void Game::read_input(float seconds) {
    CameraInput in;
    in.move = move_input();
    if (window_) {
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window_, &x, &y);
        const bool looking = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
                             (mode_ == CameraMode::orbit &&
                              glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS);
        if (looking && !(hud_ && hud_->wants_mouse())) {
            in.look = {static_cast<float>(x - last_mouse_x_),
                       static_cast<float>(y - last_mouse_y_)};
        }
        last_mouse_x_ = x;
        last_mouse_y_ = y;
        in.scroll = scroll_;
        scroll_ = 0.0f;
    }
    camera_->update(in, seconds);
}

glm::vec2 Game::walk_input() const {
    glm::vec2 walk(0.0f);
    if (mode_ == CameraMode::walk) {
        const glm::vec3 m = move_input();
        const glm::vec2 f = camera_->facing();
        walk = glm::vec2(-f.y, f.x) * m.x + f * m.z; // right, forward
        if (glm::length(walk) > 1.0f) {
            walk = glm::normalize(walk);
        }
    }
    return walk;
}

void Game::tick_once(const glm::vec2& walk) {
    if (walker_) {
        const bool on_route = route_ && frame_ >= *opt_.walk_once_at;
        // Also rolls the snowball on.
        walker_->before_tick(*sim_, on_route ? route_->direction(*sim_, *walker_) : walk);
    }
    sim_->tick();
}

void Game::advance(double seconds) {
    if (paused_) {
        ticks_last_frame_ = 0;
        return;
    }
    // Headless frames are 1/30 s of simulated time each (times the time
    // scale), whatever the wall clock; only a window's frames are budgeted.
    const double dt = sim_->config().dt;
    const std::uint64_t due =
        window_ ? step_.advance(seconds)
                : static_cast<std::uint64_t>(std::max(1l, std::lround(1.0 / (30.0 * dt))));
    const std::uint64_t ticks = time_scale_.ticks(due);
    ticks_capped_ = time_scale_.capped(due);
    const glm::vec2 walk = walk_input();
    if (route_ && walker_ && frame_ == *opt_.walk_once_at) {
        say("the walker sets off, once round its path");
    }
    const auto t0 = Clock::now();
    for (std::uint64_t i = 0; i < ticks; ++i) {
        tick_once(walk);
    }
    if (window_) {
        time_scale_.took(ticks, std::chrono::duration<double>(Clock::now() - t0).count());
    }
    ticks_last_frame_ = ticks;
}

std::string Game::moment_label() const {
    const double simulated = static_cast<double>(sim_->tick_count() - start_tick_) *
                             static_cast<double>(sim_->config().dt);
    std::string label = "t " + clock_text(simulated);
    if (const SnowSurface* g = ground_surface(sim_->world())) {
        char depth[32];
        std::snprintf(depth, sizeof depth, "  %.1f cm", 100.0 * mean_depth(*g));
        label += depth;
    }
    return label;
}

void Game::frame_output() {
    if (window_) {
        if (hud_) {
            HudInfo info;
            info.fps = fps_;
            info.paused = paused_;
            info.help = help_;
            info.fog_on = sim_->world().has_resource<Fog>();
            info.quality = quality_presets[quality_].name;
            info.camera_mode = camera_mode_name(mode_);
            info.last_message = message_;
            info.time_scale = time_scale_.factor();
            info.ticks_per_frame = ticks_last_frame_;
            info.ticks_capped = ticks_capped_;
            if (mode_ == CameraMode::walk && walker_) {
                info.depth_under = walker_->depth_under(*sim_);
                info.depth_ahead = walker_->depth_ahead(*sim_, camera_->facing());
            }
            hud_->draw(*sim_, renderer_->timings(), info);
        }
        context_->swap_buffers();
        return;
    }
    if (recorder_ || sheet_) {
        const Image image = renderer_->read_pixels();
        if (recorder_) {
            recorder_->write(image);
        }
        if (sheet_ && sheet_->wants(frame_)) {
            sheet_->add(image, moment_label());
        }
    }
    if (opt_.frames > 0 && (frame_ + 1) % 30 == 0) {
        const MassReport m = sim_->mass();
        std::printf(
            "snow_game: frame %llu/%llu, tick %llu (%s simulated, %s), %u flakes, "
            "settled %llu units, %.1f ms/frame render\n",
            static_cast<unsigned long long>(frame_ + 1),
            static_cast<unsigned long long>(opt_.frames),
            static_cast<unsigned long long>(sim_->tick_count()),
            clock_text(static_cast<double>(sim_->tick_count() - start_tick_) * sim_->config().dt)
                .c_str(),
            moment_label().c_str(), sim_->flakes().alive,
            static_cast<unsigned long long>(m.settled), renderer_->timings().frame_ms);
        std::fflush(stdout);
    }
}

void Game::report() {
    const MassReport m = sim_->mass();
    std::printf(
        "snow_game: done after %llu frames, tick %llu; mass units spawned %llu = airborne "
        "%llu + settled %llu + carried %llu + removed %llu\n",
        static_cast<unsigned long long>(frame_),
        static_cast<unsigned long long>(sim_->tick_count()),
        static_cast<unsigned long long>(m.spawned), static_cast<unsigned long long>(m.airborne),
        static_cast<unsigned long long>(m.settled), static_cast<unsigned long long>(m.carried),
        static_cast<unsigned long long>(m.removed));
    if (walker_ && walker_->alive(*sim_)) {
        const TrailReport t = walker_->trail(*sim_);
        std::printf("snow_game: player walked %.2f m from (%.2f, %.2f) to (%.2f, %.2f); snow on "
                    "its trail %.2f mm, 1 m beside it %.2f mm (%zu samples)\n",
                    static_cast<double>(t.walked), static_cast<double>(t.from.x),
                    static_cast<double>(t.from.y), static_cast<double>(t.to.x),
                    static_cast<double>(t.to.y), 1000.0 * t.on_trail, 1000.0 * t.beside, t.samples);
    }
    if (recorder_) {
        std::printf("snow_game: wrote %llu frames to %s\n",
                    static_cast<unsigned long long>(recorder_->frames()),
                    std::filesystem::absolute(recorder_->dir()).c_str());
        if (sheet_ && sheet_->size() > 0) {
            const std::filesystem::path sheet = std::filesystem::absolute(
                std::filesystem::path(recorder_->dir()) / "contact_sheet.png");
            write_png(sheet, sheet_->compose());
            std::printf("snow_game: contact sheet (%zu moments) %s\n", sheet_->size(),
                        sheet.c_str());
        }
        if (opt_.video) {
            if (const auto video = recorder_->encode_video()) {
                std::printf("snow_game: video %s\n", std::filesystem::absolute(*video).c_str());
            } else {
                std::printf("snow_game: no video (ffmpeg is not installed: scripts/deps.sh "
                            "installs it)\n");
            }
        }
    }
    std::fflush(stdout);
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
        if (opt_.contact_sheet > 0 && opt_.frames > 0) {
            // Tiles at most 320 px wide: four to a row make a README-sized sheet.
            sheet_.emplace(opt_.frames, opt_.contact_sheet, 4, (opt_.width + 319) / 320);
        }
    }
    RenderSettings settings;
    settings.lod_distance = quality_presets[quality_].lod_distance;
    settings.flake_lod = quality_presets[quality_].lod;
    if (opt_.bare_meshes) {
        settings.mesh_snow = 0.0f;
    }
    settings.min_snow_depth = opt_.min_snow_depth.value_or(settings.min_snow_depth);
    renderer_ = std::make_unique<Renderer>(*context_, settings);
    const CameraDef& def = visuals_.camera;
    camera_ = std::make_unique<CameraController>(ViewCamera::from_def(def), def.target);
    camera_->set_mode(mode_);
    std::printf("snow_game: %s, %s (%s), %s camera\n", window_ ? "window" : "headless",
                renderer_->gl_description().c_str(), std::string(context_->name()).c_str(),
                std::string(camera_mode_name(mode_)).c_str());

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
        for (const InjectedKey& k : opt_.inject.presses) {
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
        read_input(window_ ? static_cast<float>(seconds) : 1.0f / 30.0f);
        advance(seconds);
        if (mode_ == CameraMode::walk && walker_) {
            camera_->place(walker_->eye(*sim_));
        }
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
    report();
    return sim_->mass().balanced() ? 0 : 1;
}

} // namespace

void apply_timelapse(GameOptions& o) {
    o.headless = true;
    o.frames = 120;
    o.width = 640;
    o.height = 360;
    o.quality = 0;         // low: 30 ticks a second, coarse cells
    o.time_scale = 64;     // 64 × 1/30 s: 2.1 simulated seconds a frame, 4.3 minutes in all
    o.snowfall = 40000.0f; // a storm: about 13 times the village's snowfall
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
