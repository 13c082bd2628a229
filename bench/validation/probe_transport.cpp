// Blowing snow against Pomeroy & Gray's saltation law [PG90] at 8–15 m/s, and
// the flux's independence of the grid (issue #30 items 5 and 8): one flat
// strip of fresh snow in a steady wind (tests/scenes/drifting_snow.hpp).
#include "bench/validation/validation.hpp"

#include "tests/scenes/drifting_snow.hpp"

namespace snow::validation {

std::vector<Row> saltation_flux(const Plan& plan) {
    DriftingSnow base;
    if (plan.quick) {
        base.seconds = 0.5f;
    }
    const std::string strip = "10 m strip of 3 cm of fresh snow (-5 °C), steady wind through a "
                              "field of 0.25 × 0.5 × 0.25 m cells, 5 cm cells, mass across the "
                              "middle over " +
                              number("%.0f", base.seconds) + " s";
    std::vector<Row> rows;
    for (const float wind : {8.0f, 12.0f, 15.0f}) {
        DriftingSnow run = base;
        run.wind = wind;
        const DriftFlux f = drifting_snow(run);
        const double g = 1000.0 * f.published; // g/(m·s)
        rows.push_back({"saltation flux, wind " + number("%.0f", wind) + " m/s",
                        "0.68·ρ·u*t·(u*² − u*t²)/(g·u*) = " + number("%.2g", g) +
                            " g/(m·s) at u* = κ·U/ln(10 m/z0) = " + number("%.2f", f.u_star_10m) +
                            ", u*t = " + number("%.3f", f.u_star_t) + " m/s [PG90] [Lis07]",
                        strip, 1000.0 * f.flux, "g/(m·s)", 0.3 * g, 3.0 * g});
    }
    const DriftFlux at_12 = drifting_snow(base);
    rows.push_back({"density of the snow the wind lays down",
                    "wind-packed snow: 350–400 kg/m³ [CP10]",
                    "the 12 m/s strip above: what its downwind half gained", at_12.laid_density,
                    "kg/m³", 350.0, 400.0});
    const double reference = at_12.flux;
    const auto ratio_row = [&](const char* what, DriftingSnow run) {
        rows.push_back({"saltation flux, " + std::string(what) + " / as above",
                        "the same: a flux is a property of the wind and the snow",
                        "the 12 m/s strip above with " + std::string(what),
                        drifting_snow(run).flux / reference, "", 0.9, 1.1});
    };
    DriftingSnow run = base;
    run.cell = base.cell / 2.0f;
    ratio_row("2.5 cm snow cells", run);
    run = base;
    run.depth = 2.0f * base.depth;
    ratio_row("twice the depth", run);
    run = base;
    run.dt = base.dt / 2.0f;
    ratio_row("half the tick", run);
    run = base;
    run.field_cell = base.field_cell / 2.0f;
    ratio_row("field cells of half the side", run);
    return rows;
}

} // namespace snow::validation
