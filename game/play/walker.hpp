/// @file walker.hpp
/// @brief The player of snow_game's walk mode: an upright capsule body on the
/// snow (docs/cover_and_bodies.md "Moving bodies") that the game walks tick
/// by tick through the Simulation's facade, so the carve system cuts its
/// trench; and the snowball it pushes. Reads the world, never writes it.
#pragma once

#include "game/play/snow_readout.hpp"

#include "systems/api/simulation_internals.hpp"

#include <snow/snow.hpp>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace snow {

struct WalkerSettings {
    float radius = 0.25f;     ///< capsule radius (m)
    float half_height = 0.6f; ///< capsule core half length (m): 1.7 m tall
    float eye_height = 1.6f;  ///< eye above the snow under the feet (m)
    float speed = 1.4f;       ///< walking speed (m/s)
    /// Highest rise of bare ground it steps onto (m); it stands on the highest
    /// bare top at or below its feet plus this, so it walks under a roof.
    float step = 0.35f;
    float ball_radius = 0.2f;   ///< a new snowball's bare radius (m)
    float push_speed = 2.0f;    ///< speed a push gives the snowball (m/s)
    float push_reach = 0.8f;    ///< gap (m) between player and ball within which B pushes
    float ball_friction = 0.5f; ///< a rolling ball loses this fraction of its speed per second
};

/// How the walk went so far: where the player started and is, and the snow on
/// its trail against the snow 1 m to each side of it (docs: a trench is left).
struct TrailReport {
    float walked = 0.0f; ///< length of the trail (m)
    glm::vec2 from{0.0f}, to{0.0f};
    float on_trail = 0.0f; ///< mean snow depth along the trail (m), the last metre left out
    float beside = 0.0f;   ///< mean snow depth 1 m to either side of it (m)
    std::size_t samples = 0;
};

class Walker {
  public:
    /// Adds the player's capsule at (x, z) of `start`, clamped 1 m inside the
    /// largest surface on no solid or cover (the ground).
    Walker(Simulation& sim, const glm::vec3& start, WalkerSettings settings = {});

    /// Before one tick: walks along the horizontal `direction` (length <= 1)
    /// for that tick through move_body, unless the bare ground there rises
    /// more than a step (a wall, the snowman) or has no snow surface; slides
    /// along the free axis when only one is blocked; stands it on the ground,
    /// its flat soles (Body::extent_at) on the bare top, so its footprint
    /// clears a trench as wide as it is. Slows and stops a rolling snowball
    /// the same way (set_body_velocity).
    void before_tick(Simulation& sim, const glm::vec2& direction);
    /// B: pushes the snowball away from the player when it is within reach,
    /// makes a snowball ahead (along `facing`) when there is none; says which.
    [[nodiscard]] std::string push_snowball(Simulation& sim, const glm::vec2& facing);

    /// The eye: the snow top under the player plus the eye height.
    [[nodiscard]] glm::vec3 eye(const Simulation& sim) const;
    [[nodiscard]] BodyId body() const { return body_; }
    [[nodiscard]] const WalkerSettings& settings() const { return s_; }
    /// True while the body exists (a reset to before it was added removes it).
    [[nodiscard]] bool alive(const Simulation& sim) const;
    /// After a reset that kept the body: the trail starts again where it stands.
    void restart(const Simulation& sim);
    /// Snow depth (m) under the player's centre, and 1 m ahead along `facing`.
    [[nodiscard]] float depth_under(const Simulation& sim) const;
    [[nodiscard]] float depth_ahead(const Simulation& sim, const glm::vec2& facing) const;
    [[nodiscard]] TrailReport trail(const Simulation& sim) const;

  private:
    /// Where body `b` (the player or its snowball), standing on its lowest
    /// point, gets from `from` by `delta`: the whole move, else along one
    /// axis, else nowhere.
    [[nodiscard]] glm::vec2 free_move(const World& w, const Body& b, const glm::vec2& from,
                                      const glm::vec2& delta) const;
    /// The column under (x, z) it can stand on from where its feet are now.
    [[nodiscard]] std::optional<SnowColumn> footing(const Simulation& sim, float x, float z) const;
    [[nodiscard]] bool ball_alive(const Simulation& sim) const;
    void roll_snowball(Simulation& sim);

    WalkerSettings s_;
    BodyId body_;
    BodyId ball_;
    std::vector<glm::vec2> trail_; ///< where it stood, a point every 0.25 m
};

/// A route the player walks once, e.g. the path of the scene's walker: each
/// tick, the direction towards its next point.
class WalkRoute {
  public:
    /// `points` (x, z), the first where the player starts; `speed` in m/s.
    WalkRoute(std::vector<glm::vec2> points, float speed);
    /// The direction for Walker::before_tick this tick (scaled to `speed`);
    /// zero once the last point is reached.
    [[nodiscard]] glm::vec2 direction(const Simulation& sim, const Walker& walker);
    [[nodiscard]] bool done() const { return next_ >= points_.size(); }

  private:
    std::vector<glm::vec2> points_;
    float speed_;
    std::size_t next_ = 1;
};

} // namespace snow
