// A host engine's loop driving snow at its own frame rate: the simulation
// ticks at a fixed dt through snow::FixedStep, the host adds a collider and
// rolls a snowball at run time, reads flakes, snow depth and the snowball,
// and checks the mass books. Only <snow/snow.hpp> and snow::sim (no GL).
#include <snow/snow.hpp>

#include <algorithm>
#include <cstdio>

int main() {
    snow::SimConfig config;
    config.seed = 2026;
    config.dt = 1.0f / 60.0f;
    config.max_flakes = 20000;
    config.bounds = {{-6.0f, -0.5f, -6.0f}, {6.0f, 8.0f, 6.0f}};

    try {
        snow::Simulation sim(config);
        snow::SurfaceDef ground;
        ground.x0 = ground.z0 = -6.0f;
        ground.size_x = ground.size_z = 12.0f;
        ground.cell = 0.1f;
        ground.spills = false;
        const snow::SurfaceId ground_id = sim.add_surface(ground);
        snow::Emitter emitter;
        emitter.rate = 4000.0f;
        sim.add_emitter(emitter);
        snow::Wind wind;
        wind.base = wind.current = {1.5f, 0.0f, 0.0f};
        sim.set_wind(wind);

        // The host renders at 144 Hz; the simulation keeps its 60 Hz tick.
        const double frame_dt = 1.0 / 144.0;
        snow::FixedStep step(config.dt);
        snow::BodyId snowball;
        for (int frame = 0; frame < 144 * 8; ++frame) {
            sim.run(step.advance(frame_dt));
            if (frame == 144 * 2) {
                sim.add_sphere({0.0f, 1.0f, 0.0f}, 1.0f); // run-time collider
            }
            if (frame == 144 * 5) { // a snowball rolls across the snow it has by now
                snow::BodyDef ball;
                ball.position = {-4.0f, 0.5f, 3.05f}; // on a row of cell centres
                ball.radius = 0.5f;
                ball.snowball = true;
                ball.on_ground = true;
                snowball = sim.add_body(ball);
                sim.set_body_velocity(snowball, {2.0f, 0.0f, 0.0f});
            }
        }

        const snow::SnowGrid surface = sim.surface(ground_id);
        float deepest = 0.0f;
        for (std::size_t i = 0; i < surface.cell_count(); ++i) {
            deepest = std::max(deepest, surface.depth(i));
        }
        const snow::MassReport m = sim.mass();
        std::printf("embed_snow: %llu ticks, %u flakes airborne, deepest snow %.4f m\n",
                    static_cast<unsigned long long>(sim.tick_count()), sim.flakes().alive,
                    static_cast<double>(deepest));
        const snow::BodyState ball = sim.body(snowball);
        std::printf("embed_snow: the snowball picked up %llu units on its way to x = %.2f m\n",
                    static_cast<unsigned long long>(ball.carried),
                    static_cast<double>(ball.position.x));
        std::printf(
            "embed_snow: mass units spawned %llu = airborne %llu + settled %llu + "
            "carried %llu + removed %llu, state hash %016llx\n",
            static_cast<unsigned long long>(m.spawned), static_cast<unsigned long long>(m.airborne),
            static_cast<unsigned long long>(m.settled), static_cast<unsigned long long>(m.carried),
            static_cast<unsigned long long>(m.removed),
            static_cast<unsigned long long>(sim.state_hash()));
        if (!m.balanced() || m.settled == 0 || ball.carried == 0) {
            std::fprintf(stderr, "embed_snow: unexpected mass report\n");
            return 1;
        }
    } catch (const snow::Error& e) {
        std::fprintf(stderr, "embed_snow: %s\n", e.what());
        return 2;
    }
    return 0;
}
