#include "game/play/walker.hpp"
#include "systems/api/simulation_internals.hpp"

#include "systems/geometry/colliders.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace snow {

namespace {

glm::vec2 xz(const glm::vec3& p) {
    return {p.x, p.z};
}

/// How far a body reaches below and above its centre.
glm::vec2 extent(const Body& b) {
    glm::vec2 e{0.0f};
    (void)b.extent_at(0.0f, 0.0f, e.x, e.y); // the centre always lies in the footprint
    return e;
}

/// Height (m) of a body's lowest point.
float bottom(const Body& b) {
    return b.position.y - extent(b).x;
}

/// Height (m) of triangle t over (x, z), false when (x, z) lies outside its
/// projection (or the triangle stands upright).
bool height_over(const glm::vec3* t, float x, float z, float& y) {
    const float ax = t[1].x - t[0].x, az = t[1].z - t[0].z;
    const float bx = t[2].x - t[0].x, bz = t[2].z - t[0].z;
    const float det = ax * bz - az * bx;
    if (det == 0.0f) {
        return false;
    }
    const float px = x - t[0].x, pz = z - t[0].z;
    const float u = (px * bz - pz * bx) / det, v = (ax * pz - az * px) / det;
    if (!(u >= 0.0f && v >= 0.0f && u + v <= 1.0f)) {
        return false;
    }
    y = t[0].y + u * (t[1].y - t[0].y) + v * (t[2].y - t[0].y);
    return true;
}

/// True when a solid fills some of the vertical span [lo, hi] over (x, z):
/// a box or sphere there, or a mesh with a face in it or enclosing its top.
bool solid_between(const World& w, float x, float z, float lo, float hi) {
    bool hit = false;
    w.each<BoxCollider>([&](Entity, const BoxCollider& c) {
        const Aabb& b = c.box;
        hit = hit || (x >= b.min.x && x <= b.max.x && z >= b.min.z && z <= b.max.z &&
                      b.min.y < hi && b.max.y > lo);
    });
    w.each<SphereCollider>([&](Entity, const SphereCollider& s) {
        const float dx = x - s.center.x, dz = z - s.center.z;
        const float half = std::sqrt(std::max(s.radius * s.radius - dx * dx - dz * dz, 0.0f));
        hit = hit || (half > 0.0f && s.center.y - half < hi && s.center.y + half > lo);
    });
    w.each<MeshCollider>([&](Entity, const MeshCollider& m) {
        std::size_t above = 0; // faces over the span: odd means its top is inside
        for (std::size_t k = 0; k + 2 < m.triangles.size() && !hit; k += 3) {
            float y = 0.0f;
            if (height_over(&m.triangles[k], x, z, y)) {
                hit = y >= lo && y <= hi;
                above += y > hi ? 1 : 0;
            }
        }
        hit = hit || above % 2 == 1;
    });
    return hit;
}

std::string metres(float m) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f m", static_cast<double>(m));
    return text;
}

} // namespace

Walker::Walker(Simulation& sim, const glm::vec3& start, WalkerSettings settings) : s_(settings) {
    glm::vec2 at = xz(start);
    if (const SnowSurface* g = ground_surface(world_of(sim))) {
        const float x1 = g->x0 + static_cast<float>(g->nx) * g->cell;
        const float z1 = g->z0 + static_cast<float>(g->nz) * g->cell;
        at = {std::clamp(at.x, std::min(g->x0 + 1.0f, x1), std::max(x1 - 1.0f, g->x0)),
              std::clamp(at.y, std::min(g->z0 + 1.0f, z1), std::max(z1 - 1.0f, g->z0))};
    }
    BodyDef d;
    d.shape = BodyShape::capsule;
    d.radius = s_.radius;
    d.half_height = s_.half_height;
    const auto column = snow_column(world_of(sim), at.x, at.y);
    d.position = {at.x, (column ? column->base : start.y) + s_.half_height + s_.radius, at.y};
    body_ = sim.add_body(d);
    trail_.push_back(at);
}

std::optional<SnowColumn> Walker::footing(const Simulation& sim, float x, float z) const {
    return snow_column(world_of(sim), x, z, bottom(body_of(sim, body_)) + s_.step);
}

bool Walker::alive(const Simulation& sim) const {
    return world_of(sim).alive(entity_of(body_)) && world_of(sim).has<Body>(entity_of(body_));
}

bool Walker::ball_alive(const Simulation& sim) const {
    return !ball_.is_null() && world_of(sim).alive(entity_of(ball_)) &&
           world_of(sim).has<Body>(entity_of(ball_));
}

void Walker::restart(const Simulation& sim) {
    trail_.assign(1, xz(body_of(sim, body_).position));
}

glm::vec2 Walker::free_move(const World& w, const Body& b, const glm::vec2& from,
                            const glm::vec2& delta) const {
    const float ground = bottom(b), top = b.position.y + extent(b).y;
    const auto free = [&](const glm::vec2& p) {
        // Ground within a step, and no solid from there up to the body's top
        // (a wall stops it; a roof higher than the body lets it under).
        return snow_column(w, p.x, p.y, ground + s_.step) &&
               !solid_between(w, p.x, p.y, ground + s_.step, top);
    };
    const float reach = b.radius;
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
    const Body& b = body_of(sim, body_);
    const glm::vec2 from = xz(b.position);
    const glm::vec2 to =
        direction == glm::vec2(0.0f)
            ? from
            : free_move(world_of(sim), b, from, direction * (s_.speed * sim.config().dt));
    // Stand on the ground there (covers build their base in the first tick).
    const auto column = footing(sim, to.x, to.y);
    const float y = column ? column->base + s_.half_height + s_.radius : b.position.y;
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
    const Body& ball = body_of(sim, ball_);
    glm::vec2 v = xz(ball.velocity);
    if (v == glm::vec2(0.0f)) {
        return;
    }
    const float dt = sim.config().dt;
    v *= std::max(0.0f, 1.0f - s_.ball_friction * dt);
    const glm::vec2 from = xz(ball.position);
    const glm::vec2 step = v * dt;
    if (glm::length(v) < 0.05f || free_move(world_of(sim), ball, from, step) != from + step) {
        v = glm::vec2(0.0f); // stopped by friction, a wall or the end of the snow
    }
    sim.set_body_velocity(ball_, {v.x, 0.0f, v.y});
}

std::string Walker::push_snowball(Simulation& sim, const glm::vec2& facing) {
    const Body& p = body_of(sim, body_);
    if (ball_alive(sim)) {
        const Body& ball = body_of(sim, ball_);
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
    const auto column = snow_column(world_of(sim), at.x, at.y);
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
    const Body& b = body_of(sim, body_);
    const auto column = footing(sim, b.position.x, b.position.z);
    const float feet = column ? column->top() : bottom(b);
    return {b.position.x, feet + s_.eye_height, b.position.z};
}

float Walker::depth_under(const Simulation& sim) const {
    const Body& b = body_of(sim, body_);
    const auto column = footing(sim, b.position.x, b.position.z);
    return column ? column->depth : 0.0f;
}

float Walker::depth_ahead(const Simulation& sim, const glm::vec2& facing) const {
    const glm::vec2 at = xz(body_of(sim, body_).position) + facing;
    const auto column = footing(sim, at.x, at.y);
    return column ? column->depth : 0.0f;
}

TrailReport Walker::trail(const Simulation& sim) const {
    TrailReport r;
    r.from = trail_.front();
    r.to = xz(body_of(sim, body_).position);
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
            const auto c = footing(sim, p.x, p.y);
            const auto l = footing(sim, p.x + side.x, p.y + side.y);
            const auto rt = footing(sim, p.x - side.x, p.y - side.y);
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
    const glm::vec2 at = xz(body_of(sim, walker.body()).position);
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
