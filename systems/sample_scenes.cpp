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

void prefill_flakes(Simulation& sim, std::uint32_t count) {
    for (std::uint32_t n = 0; n < count; ++n) {
        if (!sim.place_flake(prefill_flake(sim.config(), n))) {
            return;
        }
    }
}

} // namespace snow
