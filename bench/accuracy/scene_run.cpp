#include "bench/accuracy/scene_run.hpp"
#include "systems/api/simulation_internals.hpp"

#include "bench/accuracy/cpu_clock.hpp"
#include <snow/scene.hpp>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace snow::accuracy {

std::string knob_label(const SceneKnobs& k) {
    char buf[128];
    std::snprintf(buf, sizeof buf, "dt=1/%.0f %s cell×%g smooth=%u occl=%u", 1.0 / k.dt,
                  std::string(integrator_name(k.integrator)).c_str(), k.cell_scale, k.smoothing,
                  k.occlusion);
    return buf;
}

SceneRun run_scene(const std::string& scene, const SceneKnobs& k, std::uint64_t seed, float seconds,
                   bool steady_wind) {
    SceneOverrides o;
    o.seed = seed;
    o.dt = k.dt;
    o.threads = 1; // costs are per core; 1 thread also keeps timings comparable
    o.integrator = k.integrator;
    o.cell_scale = k.cell_scale;
    o.smoothing_iterations = k.smoothing;
    o.occlusion_resolution = k.occlusion;
    SceneLoadResult loaded = load_scene_file(scene, o);
    if (!loaded.sim) {
        throw std::runtime_error(loaded.error);
    }
    Simulation& sim = *loaded.sim;
    if (const Wind* w = world_of(sim).try_resource<Wind>(); w != nullptr && steady_wind) {
        Wind steady = *w;
        steady.walk = 0.0f;
        sim.set_wind(steady);
    }
    SceneRun r;
    r.knobs = k;
    r.seed = seed;
    r.ticks = static_cast<std::uint64_t>(std::llround(static_cast<double>(seconds) / k.dt));
    const double t0 = thread_cpu_seconds();
    sim.run(r.ticks);
    r.cpu_ms_per_tick = (thread_cpu_seconds() - t0) * 1.0e3 / static_cast<double>(r.ticks);
    r.mass = sim.mass();
    r.ledger = world_of(sim).resource<MassLedger>();
    r.counters = sim.counters();
    r.field = capture_depth(sim);
    return r;
}

} // namespace snow::accuracy
