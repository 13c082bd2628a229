#include "systems/sample_scenes.hpp"

#include "ecs/rng.hpp"
#include "systems/random_streams.hpp"

namespace snow {

std::unique_ptr<Simulation> make_yard(const YardOptions& o) {
    SimConfig cfg;
    cfg.seed = o.seed;
    cfg.threads = o.threads;
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
    const Entity box = sim->add_box(garage);
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
        sim->add_emitter(e);
    }
    prefill_flakes(*sim, o.prefill);
    return sim;
}

std::unique_ptr<Simulation> make_stormy_yard(unsigned threads) {
    YardOptions o;
    o.threads = threads;
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
    const Entity shelter = sim->add_mesh_collider({a, b, c, a, c, d});
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
    BodyDef ball;
    ball.radius = 0.3f;
    ball.position = {-6.0f, 0.2f, -6.0f};
    ball.snowball = true;
    ball.motion.waypoints = {
        {-6.0f, 0.2f, -6.0f}, {-2.0f, 0.2f, -6.0f}, {-2.0f, 0.2f, -3.0f}, {-6.0f, 0.2f, -3.0f}};
    ball.motion.speed = 1.5f;
    sim->add_body(ball);
    return sim;
}

void prefill_flakes(Simulation& sim, std::uint32_t count) {
    const SimConfig& cfg = sim.config();
    FlakePool& f = sim.world().resource<FlakePool>();
    auto& ledger = sim.world().resource<MassLedger>();
    const glm::vec3 lo = cfg.bounds.min, hi = cfg.bounds.max;
    for (std::uint32_t n = 0; n < count; ++n) {
        std::uint32_t slot = 0;
        if (!f.acquire(slot)) {
            return;
        }
        const RngKey k{cfg.seed, ~0ull, slot, random_stream::spawn_position};
        f.px[slot] = rng_range(k, 0, lo.x, hi.x);
        f.py[slot] = rng_range(k, 1, lo.y + 0.5f * (hi.y - lo.y), hi.y);
        f.pz[slot] = rng_range(k, 2, lo.z, hi.z);
        f.vx[slot] = 0.0f;
        f.vy[slot] = -1.0f;
        f.vz[slot] = 0.0f;
        f.k_over_m[slot] = 9.81f;
        f.size[slot] = 0.01f;
        f.mass_units[slot] = 1 + rng_below(k, 3, 40);
        ledger.spawned += f.mass_units[slot];
    }
}

} // namespace snow
