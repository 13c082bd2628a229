#include "bench_scene.hpp"

#include "systems/colliders.hpp"

#include <algorithm>
#include <cmath>

namespace snow::bench {

namespace {

/// Ticks run before the snapshot in snowfall, so measured ticks see flakes
/// already landing and the ground already carrying snow.
constexpr std::uint64_t settle_ticks = 30;

double fract(double x) {
    return x - std::floor(x);
}

/// Lowest height (m) a flake over (x, z) starts at: 5 cm above the ground,
/// or above any box or sphere whose footprint covers (x, z), so no flake
/// starts inside a collider (it would be pushed out to a wall and make a
/// drift that no steady snowfall has).
float start_floor(const World& w, float x, float z) {
    float floor = 0.05f;
    w.each<BoxCollider>([&](Entity, const BoxCollider& b) {
        if (x >= b.box.min.x && x <= b.box.max.x && z >= b.box.min.z && z <= b.box.max.z) {
            floor = std::max(floor, b.box.max.y + 0.05f);
        }
    });
    w.each<SphereCollider>([&](Entity, const SphereCollider& s) {
        const float dx = x - s.center.x, dz = z - s.center.z;
        if (dx * dx + dz * dz <= s.radius * s.radius) {
            floor = std::max(floor, s.center.y + s.radius + 0.05f);
        }
    });
    return floor;
}

/// Places `count` prefill flakes spread over [start_floor, top of bounds] (a
/// fixed low-discrepancy sequence in the flake number) at terminal velocity in the wind.
void place_over_height(Simulation& sim, std::uint32_t count) {
    const World& w = sim.world();
    const float top = sim.config().bounds.max.y;
    const glm::vec3 wind = w.resource<Wind>().current;
    for (std::uint32_t i = 0; i < count; ++i) {
        FlakeSpec f = prefill_flake(sim.config(), i);
        const float lo = start_floor(w, f.position.x, f.position.z);
        f.position.y = lo + (top - lo) * static_cast<float>(fract(i * 0.7548776662466927));
        f.velocity = wind - glm::vec3(0.0f, 9.81f / f.k_over_m, 0.0f);
        (void)sim.place_flake(f);
    }
}

} // namespace

BenchWorld::BenchWorld(std::uint32_t flakes, unsigned threads, Load load) {
    YardOptions o;
    o.threads = threads;
    o.ground_cells = 512;
    o.max_flakes = flakes + flakes / 8;
    o.emitter_rate = 0.0f; // the load is the prefilled flakes, restored periodically
    o.prefill = load == Load::aloft ? flakes : 0;
    sim = make_yard(o);
    if (load == Load::snowfall) {
        place_over_height(*sim, flakes);
        sim->run(settle_ticks);
    }
    start = sim->save();
}

void BenchWorld::step_done(benchmark::State& state, std::uint64_t& iteration,
                           std::uint32_t alive_before) {
    flake_ticks += alive_before;
    if (++iteration % restore_every == 0) {
        state.PauseTiming();
        sim->restore(*start);
        state.ResumeTiming();
    }
}

void report_per_flake(benchmark::State& state, const BenchWorld& world) {
    const auto ticks = static_cast<double>(state.iterations());
    state.counters["flakes"] = ticks > 0 ? static_cast<double>(world.flake_ticks) / ticks : 0.0;
    // A rate, inverted: seconds per flake-tick (the console prints it in ns;
    // --benchmark_format=json holds the value in seconds).
    state.counters["ns_per_flake"] =
        benchmark::Counter(static_cast<double>(world.flake_ticks),
                           benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace snow::bench
