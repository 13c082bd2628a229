// Flakes against Locatelli & Hobbs 1974 [LH74]: aggregates of unrimed
// dendrites fall at v = 0.8·D^0.16 m/s and weigh m = 0.073·D^1.4 mg, D the
// largest dimension in mm (measured over 2–10 mm). A simulated flake is a
// parcel of real flakes of one size; a real flake weighs the parcel's mass
// over its multiplicity.
#include "bench/validation/validation.hpp"

#include "systems/core/units.hpp"
#include "systems/flakes/snowfall.hpp"

#include <snow/snow.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace snow::validation {

namespace {

/// kg/m²/h: several times a heavy snowfall.
constexpr float fast_snowfall = 20.0f;

struct Flake {
    double d_mm;    ///< diameter
    double speed;   ///< downward speed (m/s)
    double mass_mg; ///< what one real flake of the parcel weighs
};

/// The flakes in the air after a still-air snowfall from a default emitter
/// (what a scene gets when it declares no sizes) whose snowfall is fast
/// forwarded, so that parcels weigh many mass units and whole units round
/// little away.
std::vector<Flake> falling_flakes(const Plan& plan, float dt = SimConfig{}.dt) {
    SimConfig config;
    config.seed = 30;
    config.dt = dt;
    config.bounds = {{-5.0f, 0.0f, -5.0f}, {5.0f, 30.0f, 5.0f}};
    config.max_flakes = 60000;
    Simulation sim(config);
    Emitter emitter;
    emitter.rate = plan.quick ? 1000.0f : 4000.0f;
    emitter.snowfall_kg_m2_h = fast_snowfall;
    sim.add_emitter(emitter);
    sim.run(static_cast<std::uint64_t>(std::lround((plan.quick ? 2.0f : 10.0f) / dt)));
    const glm::vec3 floor = config.bounds.size();
    const double multiplicity = parcel_multiplicity(emitter, double{floor.x} * floor.z);
    const FlakesView f = sim.flakes();
    std::vector<Flake> out;
    for (std::size_t i = 0; i < f.slots(); ++i) {
        if (f.is_alive(i)) {
            out.push_back(
                {f.size[i] * 1000.0, -f.vy[i], f.mass_units[i] * unit_kg * 1.0e6 / multiplicity});
        }
    }
    return out;
}

/// Sizes the rows look at (mm); a bin is D/1.25 .. D·1.25.
constexpr double sizes_mm[] = {2.0, 5.0, 10.0};

/// Median of `value` among the flakes of size d_mm (±25 %), NaN when there is none.
double median_in_bin(const std::vector<Flake>& flakes, double d_mm, double Flake::*value) {
    std::vector<double> v;
    for (const Flake& f : flakes) {
        if (f.d_mm >= d_mm / 1.25 && f.d_mm < d_mm * 1.25) {
            v.push_back(f.*value);
        }
    }
    if (v.empty()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
}

/// A power law of [LH74], coefficient·D^exponent in `unit`.
struct PowerLaw {
    const char* quantity;
    double coefficient, exponent;
    const char* unit;
    double low, high; ///< the band, as factors of the law's value
};

/// One row per size of sizes_mm: the median of `value` there against the law.
std::vector<Row> law_rows(const std::vector<Flake>& flakes, const PowerLaw& law,
                          double Flake::*value) {
    std::vector<Row> rows;
    for (const double d : sizes_mm) {
        const double expected = law.coefficient * std::pow(d, law.exponent);
        rows.push_back({std::string(law.quantity) + ", D = " + number("%.0f", d) + " mm (median)",
                        number("%g", law.coefficient) + "·D^" + number("%g", law.exponent) + " = " +
                            number("%.2f", expected) + " " + law.unit + " [LH74]",
                        "still air, default emitter, 20 kg/m²/h", median_in_bin(flakes, d, value),
                        law.unit, law.low * expected, law.high * expected});
    }
    return rows;
}

} // namespace

// One snowfall gives both the speed and the mass rows.
std::vector<Row> flakes_by_size(const Plan& plan) {
    const std::vector<Flake> flakes = falling_flakes(plan);
    std::vector<Row> rows =
        law_rows(flakes, {"fall speed", 0.8, 0.16, "m/s", 0.8, 1.2}, &Flake::speed);
    // The size dependence alone: big flakes fall faster than small ones.
    const double ratio = std::pow(5.0, 0.16);
    rows.push_back(
        {"fall speed, D = 10 mm over D = 2 mm", "5^0.16 = " + number("%.2f", ratio) + " [LH74]",
         "still air, default emitter, 20 kg/m²/h",
         median_in_bin(flakes, 10.0, &Flake::speed) / median_in_bin(flakes, 2.0, &Flake::speed), "",
         1.0 + 0.5 * (ratio - 1.0), 1.0 + 1.5 * (ratio - 1.0)});
    for (Row& r : law_rows(flakes, {"flake mass", 0.073, 1.4, "mg", 0.5, 2.0}, &Flake::mass_mg)) {
        rows.push_back(std::move(r));
    }
    // Convergence (issue #30 item 8): the same snowfall at half the tick.
    const std::vector<Flake> finer = falling_flakes(plan, SimConfig{}.dt / 2.0f);
    rows.push_back(
        {"fall speed, D = 5 mm, half the tick / as above",
         "the same: the terminal speed is the drag law's", "the snowfall above at 1/120 s",
         median_in_bin(finer, 5.0, &Flake::speed) / median_in_bin(flakes, 5.0, &Flake::speed), "",
         0.9, 1.1});
    return rows;
}

} // namespace snow::validation
