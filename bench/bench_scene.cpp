#include "bench_scene.hpp"
#include "systems/api/simulation_internals.hpp"

#include "systems/flakes/flake_order.hpp"
#include "systems/geometry/colliders.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <utility>

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
    const World& w = world_of(sim);
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
    // Start on an ordering tick: each restore cycle orders the pool once
    // (twice as often as a long run does) and then lets the order decay.
    while (sim->tick_count() % flake_order_every != 0) {
        sim->tick();
    }
    start = save_snapshot(*sim);
}

BenchWorld::BenchWorld(std::unique_ptr<Simulation> ready) : sim(std::move(ready)) {
    start = save_snapshot(*sim);
}

void BenchWorld::restore(benchmark::State& state) {
    state.PauseTiming();
    restore_snapshot(*sim, *start);
    state.ResumeTiming();
}

double FlakeClock::process_cpu_ns() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1.0e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

void FlakeClock::report(benchmark::State& state) const {
    const bool any = flake_ticks_ > 0.0;
    state.counters["flakes"] = calls_ > 0 ? flake_ticks_ / static_cast<double>(calls_) : 0.0;
    state.counters["ns_per_flake"] = any ? ns_ / flake_ticks_ : 0.0;
    state.counters["cpu_ns_per_flake"] = any ? cpu_ns_ / flake_ticks_ : 0.0;
}

void flake_args(benchmark::internal::Benchmark* b, std::initializer_list<int> sizes) {
    b->ArgNames({"flakes", "threads"});
    for (const int n : sizes) {
        for (const int t : {1, 2}) {
            b->Args({n, t});
        }
    }
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

} // namespace snow::bench
