#include "game/walker.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace snow {

namespace {

glm::vec2 xz(const glm::vec3& p) {
    return {p.x, p.z};
}

/// Height (m) of a body's lowest point.
float bottom(const Body& b) {
    float depth = 0.0f;
    (void)b.depth_below(0.0f, 0.0f, depth); // the centre always lies in the footprint
    return b.position.y - depth;
}

std::string metres(float m) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f m", static_cast<double>(m));
    return text;
}

} // namespace

Walker::Walker(Simulation& sim, const glm::vec3& start, WalkerSettings settings) : s_(settings) {
    glm::vec2 at = xz(start);
    if (const SnowSurface* g = ground_surface(sim.world())) {
        const float x1 = g->x0 + static_cast<float>(g->nx) * g->cell;
        const float z1 = g->z0 + static_cast<float>(g->nz) * g->cell;
        at = {std::clamp(at.x, std::min(g->x0 + 1.0f, x1), std::max(x1 - 1.0f, g->x0)),
              std::clamp(at.y, std::min(g->z0 + 1.0f, z1), std::max(z1 - 1.0f, g->z0))};
    }
    BodyDef d;
    d.shape = BodyShape::capsule;
    d.radius = s_.radius;
    d.half_height = s_.half_height;
    const auto column = snow_column(sim.world(), at.x, at.y);
    d.position = {at.x, (column ? column->base : start.y) + s_.half_height + s_.radius - sink(),
                  at.y};
    body_ = sim.add_body(d);
    trail_.push_back(at);
}

float Walker::sink() const {
    const float t = std::min(s_.tread, s_.radius);
    return s_.radius - std::sqrt(s_.radius * s_.radius - t * t);
}

bool Walker::alive(const Simulation& sim) const {
    return sim.world().alive(body_) && sim.world().has<Body>(body_);
}

bool Walker::ball_alive(const Simulation& sim) const {
    return !ball_.is_null() && sim.world().alive(ball_) && sim.world().has<Body>(ball_);
}

void Walker::restart(const Simulation& sim) {
    trail_.assign(1, xz(sim.body(body_).position));
}

glm::vec2 Walker::free_move(const World& w, float ground, float reach, const glm::vec2& from,
                            const glm::vec2& delta) const {
    const auto free = [&](const glm::vec2& p) {
        const auto c = snow_column(w, p.x, p.y);
        return c && c->base <= ground + s_.step;
    };
    for (const glm::vec2& d : {delta, glm::vec2(delta.x, 0.0f), glm::vec2(0.0f, delta.y)}) {
        // The centre and the body's front along each axis it moves on (the
        // scene's walls are boxes) must all find ground.
        const glm::vec2 to = from + d;
        const glm::vec2 front{d.x > 0.0f   ? reach
                              : d.x < 0.0f ? -reach
                                           : 0.0f,
                              d.y > 0.0f   ? reach
                              : d.y < 0.0f ? -reach
                                           : 0.0f};
        if (d != glm::vec2(0.0f) && free(to) && free({to.x + front.x, to.y}) &&
            free({to.x, to.y + front.y})) {
            return to;
        }
    }
    return from;
}

void Walker::before_tick(Simulation& sim, const glm::vec2& direction) {
    const Body& b = sim.body(body_);
    const glm::vec2 from = xz(b.position);
    const float ground = bottom(b) + sink();
    const glm::vec2 to = direction == glm::vec2(0.0f)
                             ? from
                             : free_move(sim.world(), ground, b.radius, from,
                                         direction * (s_.speed * sim.config().dt));
    // Stand on the ground there (covers build their base in the first tick).
    const auto column = snow_column(sim.world(), to.x, to.y);
    const float y = column ? column->base + s_.half_height + s_.radius - sink() : b.position.y;
    if (to != from || y != b.position.y) {
        sim.move_body(body_, {to.x, y, to.y});
    }
    if (glm::distance(trail_.back(), to) >= 0.25f) {
        trail_.push_back(to);
    }
    roll_snowball(sim);
}

void Walker::roll_snowball(Simulation& sim) {
    if (!ball_alive(sim)) {
        return;
    }
    const Body& ball = sim.body(ball_);
    glm::vec2 v = xz(ball.velocity);
    if (v == glm::vec2(0.0f)) {
        return;
    }
    const float dt = sim.config().dt;
    v *= std::max(0.0f, 1.0f - s_.ball_friction * dt);
    const glm::vec2 from = xz(ball.position);
    const glm::vec2 step = v * dt;
    if (glm::length(v) < 0.05f ||
        free_move(sim.world(), bottom(ball), ball.radius, from, step) != from + step) {
        v = glm::vec2(0.0f); // stopped by friction, a wall or the end of the snow
    }
    sim.set_body_velocity(ball_, {v.x, 0.0f, v.y});
}

std::string Walker::push_snowball(Simulation& sim, const glm::vec2& facing) {
    const Body& p = sim.body(body_);
    if (ball_alive(sim)) {
        const Body& ball = sim.body(ball_);
        const glm::vec2 d = xz(ball.position) - xz(p.position);
        const float gap = glm::length(d) - ball.radius - p.radius;
        if (gap > s_.push_reach) {
            return "the snowball is " + metres(gap) + " away: walk up to it";
        }
        const glm::vec2 dir = glm::length(d) > 1.0e-4f ? d / glm::length(d) : facing;
        sim.set_body_velocity(ball_, {dir.x * s_.push_speed, 0.0f, dir.y * s_.push_speed});
        return "snowball pushed (radius " + metres(ball.radius) + ")";
    }
    const glm::vec2 at = xz(p.position) + facing * (p.radius + s_.ball_radius + 0.3f);
    const auto column = snow_column(sim.world(), at.x, at.y);
    if (!column) {
        return "no snow ahead to make a snowball on";
    }
    BodyDef d;
    d.shape = BodyShape::sphere;
    d.radius = s_.ball_radius;
    d.position = {at.x, column->base + s_.ball_radius, at.y};
    d.on_ground = true;
    d.snowball = true;
    ball_ = sim.add_body(d);
    return "snowball made ahead: press B again to push it";
}

glm::vec3 Walker::eye(const Simulation& sim) const {
    const Body& b = sim.body(body_);
    const auto column = snow_column(sim.world(), b.position.x, b.position.z);
    const float feet = column ? column->top() : bottom(b) + sink();
    return {b.position.x, feet + s_.eye_height, b.position.z};
}

float Walker::depth_under(const Simulation& sim) const {
    const Body& b = sim.body(body_);
    const auto column = snow_column(sim.world(), b.position.x, b.position.z);
    return column ? column->depth : 0.0f;
}

float Walker::depth_ahead(const Simulation& sim, const glm::vec2& facing) const {
    const glm::vec2 at = xz(sim.body(body_).position) + facing;
    const auto column = snow_column(sim.world(), at.x, at.y);
    return column ? column->depth : 0.0f;
}

TrailReport Walker::trail(const Simulation& sim) const {
    TrailReport r;
    r.from = trail_.front();
    r.to = xz(sim.body(body_).position);
    std::vector<glm::vec2> path = trail_;
    path.push_back(r.to);
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        r.walked += glm::distance(path[i], path[i + 1]);
    }
    // Samples every 0.25 m of the trail up to a metre before the player (its
    // own footprint), each beside the segment it lies on.
    constexpr float spacing = 0.25f;
    double on = 0.0, beside = 0.0;
    float along = 0.0f;
    for (std::size_t i = 0; i + 1 < path.size(); ++i) {
        const glm::vec2 d = path[i + 1] - path[i];
        const float length = glm::length(d);
        const glm::vec2 side = length > 0.0f ? glm::vec2(-d.y, d.x) / length : glm::vec2(0.0f);
        for (float t = std::ceil(along / spacing) * spacing - along;
             t < length && along + t <= r.walked - 1.0f; t += spacing) {
            const glm::vec2 p = path[i] + d * (t / length);
            const auto c = snow_column(sim.world(), p.x, p.y);
            const auto l = snow_column(sim.world(), p.x + side.x, p.y + side.y);
            const auto rt = snow_column(sim.world(), p.x - side.x, p.y - side.y);
            if (c && l && rt) {
                on += c->depth;
                beside += 0.5 * (l->depth + rt->depth);
                ++r.samples;
            }
        }
        along += length;
    }
    if (r.samples > 0) {
        r.on_trail = static_cast<float>(on / static_cast<double>(r.samples));
        r.beside = static_cast<float>(beside / static_cast<double>(r.samples));
    }
    return r;
}

WalkRoute::WalkRoute(std::vector<glm::vec2> points, float speed)
    : points_(std::move(points)), speed_(speed) {}

glm::vec2 WalkRoute::direction(const Simulation& sim, const Walker& walker) {
    const float step = speed_ * sim.config().dt;
    const glm::vec2 at = xz(sim.body(walker.body()).position);
    while (!done() && glm::distance(points_[next_], at) <= step) {
        ++next_; // reached (this tick's step would overshoot it)
    }
    if (done() || step <= 0.0f) {
        return glm::vec2(0.0f);
    }
    const glm::vec2 d = points_[next_] - at;
    return d / glm::length(d) * std::min(1.0f, speed_ / walker.settings().speed);
}

} // namespace snow
