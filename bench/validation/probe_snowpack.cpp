// Settled snow against measurements: the density of fresh snow by air
// temperature [HP98], the flanks of a pile poured at one point [NSA]
// (natural slope angle of loose snow, 37–53° by grain type) and what a roof
// keeps by its pitch [EN1991] (the code's roof shape coefficient).
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

std::vector<Row> fresh_snow_density(const Plan&) {
    SimConfig config;
    Simulation sim(config);
    SurfaceDef def;
    def.size_x = def.size_z = 0.1f;
    def.cell = 0.1f;
    const SurfaceId surface = sim.add_surface(def);
    const std::uint32_t units = 10000;
    sim.add_settled_snow(surface, 0, 0, units);
    const SnowGrid g = sim.surface(surface);
    const double density = units * unit_kg / (g.depth(0) * g.cell * g.cell);
    std::vector<Row> rows;
    for (const double t : {-10.0, -5.0, -1.0}) {
        const double rho = 67.92 + 51.25 * std::exp(t / 2.59);
        rows.push_back({"fresh snow density, air " + number("%.0f", t) + " °C",
                        "67.92 + 51.25·e^(T/2.59) = " + number("%.0f", rho) + " kg/m³ [HP98]",
                        "snow added to a flat surface", density, "kg/m³", 0.75 * rho, 1.25 * rho});
    }
    return rows;
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
        rows.push_back({"roof / ground load, pitch " + number("%.0f", p.degrees) + "°",
                        std::string("μ1 = ") + p.code + " [EN1991]",
                        "plane roof, still-air snowfall to 1 kN/m² on the ground, loads averaged over it",
                        roof_over_ground(p.degrees), "", p.low, p.high});
    }
    return rows;
}

} // namespace snow::validation
