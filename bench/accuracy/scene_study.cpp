// The scene study's plan: reference ensemble, noise floor, one-knob sweeps
// around the scene's settings and a grid for the Pareto front. Every setting
// runs with the same seeds; runs with the same dt and seed draw the same
// flakes (keys are (seed, tick, slot)), which the paired error relies on.
#include "bench/accuracy/scene_study.hpp"

#include "systems/core/units.hpp"

#include <algorithm>
#include <utility>

namespace snow::accuracy {

namespace {

void add_scaled(DepthError& sum, const DepthError& e, double w) {
    sum.l1 += w * e.l1;
    sum.linf += w * e.linf;
    sum.rel_l1 += w * e.rel_l1;
    sum.centroid_shift += w * e.centroid_shift;
    sum.volume_ratio += w * e.volume_ratio;
}

double share(std::uint64_t units, const MassReport& m) {
    return m.spawned > 0 ? static_cast<double>(units) / static_cast<double>(m.spawned) : 0.0;
}

class Runner {
  public:
    Runner(const SceneStudyOptions& o, const DepthField& ref, std::FILE* progress)
        : o_(o), ref_(ref), progress_(progress) {}

    /// Index of the point with these knobs, evaluating it the first time.
    std::size_t point(const SceneKnobs& k) {
        for (std::size_t i = 0; i < points_.size(); ++i) {
            if (points_[i].knobs == k) {
                return i;
            }
        }
        points_.push_back(evaluate(k, o_.seeds));
        return points_.size() - 1;
    }

    /// Runs `k` once per seed: errors are the means over the seeds, the cost
    /// is the fastest seed's.
    ScenePoint evaluate(const SceneKnobs& k, const std::vector<std::uint64_t>& seeds) {
        ScenePoint p;
        p.knobs = k;
        const double w = 1.0 / static_cast<double>(seeds.size());
        p.cpu_ms_per_tick = 1.0e30;
        for (const std::uint64_t seed : seeds) {
            const SceneRun r = run_scene(o_.scene, k, seed, o_.seconds, o_.steady_wind);
            const DepthError e = compare_depth(r.field, ref_, o_.block);
            say(r, &e);
            p.ticks = r.ticks;
            p.cpu_ms_per_tick = std::min(p.cpu_ms_per_tick, r.cpu_ms_per_tick);
            p.smoothing_per_tick +=
                w * static_cast<double>(r.counters.smoothing_iterations) / r.ticks;
            p.settled_share += w * share(r.mass.settled, r.mass);
            p.airborne_share += w * share(r.mass.airborne, r.mass);
            p.bounds_share += w * share(r.ledger.removed_bounds, r.mass);
            p.sphere_share += w * share(r.ledger.removed_sphere, r.mass);
            p.bare_share += w * share(r.ledger.removed_bare, r.mass);
            add_scaled(p.error, e, w);
            add_scaled(p.fine_error, compare_depth(r.field, ref_, o_.fine_block), w);
            add_scaled(p.cell_error, compare_depth(r.field, ref_, 0.0f), w);
            const bool is_pair = k == paired_knobs(k.dt);
            const DepthField& pair = paired_field(k.dt, seed, is_pair ? &r.field : nullptr);
            add_scaled(p.paired, compare_depth(r.field, pair, o_.block), w);
            p.rel_l1_by_seed.push_back(e.rel_l1);
        }
        return p;
    }

    std::vector<ScenePoint> take() { return std::move(points_); }

  private:
    /// The knobs a run at dt is paired with: the reference's, at that dt.
    SceneKnobs paired_knobs(float dt) const {
        SceneKnobs k = o_.reference;
        k.dt = dt;
        return k;
    }

    /// Field of the paired run at (dt, seed): cached; `self` is that run's
    /// field when the caller is the paired run itself.
    const DepthField& paired_field(float dt, std::uint64_t seed, const DepthField* self) {
        for (const auto& [key, field] : paired_) {
            if (key.first == dt && key.second == seed) {
                return field;
            }
        }
        if (self != nullptr) {
            paired_.emplace_back(std::make_pair(dt, seed), *self);
        } else {
            SceneRun r = run_scene(o_.scene, paired_knobs(dt), seed, o_.seconds, o_.steady_wind);
            say(r, nullptr);
            paired_.emplace_back(std::make_pair(dt, seed), std::move(r.field));
        }
        return paired_.back().second;
    }

    void say(const SceneRun& r, const DepthError* e) const {
        if (progress_ == nullptr) {
            return;
        }
        std::fprintf(progress_, "  %-8s %-46s seed %3llu %7.3f ms/tick", e ? "" : "paired",
                     knob_label(r.knobs).c_str(), static_cast<unsigned long long>(r.seed),
                     r.cpu_ms_per_tick);
        if (e != nullptr) {
            std::fprintf(progress_, "  rel L1 %.3f", e->rel_l1);
        }
        std::fputc('\n', progress_);
        std::fflush(progress_);
    }

    const SceneStudyOptions& o_;
    const DepthField& ref_;
    std::FILE* progress_;
    std::vector<ScenePoint> points_;
    std::vector<std::pair<std::pair<float, std::uint64_t>, DepthField>> paired_;
};

/// Reference ensemble: mean field of the reference runs; fills the study's reference figures.
DepthField reference_field(const SceneStudyOptions& o, SceneStudy& study, std::FILE* progress) {
    std::vector<DepthField> fields;
    const double w = 1.0 / static_cast<double>(o.reference_seeds.size());
    for (const std::uint64_t seed : o.reference_seeds) {
        SceneRun r = run_scene(o.scene, o.reference, seed, o.seconds, o.steady_wind);
        if (progress != nullptr) {
            std::fprintf(progress, "  %-8s %-46s seed %3llu %7.3f ms/tick\n", "ref",
                         knob_label(r.knobs).c_str(), static_cast<unsigned long long>(seed),
                         r.cpu_ms_per_tick);
        }
        study.reference_ms_per_tick += w * r.cpu_ms_per_tick;
        study.reference_settled_kg += w * static_cast<double>(r.mass.settled) * unit_kg;
        double finest = 1.0e30;
        for (const SurfaceDepth& s : r.field.surfaces) {
            finest = std::min(finest, static_cast<double>(s.cell));
        }
        study.base_cell = finest / o.reference.cell_scale;
        fields.push_back(std::move(r.field));
    }
    return mean_field(fields);
}

/// Settled share of spawned mass at the end of a run.
double settled_share(const SceneRun& r) {
    return share(r.mass.settled, r.mass);
}

/// Noise floor at the baseline knobs with or without the walk; see WindCheck.
void wind_floor(const SceneStudyOptions& o, bool steady, double& rel_l1, double& settled_min,
                double& settled_max, std::FILE* progress) {
    settled_min = 1.0;
    settled_max = 0.0;
    const auto run = [&](std::uint64_t seed) {
        SceneRun r = run_scene(o.scene, o.baseline, seed, o.seconds, steady);
        settled_min = std::min(settled_min, settled_share(r));
        settled_max = std::max(settled_max, settled_share(r));
        if (progress != nullptr) {
            std::fprintf(progress, "  %-8s %-46s seed %3llu %7.3f ms/tick\n",
                         steady ? "steady" : "walk", knob_label(r.knobs).c_str(),
                         static_cast<unsigned long long>(seed), r.cpu_ms_per_tick);
        }
        return r;
    };
    std::vector<DepthField> refs;
    for (const std::uint64_t seed : o.reference_seeds) {
        refs.push_back(run(seed).field);
    }
    const DepthField ref = mean_field(refs);
    rel_l1 = 0.0;
    for (const std::uint64_t seed : o.floor_seeds) {
        rel_l1 += compare_depth(run(seed).field, ref, o.block).rel_l1 / o.floor_seeds.size();
    }
}

} // namespace

double SceneStudy::floor_rel_l1() const {
    double sum = 0.0;
    for (const ScenePoint& p : floor) {
        sum += p.error.rel_l1;
    }
    return floor.empty() ? 0.0 : sum / static_cast<double>(floor.size());
}

double SceneStudy::floor_rel_l1_min() const {
    double v = floor.empty() ? 0.0 : floor.front().error.rel_l1;
    for (const ScenePoint& p : floor) {
        v = std::min(v, p.error.rel_l1);
    }
    return v;
}

double SceneStudy::floor_rel_l1_max() const {
    double v = 0.0;
    for (const ScenePoint& p : floor) {
        v = std::max(v, p.error.rel_l1);
    }
    return v;
}

SceneStudy run_scene_study(const SceneStudyOptions& o, std::FILE* progress) {
    SceneStudy study;
    const DepthField ref = reference_field(o, study, progress);
    Runner runner(o, ref, progress);
    for (const std::uint64_t seed : o.floor_seeds) {
        study.floor.push_back(runner.evaluate(o.reference, {seed}));
    }
    for (const float dt : o.dts) {
        SceneKnobs k = o.baseline;
        k.dt = dt;
        study.dt_sweep.push_back(runner.point(k));
    }
    for (const float dt : o.integrator_dts) {
        SceneKnobs k = o.baseline;
        k.dt = dt;
        for (const Integrator i : o.integrators) {
            k.integrator = i;
            study.integrator_sweep.push_back(runner.point(k));
        }
    }
    for (const float c : o.cell_scales) {
        SceneKnobs k = o.baseline;
        k.cell_scale = c;
        study.cell_sweep.push_back(runner.point(k));
    }
    for (const std::uint32_t s : o.smoothings) {
        SceneKnobs k = o.baseline;
        k.smoothing = s;
        study.smoothing_sweep.push_back(runner.point(k));
    }
    for (const std::uint32_t r : o.occlusions) {
        SceneKnobs k = o.baseline;
        k.occlusion = r;
        study.occlusion_sweep.push_back(runner.point(k));
    }
    for (const float dt : o.grid_dts) {
        for (const float c : o.grid_cell_scales) {
            for (const std::uint32_t r : o.grid_occlusions) {
                SceneKnobs k = o.baseline;
                k.dt = dt;
                k.cell_scale = c;
                k.occlusion = r;
                study.grid.push_back(runner.point(k));
            }
        }
    }
    study.points = runner.take();
    WindCheck& w = study.wind;
    wind_floor(o, true, w.rel_l1_steady, w.settled_min_steady, w.settled_max_steady, progress);
    wind_floor(o, false, w.rel_l1_walk, w.settled_min_walk, w.settled_max_walk, progress);
    return study;
}

} // namespace snow::accuracy
