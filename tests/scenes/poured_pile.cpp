// A pile poured at one point (tests/scenes/poured_pile.hpp).
#include "tests/scenes/poured_pile.hpp"

#include "systems/core/units.hpp"

#include <array>
#include <cmath>
#include <numbers>

namespace snow {

namespace {

/// Where the profile from cell (ix, iz) in direction (dx, dz) first falls to
/// `level` (m of depth), in metres from the cell's centre (linear between cells).
double crossing(const SnowGrid& g, std::uint32_t ix, std::uint32_t iz, int dx, int dz,
                double level) {
    double previous = g.depth(g.index(ix, iz));
    for (int k = 1;; ++k) {
        const int x = static_cast<int>(ix) + k * dx, z = static_cast<int>(iz) + k * dz;
        if (x < 0 || z < 0 || x >= static_cast<int>(g.nx) || z >= static_cast<int>(g.nz)) {
            return k * g.cell; // the pile reaches the grid's edge
        }
        const double d =
            g.depth(g.index(static_cast<std::uint32_t>(x), static_cast<std::uint32_t>(z)));
        if (d <= level) {
            return (k - 1 + (previous - level) / (previous - d)) * g.cell;
        }
        previous = d;
    }
}

} // namespace

double flank_degrees(const SnowGrid& g) {
    std::size_t top = 0;
    for (std::size_t i = 1; i < g.cell_count(); ++i) {
        top = g.units[i] > g.units[top] ? i : top;
    }
    const auto ix = static_cast<std::uint32_t>(top % g.nx);
    const auto iz = static_cast<std::uint32_t>(top / g.nx);
    const double h = g.depth(top);
    double sum = 0.0;
    for (const auto& [dx, dz] :
         std::array<std::array<int, 2>, 4>{{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}}) {
        const double run =
            crossing(g, ix, iz, dx, dz, 0.2 * h) - crossing(g, ix, iz, dx, dz, 0.8 * h);
        sum += std::atan2(0.6 * h, run);
    }
    return sum / 4.0 * 180.0 / std::numbers::pi;
}

double poured_pile_degrees(double cell, std::uint64_t units, std::uint64_t rest_ticks,
                           float repose_deg) {
    SimConfig config;
    config.seed = 31;
    config.bounds = {{-2.0f, -1.0f, -2.0f}, {2.0f, 4.0f, 2.0f}};
    config.max_flakes = 1000;
    Simulation sim(config);
    SurfaceDef def;
    def.x0 = def.z0 = -1.5f;
    def.size_x = def.size_z = 3.0f;
    def.cell = static_cast<float>(cell);
    def.spills = false;
    def.repose_deg = repose_deg;
    const SurfaceId surface = sim.add_surface(def);
    const SnowGrid first = sim.surface(surface);
    const std::size_t centre = first.index(first.nx / 2, first.nz / 2);
    const float x = first.x0 + (first.nx / 2 + 0.5f) * first.cell;
    const float z = first.z0 + (first.nz / 2 + 0.5f) * first.cell;
    for (std::uint64_t poured = 0; poured < units;) {
        const float top = static_cast<float>(sim.surface(surface).depth(centre));
        for (int k = 0; k < 10 && poured < units; ++k, poured += max_flake_units) {
            (void)sim.place_flake(
                {{x, top + 0.01f, z}, {0.0f, -1.0f, 0.0f}, 9.81f, 0.01f, max_flake_units});
        }
        sim.tick();
    }
    sim.run(rest_ticks);
    return flank_degrees(sim.surface(surface));
}

} // namespace snow
