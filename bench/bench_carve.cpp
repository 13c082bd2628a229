// Trails (issue 14): what moving bodies cost the carve system per body per
// tick. Spheres of 0.5 m diameter (a 0.5 m footprint) sunk into 10 cm of
// snow on 5 cm cells, each lapping its own square at 1.5 m/s, so every tick
// each one ploughs fresh cells and pushes them to its rims. Only the body
// and carve systems run (nothing falls), so the time is theirs alone.
#include "systems/api/simulation_internals.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

namespace snow::bench {
namespace {

constexpr float half = 10.0f;    ///< the ground spans [-half, half]² (m)
constexpr float cell = 0.05f;    ///< 400² cells
constexpr float radius = 0.25f;  ///< 0.5 m footprint
constexpr float snow_m = 0.10f;  ///< depth of the snow every body ploughs
constexpr float lap_side = 1.5f; ///< each body laps a square this wide (m)
constexpr float lane = 1.9f;     ///< spacing of the laps' squares (m)
/// Ticks between restores of the starting state (outside the timing): a body
/// laps its square in 4 s, so every measured tick meets unploughed snow.
constexpr std::uint64_t restore_every = 120;

std::unique_ptr<Simulation> make_ploughed_field(std::uint32_t bodies) {
    SimConfig c;
    c.bounds = {{-half, -1.0f, -half}, {half, 4.0f, half}};
    c.max_flakes = 1024;
    auto sim = std::make_unique<Simulation>(c);
    SurfaceDef ground;
    ground.x0 = ground.z0 = -half;
    ground.size_x = ground.size_z = 2.0f * half;
    ground.cell = cell;
    ground.spills = false;
    const SurfaceId g = sim->add_surface(ground);
    const SnowSurface& s = snow_surface(*sim, g);
    const auto units = static_cast<std::uint32_t>(std::lround(snow_m / s.unit_height));
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            sim->add_settled_snow(g, ix, iz, units);
        }
    }
    const auto per_row = static_cast<std::uint32_t>((2.0f * half - 1.0f) / lane);
    for (std::uint32_t k = 0; k < bodies; ++k) {
        const float x = -half + 0.5f + lane * static_cast<float>(k % per_row);
        const float z = -half + 0.5f + lane * static_cast<float>(k / per_row);
        const float y = radius; // the lowest point on the bare ground: sunk 10 cm
        BodyDef b;
        b.radius = radius;
        b.position = {x, y, z};
        b.motion.waypoints = {
            {x, y, z}, {x + lap_side, y, z}, {x + lap_side, y, z + lap_side}, {x, y, z + lap_side}};
        b.motion.speed = 1.5f;
        sim->add_body(b);
    }
    return sim;
}

void BM_CarveTrails(benchmark::State& state) {
    const auto bodies = static_cast<std::uint32_t>(state.range(0));
    const auto sim = make_ploughed_field(bodies);
    World& w = InternalAccess::world(*sim);
    const auto start = save_snapshot(*sim);
    std::uint64_t carved = 0, iteration = 0;
    for (auto _ : state) {
        const std::uint64_t before = sim->counters().carved_units;
        body_system(w);
        carve_system(w);
        carved += sim->counters().carved_units - before;
        if (++iteration % restore_every == 0) {
            state.PauseTiming();
            restore_snapshot(*sim, *start);
            state.ResumeTiming();
        }
    }
    const double ticks = static_cast<double>(state.iterations());
    state.counters["bodies"] = bodies;
    state.counters["units_moved_per_tick"] = static_cast<double>(carved) / ticks;
    // Time per body per tick, in seconds (printed with an SI prefix: 3.5u = 3.5 µs).
    state.counters["per_body_tick"] = benchmark::Counter(
        ticks * bodies, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_CarveTrails)->ArgName("bodies")->Arg(1)->Arg(100)->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace snow::bench
