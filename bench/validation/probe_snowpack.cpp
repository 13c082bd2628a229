// Settled snow against measurements: the density of fresh snow by air
// temperature [HP98] and after days of settling [CP10], the flanks of a pile poured at one point
// [NSA] (natural slope angle of loose snow, 37–53° by grain type) and what a roof keeps by its
// pitch [EN1991] (the code's roof shape coefficient).
#include "bench/validation/validation.hpp"

#include "systems/core/units.hpp"
#include "tests/scenes/poured_pile.hpp"
#include "tests/scenes/roof_load.hpp"

#include <snow/snow.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace snow::validation {

namespace {

/// A simulation at `air_c` with one flat 10 cm cell of ground holding
/// `metres` of fresh snow.
struct OneCell {
    Simulation sim;
    SurfaceId surface;
    std::uint32_t units = 0;

    OneCell(double air_c, float dt, double metres) : sim(config(air_c, dt)) {
        SurfaceDef def;
        def.size_x = def.size_z = def.cell = 0.1f;
        def.spills = false; // ground: its edges keep their snow
        surface = sim.add_surface(def);
        units = static_cast<std::uint32_t>(std::llround(metres / sim.surface(surface).unit_height));
        sim.add_settled_snow(surface, 0, 0, units);
    }
    static SimConfig config(double air_c, float dt) {
        SimConfig c;
        c.air_temperature = static_cast<float>(air_c);
        c.dt = dt;
        return c;
    }
    /// The cell's density (kg/m³): its mass over the volume its depth gives.
    [[nodiscard]] double density() const {
        const SnowGrid g = sim.surface(surface);
        return units * unit_kg / (g.depth(0) * g.cell * g.cell);
    }
};

} // namespace

std::vector<Row> fresh_density_by_temperature(const Plan&) {
    std::vector<Row> rows;
    for (const double t : {-10.0, -5.0, -1.0}) {
        const double rho = 67.92 + 51.25 * std::exp(t / 2.59);
        rows.push_back({"fresh snow density, air " + number("%.0f", t) + " °C",
                        "67.92 + 51.25·e^(T/2.59) = " + number("%.0f", rho) + " kg/m³ [HP98]",
                        "10 cm of snow added to a flat surface",
                        OneCell(t, SimConfig{}.dt, 0.1).density(), "kg/m³", 0.75 * rho,
                        1.25 * rho});
    }
    return rows;
}

std::vector<Row> settled_density(const Plan&) {
    // One-second ticks: five days are 432 000 ticks of a single cell.
    constexpr double days = 5.0;
    OneCell pack(-5.0, 1.0f, 1.0);
    pack.sim.run(static_cast<std::uint64_t>(days * 86400.0));
    return {{"snow density after " + number("%.0f", days) + " days of settling",
             "settled snow: 200–300 kg/m³ [CP10]; Anderson's law [And76]",
             "1 m of fresh snow at -5 °C on a flat surface", pack.density(), "kg/m³", 200.0,
             350.0}};
}

std::vector<Row> pile_flank_angle(const Plan& plan) {
    std::vector<Row> rows;
    for (const double cell : {0.05, 0.1}) {
        for (const std::uint64_t units : {std::uint64_t{300000}, std::uint64_t{3000000}}) {
            rows.push_back({"pile flank, " + number("%.1f", units * unit_kg) + " kg poured, cell " +
                                number("%.0f", cell * 100.0) + " cm",
                            "loose dry snow: 37–53° [NSA]", "one point on a flat surface",
                            poured_pile_degrees(cell, plan.quick ? units / 10 : units,
                                                plan.quick ? 120 : 1200),
                            "°", 37.0, 53.0});
        }
    }
    return rows;
}

std::vector<Row> roof_load_by_pitch(const Plan&) {
    struct Pitch {
        double degrees, low, high;
        const char* code;
    };
    std::vector<Row> rows;
    for (const Pitch& p : {Pitch{15.0, 0.7, 1.0, "0.8"}, Pitch{30.0, 0.7, 1.0, "0.8"},
                           Pitch{40.0, 0.33, 0.73, "0.53"}, Pitch{45.0, 0.2, 0.6, "0.4"},
                           Pitch{60.0, 0.0, 0.1, "0"}}) {
        rows.push_back(
            {"roof / ground load, pitch " + number("%.0f", p.degrees) + "°",
             std::string("μ1 = ") + p.code + " [EN1991]",
             "plane roof, 10 cm cells, still-air snowfall to 1 kN/m² on the ground, loads "
             "averaged over it",
             roof_over_ground(p.degrees), "", p.low, p.high});
    }
    // Convergence (issue #30 item 8): the roofs that keep part of their snow,
    // on cells of half the side.
    for (const double degrees : {45.0, 60.0}) {
        rows.push_back(
            {"roof / ground load, pitch " + number("%.0f", degrees) + "°, 5 cm cells / 10 cm",
             "the same: what a roof keeps is its pitch's, not its grid's",
             "the roof above on cells of half the side",
             roof_over_ground(degrees, {}, 0.05f) / roof_over_ground(degrees), "", 0.9, 1.1});
    }
    return rows;
}

} // namespace snow::validation
