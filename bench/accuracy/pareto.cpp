#include "bench/accuracy/pareto.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace snow::accuracy {

namespace {

/// The integrator for a preset at dt; see pick_presets.
const TrajectoryRow& pick_integrator(const std::vector<TrajectoryRow>& rows, float dt,
                                     double max_drift) {
    const TrajectoryRow* best = nullptr; // most accurate overall
    double cheapest = 1.0e300;           // ns of the cheapest within the drift
    for (const TrajectoryRow& r : rows) {
        if (r.dt != dt) {
            continue;
        }
        if (best == nullptr || r.max_pos_error < best->max_pos_error) {
            best = &r;
        }
        if (r.max_pos_error <= max_drift) {
            cheapest = std::min(cheapest, r.ns_per_flake_tick);
        }
    }
    if (best == nullptr) {
        throw std::invalid_argument("pick_presets: no trajectory rows at a preset's dt");
    }
    const TrajectoryRow* pick = nullptr;
    for (const TrajectoryRow& r : rows) {
        if (r.dt == dt && r.max_pos_error <= max_drift &&
            r.ns_per_flake_tick <= cheapest * preset_cost_tie &&
            (pick == nullptr || r.max_pos_error < pick->max_pos_error)) {
            pick = &r;
        }
    }
    return pick != nullptr ? *pick : *best;
}

/// The front point for a preset allowed `max_error`; see pick_presets.
std::size_t pick_setting(const SceneStudy& study, const std::vector<std::size_t>& front,
                         double max_error) {
    double cheapest = -1.0;
    std::size_t pick = front.back(); // the most accurate, if none is good enough
    // The front runs from cheap and inaccurate to dear and accurate: the last
    // point within the error and the cost band is the most accurate of them.
    for (const std::size_t i : front) {
        const ScenePoint& p = study.points[i];
        if (p.error.rel_l1 > max_error) {
            continue;
        }
        if (cheapest < 0.0) {
            cheapest = p.cpu_ms_per_second();
        }
        if (p.cpu_ms_per_second() > cheapest * preset_cost_tie) {
            break;
        }
        pick = i;
    }
    return pick;
}

} // namespace

std::vector<std::size_t> pareto_front(const SceneStudy& study,
                                      const std::vector<std::size_t>& candidates) {
    std::vector<std::size_t> order = candidates;
    std::sort(order.begin(), order.end());
    order.erase(std::unique(order.begin(), order.end()), order.end());
    const auto cost = [&](std::size_t i) { return study.points[i].cpu_ms_per_second(); };
    const auto err = [&](std::size_t i) { return study.points[i].error.rel_l1; };
    // Cheapest first (ties: more accurate first, then index): a point is on
    // the front iff it is more accurate than every cheaper one.
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return cost(a) != cost(b) ? cost(a) < cost(b) : err(a) < err(b);
    });
    std::vector<std::size_t> front;
    for (const std::size_t i : order) {
        if (front.empty() || err(i) < err(front.back())) {
            front.push_back(i);
        }
    }
    return front;
}

std::vector<PresetPick> pick_presets(const SceneStudy& study,
                                     const std::vector<TrajectoryRow>& trajectory) {
    const double floor = study.floor_rel_l1();
    std::vector<PresetPick> picks;
    for (const PresetRule& rule : preset_rules) {
        std::vector<std::size_t> allowed;
        for (std::size_t i = 0; i < study.points.size(); ++i) {
            const SceneKnobs& k = study.points[i].knobs;
            if (k.dt <= rule.max_dt && k.cell_scale >= rule.min_cell_scale) {
                allowed.push_back(i);
            }
        }
        if (allowed.empty()) {
            throw std::invalid_argument("pick_presets: no studied setting fits preset " +
                                        std::string(rule.name));
        }
        PresetPick p{rule, rule.tolerance * floor,     pareto_front(study, allowed),
                     0,    Integrator::explicit_euler, 0.0,
                     0.0};
        p.point = pick_setting(study, p.front, p.max_error);
        const SceneKnobs& k = study.points[p.point].knobs;
        p.max_drift = 0.5 * study.base_cell * k.cell_scale;
        const TrajectoryRow& t = pick_integrator(trajectory, k.dt, p.max_drift);
        p.integrator = t.integrator;
        p.drift = t.max_pos_error;
        picks.push_back(std::move(p));
    }
    return picks;
}

} // namespace snow::accuracy
