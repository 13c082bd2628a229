// The wind-field study: every run loads the scene with the same seed (same
// flakes, same gusts and walk), declares a field of the studied size and
// interval, and samples the field's wind at fixed probes every 4 ticks after
// the warm-up. The lee box and strip are those of the village's lee test
// (tests/game/scene/test_wind_field_scene.cpp): 0.25 – 2.25 m behind the garage's
// lee face (x 7.25 – 9.25), along its width (z −3 – 0).
#include "bench/accuracy/wind_field_study.hpp"

#include "bench/accuracy/cpu_clock.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/api/systems.hpp"
#include "systems/snowpack/ground_snow.hpp"
#include <snow/scene.hpp>

#include <glm/vec3.hpp>

#include <cmath>
#include <stdexcept>

namespace snow::accuracy {

namespace {

constexpr float lee_x0 = 7.25f, lee_x1 = 9.25f, lee_z0 = -3.0f, lee_z1 = 0.0f;
constexpr std::uint64_t sample_every = 4; // ticks

/// Probe points: the wide lattice, then the lee box, then the free stream.
struct Probes {
    std::vector<glm::vec3> at;
    std::size_t lee_begin = 0, free_begin = 0;
};

Probes make_probes() {
    Probes p;
    for (const float y : {0.5f, 1.5f, 3.0f}) {
        for (float z = -9.5f; z < 10.0f; z += 1.0f) {
            for (float x = -9.5f; x < 10.0f; x += 1.0f) {
                p.at.push_back({x, y, z});
            }
        }
    }
    p.lee_begin = p.at.size();
    for (float y = 0.25f; y < 1.3f; y += 0.25f) {
        for (float z = lee_z0 + 0.125f; z < lee_z1; z += 0.25f) {
            for (float x = lee_x0 + 0.125f; x < lee_x1; x += 0.25f) {
                p.at.push_back({x, y, z});
            }
        }
    }
    p.free_begin = p.at.size();
    for (float z = -3.0f; z < 3.0f; z += 0.5f) {
        p.at.push_back({-9.5f, 1.5f, z}); // upwind of the fence, at the inflow
    }
    return p;
}

/// CPU ms per tick of the wind_field system alone: 16 steps' worth of calls
/// on the run's final state (the run is over; they only advance the field).
double field_cpu_ms_per_tick(Simulation& sim, std::uint32_t update_every) {
    World& w = InternalAccess::world(sim);
    const std::uint32_t calls = 16 * update_every;
    const double t0 = thread_cpu_seconds();
    for (std::uint32_t c = 0; c < calls; ++c) {
        wind_field_system(w);
    }
    return (thread_cpu_seconds() - t0) * 1.0e3 / calls;
}

struct Run {
    WindFieldPoint point;
    std::vector<glm::vec3> mean; ///< per probe: time-mean wind
};

Run run_field(const WindFieldStudyOptions& o, const WindFieldKnobs& k, const Probes& probes,
              float& dt) {
    SceneOverrides ov;
    ov.seed = o.seed;
    ov.threads = 1;
    SceneLoadResult loaded = load_scene_file(o.scene, ov);
    if (!loaded.sim) {
        throw std::runtime_error(loaded.error);
    }
    Simulation& sim = *loaded.sim;
    WindFieldDef def;
    def.cells_x = k.cells(0);
    def.cells_y = k.cells(1);
    def.cells_z = k.cells(2);
    def.update_every = k.update_every;
    def.sample_every = k.sample_every;
    sim.set_wind_field(def);
    dt = sim.config().dt;
    const auto ticks = static_cast<std::uint64_t>(std::llround(o.seconds / dt));
    const auto warm = static_cast<std::uint64_t>(std::llround(o.warmup / dt));
    Run r;
    r.point.knobs = k;
    r.point.ticks = ticks;
    r.mean.assign(probes.at.size(), glm::vec3(0.0f));
    std::uint64_t samples = 0;
    sim.run(warm);
    // The tick's cost over the ticks after the warm-up: the first step's
    // long projection and the obstacle marking are not what a tick pays.
    const double t0 = thread_cpu_seconds();
    for (std::uint64_t t = warm; t + sample_every <= ticks; t += sample_every) {
        sim.run(sample_every);
        const WindField& f = world_of(sim).resource<WindField>();
        for (std::size_t i = 0; i < probes.at.size(); ++i) {
            r.mean[i] += f.at(probes.at[i].x, probes.at[i].y, probes.at[i].z);
        }
        ++samples;
    }
    sim.run(ticks - warm - samples * sample_every);
    const auto timed = static_cast<double>(ticks - warm);
    r.point.cpu_ms_per_tick = (thread_cpu_seconds() - t0) * 1.0e3 / timed;
    r.point.field_ms_per_tick = field_cpu_ms_per_tick(sim, k.update_every);
    for (glm::vec3& m : r.mean) {
        m /= static_cast<float>(std::max<std::uint64_t>(samples, 1));
    }
    const auto mean_speed = [&](std::size_t from, std::size_t to) {
        double sum = 0.0;
        for (std::size_t i = from; i < to; ++i) {
            sum += std::hypot(static_cast<double>(r.mean[i].x), static_cast<double>(r.mean[i].z));
        }
        return sum / static_cast<double>(to - from);
    };
    r.point.lee_speed = mean_speed(probes.lee_begin, probes.free_begin);
    r.point.free_speed = mean_speed(probes.free_begin, probes.at.size());
    r.point.lee_units = ground_units_in(world_of(sim), {lee_x0, lee_z0, lee_x1, lee_z1});
    r.point.depth = capture_depth(sim);
    return r;
}

/// Σ |a − b| / Σ |b| over the wide lattice, horizontal components.
double wind_rel_l1(const Run& a, const Run& ref, const Probes& probes) {
    double diff = 0.0, size = 0.0;
    for (std::size_t i = 0; i < probes.lee_begin; ++i) {
        const glm::vec3 d = a.mean[i] - ref.mean[i];
        diff += std::hypot(static_cast<double>(d.x), static_cast<double>(d.z));
        size += std::hypot(static_cast<double>(ref.mean[i].x), static_cast<double>(ref.mean[i].z));
    }
    return size > 0.0 ? diff / size : 0.0;
}

void say(std::FILE* progress, const char* role, const WindFieldPoint& p) {
    if (progress == nullptr) {
        return;
    }
    std::fprintf(progress,
                 "  %-8s field %ux%ux%u every %2u, samples every %2u  %7.3f ms/tick (field %.3f)  "
                 "wind rel L1 %.3f  lee %.2f m/s\n",
                 role, p.knobs.cells(0), p.knobs.cells(1), p.knobs.cells(2), p.knobs.update_every,
                 p.knobs.sample_every, p.cpu_ms_per_tick, p.field_ms_per_tick, p.wind_rel_l1,
                 p.lee_speed);
    std::fflush(progress);
}

} // namespace

std::uint32_t WindFieldKnobs::cells(int axis) const {
    const float base = axis == 1 ? 16.0f : 64.0f;
    return static_cast<std::uint32_t>(std::max(1l, std::lround(base * cell_scale)));
}

std::uint64_t WindFieldKnobs::total_cells() const {
    return static_cast<std::uint64_t>(cells(0)) * cells(1) * cells(2);
}

WindFieldStudy run_wind_field_study(const WindFieldStudyOptions& o, std::FILE* progress) {
    WindFieldStudy study;
    const Probes probes = make_probes();
    const Run ref = run_field(o, o.reference, probes, study.dt);
    study.reference = ref.point;
    say(progress, "ref", study.reference);
    const auto point = [&](const WindFieldKnobs& k) {
        for (std::size_t i = 0; i < study.points.size(); ++i) {
            if (study.points[i].knobs == k) {
                return i;
            }
        }
        const Run r = run_field(o, k, probes, study.dt);
        WindFieldPoint p = r.point;
        p.wind_rel_l1 = wind_rel_l1(r, ref, probes);
        p.lee_units_ratio = ref.point.lee_units > 0 ? static_cast<double>(p.lee_units) /
                                                          static_cast<double>(ref.point.lee_units)
                                                    : 0.0;
        say(progress, "", p);
        study.points.push_back(p);
        return study.points.size() - 1;
    };
    for (const float s : o.cell_scales) {
        study.cell_sweep.push_back(point({s, o.baseline.update_every, o.baseline.sample_every}));
    }
    for (const std::uint32_t every : o.update_everys) {
        study.update_sweep.push_back(
            point({o.baseline.cell_scale, every, o.baseline.sample_every}));
    }
    for (const std::uint32_t every : o.sample_everys) {
        study.sample_sweep.push_back(
            point({o.baseline.cell_scale, o.baseline.update_every, every}));
    }
    const WindFieldPoint& first = study.points[study.sample_sweep.front()];
    for (const std::size_t i : study.sample_sweep) {
        WindFieldPoint& p = study.points[i];
        p.depth_vs_first = compare_depth(p.depth, first.depth, 1.0f);
        p.lee_units_vs_first = first.lee_units > 0 ? static_cast<double>(p.lee_units) /
                                                         static_cast<double>(first.lee_units)
                                                   : 0.0;
    }
    return study;
}

} // namespace snow::accuracy
