#include "tests/scenes/sample_scenes.hpp"

#include "ecs/rng.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/flakes/snowfall.hpp"

#include <utility>
#include <vector>

namespace snow {

std::unique_ptr<Simulation> make_yard(const YardOptions& o) {
    SimConfig cfg;
    cfg.seed = o.seed;
    cfg.threads = o.threads;
    cfg.task_system = o.task_system;
    cfg.dt = o.dt;
    cfg.integrator = o.integrator;
    cfg.max_flakes = o.max_flakes;
    cfg.bounds = {{-8.0f, -0.5f, -8.0f}, {8.0f, 10.0f, 8.0f}};
    auto sim = std::make_unique<Simulation>(cfg);

    SurfaceDef ground;
    ground.x0 = -8.0f;
    ground.z0 = -8.0f;
    ground.size_x = ground.size_z = 16.0f;
    ground.cell = 16.0f / static_cast<float>(o.ground_cells);
    ground.spills = false;
    sim->add_surface(ground);

    const Aabb garage{{-1.0f, 0.0f, -1.5f}, {2.0f, 2.5f, 1.5f}};
    const ColliderId box = sim->add_box(garage);
    SurfaceDef roof;
    roof.x0 = garage.min.x;
    roof.z0 = garage.min.z;
    roof.size_x = garage.size().x;
    roof.size_z = garage.size().z;
    roof.cell = 0.1f;
    roof.base_y = garage.max.y;
    roof.edge_limit = 0.05f;
    sim->add_surface(roof, box);

    sim->add_sphere({-4.0f, 0.8f, 3.0f}, 0.8f);
    if (o.wind) {
        Wind wind;
        wind.base = wind.current = {2.0f, 0.0f, 0.0f};
        sim->set_wind(wind);
    }
    if (o.emitter_rate > 0.0f) {
        Emitter e;
        e.rate = o.emitter_rate;
        const glm::vec3 size = sim->config().bounds.size();
        e.snowfall_kg_m2_h =
            o.snowfall_kg_m2_h > 0.0f
                ? o.snowfall_kg_m2_h
                : heaviest_snowfall_kg_m2_h(e, static_cast<double>(size.x) * size.z);
        sim->add_emitter(e);
    }
    prefill_flakes(*sim, o.prefill);
    return sim;
}

YardOptions busy_yard(unsigned threads) {
    YardOptions o;
    o.threads = threads;
    o.max_flakes = 60000;
    o.prefill = 40000;
    o.emitter_rate = 6000.0f;
    return o;
}

FlakeSpec prefill_flake(const SimConfig& config, std::uint32_t n) {
    const glm::vec3 lo = config.bounds.min, hi = config.bounds.max;
    const RngKey k{config.seed, ~0ull, n, random_stream::spawn_position};
    FlakeSpec f;
    f.position = {rng_range(k, 0, lo.x, hi.x), rng_range(k, 1, lo.y + 0.5f * (hi.y - lo.y), hi.y),
                  rng_range(k, 2, lo.z, hi.z)};
    f.velocity = {0.0f, -1.0f, 0.0f};
    f.mass_units = 1 + rng_below(k, 3, 40);
    return f;
}

namespace {

/// A body of `shape` and `radius` lapping `path` at 1.5 m/s from its first point.
BodyDef lapping(BodyShape shape, float radius, std::vector<glm::vec3> path) {
    BodyDef d;
    d.shape = shape;
    d.radius = radius;
    d.position = path.front();
    d.motion = BodyMotion{std::move(path), 1.5f, true};
    return d;
}

} // namespace

std::unique_ptr<Simulation> make_stormy_yard(unsigned threads, TaskSystem* task_system) {
    YardOptions o;
    o.threads = threads;
    o.task_system = task_system;
    o.ground_cells = 64;
    o.max_flakes = 60000;
    o.prefill = 40000;
    o.emitter_rate = 6000.0f;
    auto sim = make_yard(o);
    Wind wind;
    wind.base = wind.current = {2.0f, 0.0f, 0.5f};
    wind.walk = 1.5f;
    wind.max_deviation = 2.0f;
    wind.gust_strength = 3.0f;
    wind.gust_rate = 0.8f;
    wind.gust_duration = 0.7f;
    sim->set_wind(wind);
    const glm::vec3 a{-6.0f, 2.0f, 1.0f}, b{-2.0f, 2.0f, 1.0f}, c{-2.0f, 2.5f, 5.0f},
        d{-6.0f, 2.5f, 5.0f};
    const ColliderId shelter = sim->add_mesh_collider({a, b, c, a, c, d});
    SurfaceDef roof;
    roof.x0 = a.x;
    roof.z0 = a.z;
    roof.size_x = b.x - a.x;
    roof.size_z = d.z - a.z;
    roof.cell = 0.1f;
    roof.base_y = a.y;
    roof.slope_z = (d.y - a.y) / (d.z - a.z);
    roof.edge_limit = 0.0005f;
    sim->add_surface(roof, shelter);
    sim->add_mesh_collider({{3.0f, 1.0f, -6.0f}, {6.0f, 1.5f, -6.0f}, {4.5f, 2.5f, -3.0f}});
    OcclusionCamera cam;
    cam.resolution = 96;
    cam.tilt = 0.5f;
    sim->set_occlusion(cam);
    sim->add_sphere({4.5f, 0.2f, 5.0f}, 0.7f); // a boulder under a snow cover
    CoverDef cover;
    cover.min_x = 3.0f;
    cover.min_z = 3.5f;
    cover.max_x = 7.0f;
    cover.max_z = 7.0f;
    cover.cell = 0.1f;
    sim->add_cover(cover);
    // A snowball pressed into the ground doing laps: it takes the snow it rolls over.
    BodyDef ball = lapping(
        BodyShape::sphere, 0.3f,
        {{-6.0f, 0.2f, -6.0f}, {-2.0f, 0.2f, -6.0f}, {-2.0f, 0.2f, -3.0f}, {-6.0f, 0.2f, -3.0f}});
    ball.snowball = true;
    sim->add_body(ball);
    // A capsule walking laps through the ground's snow: trails and rims.
    BodyDef walker = lapping(BodyShape::capsule, 0.25f,
                             {{2.0f, 0.0f, -4.0f}, {6.0f, 0.0f, -4.0f}, {6.0f, 0.0f, 4.0f}});
    walker.half_height = 0.6f;
    walker.on_ground = true;
    sim->add_body(walker);
    WindFieldDef field; // a coarse field the buildings shape
    field.cells_x = field.cells_z = 16;
    field.cells_y = 8;
    field.update_every = 2;
    sim->set_wind_field(field);
    // Gusts lift the snow off the windward ends. A short adjustment length:
    // the flux reaches its full rate within the small roofs, so every tick
    // sees snow shed over their edges.
    WindTransportDef drift;
    drift.adjustment_length = 0.5f;
    sim->set_wind_transport(drift);
    return sim;
}

void prefill_flakes(Simulation& sim, std::uint32_t count) {
    for (std::uint32_t n = 0; n < count; ++n) {
        if (!sim.place_flake(prefill_flake(sim.config(), n))) {
            return;
        }
    }
}

} // namespace snow
