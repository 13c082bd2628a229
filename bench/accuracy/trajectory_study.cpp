// Trajectory error of each integrator against integrate::exact_at, and its
// cost through the same integrate_system the simulation runs (stiffness guards
// included), timed in thread CPU time, fastest of several repeats.
#include "bench/accuracy/trajectory_study.hpp"

#include "bench/accuracy/cpu_clock.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/flakes/integrator.hpp"
#include "tests/scenes/sample_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

namespace snow::accuracy {

namespace {

/// k/m of flake i: terminal speed g/(k/m) spread evenly over [fall_min, fall_max].
float drag_of(const TrajectoryOptions& o, float g, std::uint32_t i) {
    const float u = (static_cast<float>(i % o.flakes) + 0.5f) / static_cast<float>(o.flakes);
    return g / (o.fall_min + (o.fall_max - o.fall_min) * u);
}

/// An empty simulation with a steady wind; flakes are added by the caller and
/// only integrate_system is run, so nothing but the integrator acts on them.
std::unique_ptr<Simulation> make_pool(const TrajectoryOptions& o, float dt, Integrator i,
                                      std::uint32_t capacity) {
    SimConfig c;
    c.dt = dt;
    c.integrator = i;
    c.max_flakes = capacity;
    auto sim = std::make_unique<Simulation>(c);
    Wind w;
    w.base = w.current = o.wind;
    w.walk = 0.0f;
    sim->set_wind(w);
    return sim;
}

std::uint64_t ticks_for(float seconds, float dt) {
    return static_cast<std::uint64_t>(std::llround(static_cast<double>(seconds) / dt));
}

/// Error columns of one (integrator, dt): flakes start at rest at the origin.
TrajectoryRow measure_error(const TrajectoryOptions& o, Integrator integrator, float dt) {
    auto sim = make_pool(o, dt, integrator, o.flakes);
    const FlakePool& f = flake_pool(*sim);
    const glm::vec3 g = sim->config().gravity;
    for (std::uint32_t n = 0; n < o.flakes; ++n) {
        FlakeSpec flake;
        flake.k_over_m = drag_of(o, -g.y, n);
        (void)sim->place_flake(flake);
    }
    TrajectoryRow row{integrator, dt, 0.0, 0.0, 0.0, 0.0, 0.0};
    const std::uint64_t ticks = ticks_for(o.seconds, dt);
    double last_sq = 0.0;
    for (std::uint64_t t = 1; t <= ticks; ++t) {
        integrate_system(InternalAccess::world(*sim));
        // The simulation's own dt (a float) is the step the exact solution follows.
        const double time = static_cast<double>(dt) * static_cast<double>(t);
        last_sq = 0.0;
        for (std::uint32_t i = 0; i < f.slot_end; ++i) {
            const double c = f.k_over_m[i];
            double dp2 = 0.0, dv2 = 0.0;
            const float p[3] = {f.px[i], f.py[i], f.pz[i]};
            const float v[3] = {f.vx[i], f.vy[i], f.vz[i]};
            for (int a = 0; a < 3; ++a) {
                double pe = 0.0, ve = 0.0;
                integrate::exact_at(pe, ve, 0.0, 0.0, c, g[a], o.wind[a], time);
                dp2 += (p[a] - pe) * (p[a] - pe);
                dv2 += (v[a] - ve) * (v[a] - ve);
            }
            row.max_pos_error = std::max(row.max_pos_error, std::sqrt(dp2));
            row.max_vel_error = std::max(row.max_vel_error, std::sqrt(dv2));
            last_sq += dp2;
        }
    }
    row.rms_pos_error = std::sqrt(last_sq / f.slot_end);
    row.stiff_share = static_cast<double>(sim->counters().stiff_flake_ticks) /
                      (static_cast<double>(f.slot_end) * static_cast<double>(ticks));
    return row;
}

/// Fastest repeat of integrate_system over a prefilled pool, in ns per flake-tick.
double measure_cost(const TrajectoryOptions& o, Integrator integrator, float dt,
                    std::uint32_t flakes) {
    auto sim = make_pool(o, dt, integrator, flakes);
    const float g = -sim->config().gravity.y;
    for (std::uint32_t i = 0; i < flakes; ++i) {
        FlakeSpec flake = prefill_flake(sim->config(), i);
        flake.k_over_m = drag_of(o, g, i); // the emitter's spread, so guards trip as in a scene
        (void)sim->place_flake(flake);
    }
    World& w = InternalAccess::world(*sim);
    for (int i = 0; i < 10; ++i) {
        integrate_system(w); // warm-up: caches, the guard's scratch
    }
    double best = 1.0e30;
    for (int r = 0; r < o.timing_repeats; ++r) {
        const double t0 = thread_cpu_seconds();
        for (std::uint32_t t = 0; t < o.timing_ticks; ++t) {
            integrate_system(w);
        }
        best = std::min(best, thread_cpu_seconds() - t0);
    }
    return best * 1.0e9 / (static_cast<double>(o.timing_ticks) * flake_pool(*sim).alive);
}

} // namespace

std::vector<TrajectoryRow> run_trajectory_study(const TrajectoryOptions& o) {
    std::vector<TrajectoryRow> rows;
    for (const Integrator i : o.integrators) {
        for (const float dt : o.dts) {
            TrajectoryRow row = measure_error(o, i, dt);
            row.ns_per_flake_tick = measure_cost(o, i, dt, o.timing_flakes);
            rows.push_back(row);
        }
    }
    return rows;
}

std::vector<double> integrator_costs(const TrajectoryOptions& o, float dt, std::uint32_t flakes) {
    std::vector<double> ns;
    for (const Integrator i : o.integrators) {
        ns.push_back(measure_cost(o, i, dt, flakes));
    }
    return ns;
}

} // namespace snow::accuracy
