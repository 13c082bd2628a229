// The drifts a 50% porous fence grows, against Tabler's equilibrium drifts
// behind Wyoming fences [Tab80] (issue #30 item 7): a 1 m fence in a slice of
// a long one, an endless fetch upwind, a steady 10 m/s, the drifting fast-
// forwarded (tests/scenes/fence_drift.hpp).
#include "bench/validation/validation.hpp"

#include "tests/scenes/fence_drift.hpp"

namespace snow::validation {

std::vector<Row> fence_drift_shape(const Plan& plan) {
    FenceDrift run = towards_equilibrium(plan.quick ? 2.0f : 720.0f);
    run.shape_at = {run.seconds};
    const DriftShape d = fence_drift(run).shapes.at(0);
    const std::string scene =
        "1 m fence (50%) across a 1 m tunnel of 0.25 m field cells, 10 cm snow cells, endless "
        "70 m fetch, 10 m/s, " +
        number("%.0f", run.seconds * run.fast_forward / 3600.0) + " h of drifting (fast_forward " +
        number("%.0f", run.fast_forward) + "); drift: snow ≥ H/50 above the start";
    // Tabler's fences were 0.8–3.8 m; the band is ±20% of his regression.
    const auto row = [&](const char* what, double published, double ours) {
        return Row{what,
                   number("%.1f", published) + " H at equilibrium, Wyoming fences [Tab80]",
                   scene,
                   ours,
                   "H",
                   0.8 * published,
                   1.2 * published};
    };
    return {row("lee drift length behind a 50% fence", 30.0, d.lee_length),
            row("lee drift depth behind a 50% fence", 1.2, d.lee_depth),
            row("windward drift length before a 50% fence", 12.0, d.windward_length),
            row("windward drift depth before a 50% fence", 0.5, d.windward_depth)};
}

} // namespace snow::validation
