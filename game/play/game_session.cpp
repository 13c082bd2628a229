#include "game/play/game_session.hpp"
#include "systems/api/simulation_internals.hpp"

#include "game/app/builtin_scene.hpp"
#include "game/play/quality.hpp"
#include "game/play/snow_readout.hpp"
#include "systems/core/limits.hpp"
#include "systems/flakes/snowfall.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

namespace snow {

namespace {

/// Rotates a horizontal vector about +y by `radians`.
glm::vec3 rotate_y(const glm::vec3& v, float radians) {
    const float c = std::cos(radians), s = std::sin(radians);
    return {c * v.x + s * v.z, v.y, -s * v.x + c * v.z};
}

} // namespace

GameSession::GameSession(const GameOptions& options) : opt_(options), quality_(options.quality) {
    (void)time_scale_.set(options.time_scale); // snow_game's parser checked the value
}

std::unique_ptr<GameSession> GameSession::open(const GameOptions& options) {
    std::unique_ptr<GameSession> s(new GameSession(options));
    if (!s->load()) {
        return nullptr;
    }
    return s;
}

bool GameSession::load() {
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
    const World& w = world_of(*sim_);
    fog_ = visuals_.fog;
    const bool walkable = ground_surface(w) != nullptr;
    if (opt_.camera == CameraMode::walk && !walkable) {
        std::fprintf(stderr, "snow_game: --camera walk: the scene has no cover and no ground "
                             "surface to walk on\n");
        return false;
    }
    if (!camera_) { // the first load; a reload keeps the camera where the player put it
        const CameraDef& def = visuals_.camera;
        camera_.emplace(ViewCamera::from_def(def), def.target);
        camera_->set_mode(opt_.camera.value_or(walkable ? CameraMode::walk : CameraMode::fly));
    }
    if (opt_.snowfall) {
        set_snowfall([&](const Emitter&) { return *opt_.snowfall; });
    }
    route_.reset();
    if (opt_.walk_once_at) {
        take_over_walker();
    }
    if (camera_->mode() == CameraMode::walk) {
        ensure_walker(); // before the snapshot: a reset puts the player back too
    }
    if (opt_.warmup_ticks > 0) {
        std::printf("snow_game: simulating %llu warm-up ticks ...\n",
                    static_cast<unsigned long long>(opt_.warmup_ticks));
        std::fflush(stdout);
        sim_->run(opt_.warmup_ticks);
    }
    start_ = save_snapshot(*sim_);
    start_tick_ = sim_->tick_count();
    return true;
}

const Walker* GameSession::walker() const {
    return walker_ ? &*walker_ : nullptr;
}

void GameSession::ensure_walker() {
    if (!walker_ || !walker_->alive(*sim_)) {
        walker_.emplace(*sim_, camera_->camera().position);
    }
}

void GameSession::take_over_walker() {
    const World& w = world_of(*sim_);
    BodyId scene_walker;
    w.each<Body>([&](Entity e, const Body& b) {
        if (scene_walker.is_null() && b.motion.waypoints.size() > 1) {
            scene_walker = id_of<BodyId>(e);
        }
    });
    if (scene_walker.is_null() || ground_surface(w) == nullptr) {
        return;
    }
    const Body& b = body_of(*sim_, scene_walker);
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

void GameSession::say(const std::string& message) {
    message_ = message;
    std::printf("snow_game: %s\n", message.c_str());
    std::fflush(stdout);
}

void GameSession::update(const PlayerActions& actions, std::uint64_t frame,
                         std::optional<double> wall_seconds) {
    screenshot_requested_ = false;
    for (const Action a : actions.presses) {
        if (quit_) {
            return;
        }
        apply(a, actions, frame);
    }
    if (quit_) {
        return;
    }
    look(actions, wall_seconds ? static_cast<float>(*wall_seconds) : 1.0f / 30.0f);
    advance(frame, wall_seconds, walk_input(actions.move));
    if (camera_->mode() == CameraMode::walk && walker_) {
        camera_->place(walker_->eye(*sim_));
    }
}

void GameSession::next_camera() {
    const bool walkable = ground_surface(world_of(*sim_)) != nullptr;
    CameraMode mode = camera_->mode();
    do {
        mode = static_cast<CameraMode>((static_cast<int>(mode) + 1) % 3);
    } while (mode == CameraMode::walk && !walkable);
    if (mode == CameraMode::walk) {
        ensure_walker();
        camera_->place(walker_->eye(*sim_));
    }
    camera_->set_mode(mode);
    say(std::string(camera_mode_name(mode)) + " camera");
}

Emitter GameSession::set_snowfall(const std::function<float(const Emitter&)>& snowfall) {
    const glm::vec3 size = sim_->config().bounds.size();
    std::vector<std::pair<EmitterId, Emitter>> changed;
    world_of(*sim_).each<Emitter>([&](Entity e, const Emitter& em) {
        changed.emplace_back(
            id_of<EmitterId>(e),
            with_snowfall(em,
                          std::clamp(snowfall(em), 0.0f, static_cast<float>(max_snowfall_kg_m2_h)),
                          static_cast<double>(size.x) * size.z));
    });
    for (const auto& [id, emitter] : changed) {
        sim_->set_emitter(id, emitter);
    }
    return changed.empty() ? Emitter{} : changed.back().second;
}

void GameSession::change_snowfall(float factor) {
    const Emitter last =
        set_snowfall([&](const Emitter& e) { return e.snowfall_kg_m2_h * factor; });
    char text[96];
    std::snprintf(text, sizeof text, "snowfall %.3g kg/m²/h (%.0f parcels/s)",
                  static_cast<double>(last.snowfall_kg_m2_h), static_cast<double>(last.rate));
    say(text);
}

void GameSession::change_wind(Action a) {
    const World& w = world_of(*sim_);
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
}

void GameSession::apply(Action a, const PlayerActions& actions, std::uint64_t frame) {
    const World& w = world_of(*sim_);
    switch (a) {
    case Action::pause:
        paused_ = !paused_;
        say(std::string(paused_ ? "paused" : "resumed") + " at tick " +
            std::to_string(sim_->tick_count()));
        break;
    case Action::step:
        if (paused_) {
            tick_once(frame, walk_input(actions.move));
            say("stepped to tick " + std::to_string(sim_->tick_count()));
        }
        break;
    case Action::reset:
        reset_to_start();
        break;
    case Action::rate_up:
    case Action::rate_down:
        change_snowfall(a == Action::rate_up ? 1.5f : 1.0f / 1.5f);
        break;
    case Action::wind_left:
    case Action::wind_right:
    case Action::wind_up:
    case Action::wind_down:
        change_wind(a);
        break;
    case Action::toggle_fog:
        if (!fog_) {
            say("this scene declares no fog");
        } else if (visuals_.fog) {
            visuals_.fog.reset();
            say("fog off");
        } else {
            visuals_.fog = fog_;
            say("fog on");
        }
        break;
    case Action::toggle_wind:
        if (!w.has_resource<WindField>()) {
            say("this scene declares no wind field");
        } else {
            show_wind_field_ = !show_wind_field_;
            say(show_wind_field_ ? "wind field arrows on (blue still, red fastest)"
                                 : "wind field arrows off");
        }
        break;
    case Action::quality_next:
        quality_ = (quality_ + 1) % quality_presets.size();
        if (load()) {
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
        if (camera_->mode() == CameraMode::walk && walker_) {
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

void GameSession::reset_to_start() {
    added_bodies_.clear();
    world_of(*sim_).each<Body>([&](Entity e, const Body&) {
        const auto saved = std::find_if(start_->bodies.begin(), start_->bodies.end(),
                                        [e](const auto& body) { return body.first == e; });
        if (saved == start_->bodies.end()) {
            added_bodies_.push_back(id_of<BodyId>(e));
        }
    });
    for (const BodyId e : added_bodies_) {
        sim_->remove(e);
    }
    try {
        restore_snapshot(*sim_, *start_);
    } catch (const SimulationError& e) { // restore changed nothing; the game goes on
        say(std::string("cannot reset: ") + e.what());
        return;
    }
    if (walker_ && walker_->alive(*sim_)) {
        walker_->restart(*sim_);
    } else {
        walker_.reset(); // it was added after the start
        if (camera_->mode() == CameraMode::walk) {
            ensure_walker();
        }
    }
    say("reset to tick " + std::to_string(sim_->tick_count()));
}

void GameSession::look(const PlayerActions& actions, float seconds) {
    CameraInput in;
    in.move = actions.move;
    if (actions.look_button || (camera_->mode() == CameraMode::orbit && actions.drag_button)) {
        in.look = actions.mouse;
    }
    in.scroll = actions.scroll;
    camera_->update(in, seconds);
}

glm::vec2 GameSession::walk_input(const glm::vec3& move) const {
    glm::vec2 walk(0.0f);
    if (camera_->mode() == CameraMode::walk) {
        const glm::vec2 f = camera_->facing();
        walk = glm::vec2(-f.y, f.x) * move.x + f * move.z; // right, forward
        if (glm::length(walk) > 1.0f) {
            walk = glm::normalize(walk);
        }
    }
    return walk;
}

void GameSession::tick_once(std::uint64_t frame, const glm::vec2& walk) {
    if (walker_) {
        const bool on_route = route_ && frame >= *opt_.walk_once_at;
        // Also rolls the snowball on.
        walker_->before_tick(*sim_, on_route ? route_->direction(*sim_, *walker_) : walk);
    }
    sim_->tick();
}

void GameSession::advance(std::uint64_t frame, std::optional<double> wall_seconds,
                          const glm::vec2& walk) {
    if (paused_) {
        ticks_last_frame_ = 0;
        return;
    }
    // Headless frames are 1/30 s of simulated time each (times the time
    // scale), whatever the wall clock; only a window's frames are budgeted.
    const double dt = sim_->config().dt;
    const std::uint64_t due =
        wall_seconds ? step_.advance(*wall_seconds)
                     : static_cast<std::uint64_t>(std::max(1l, std::lround(1.0 / (30.0 * dt))));
    const std::uint64_t ticks = time_scale_.ticks(due);
    ticks_capped_ = time_scale_.capped(due);
    if (route_ && walker_ && frame == *opt_.walk_once_at) {
        say("the walker sets off, once round its path");
    }
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    for (std::uint64_t i = 0; i < ticks; ++i) {
        tick_once(frame, walk);
    }
    if (wall_seconds) {
        time_scale_.took(ticks, std::chrono::duration<double>(Clock::now() - t0).count());
    }
    ticks_last_frame_ = ticks;
}

} // namespace snow
