#include "tests/scenes/roof_load.hpp"

#include "systems/core/units.hpp"

#include <cmath>
#include <numbers>

namespace snow {

namespace {

/// kg of snow a grid holds per m² of its plan area.
double load(const SnowGrid& g) {
    std::uint64_t units = 0;
    for (const std::uint32_t u : g.units) {
        units += u;
    }
    return static_cast<double>(units) * unit_kg / (g.nx * g.cell * g.nz * g.cell);
}

} // namespace

double roof_over_ground(double pitch_deg, const SurfaceDef& roof_settings, float cell) {
    SimConfig config;
    config.bounds = {{-4.0f, 0.0f, -2.0f}, {4.0f, 8.0f, 2.0f}};
    Simulation sim(config);
    SurfaceDef ground;
    ground.x0 = 1.0f;
    ground.z0 = -1.0f;
    ground.size_x = ground.size_z = 2.0f;
    ground.cell = cell;
    ground.spills = false;
    const SurfaceId g = sim.add_surface(ground);
    SurfaceDef roof = roof_settings;
    roof.x0 = -3.0f;
    roof.z0 = ground.z0;
    roof.size_x = ground.size_x;
    roof.size_z = ground.size_z;
    roof.cell = ground.cell;
    roof.base_y = 2.0f;
    roof.slope_x = static_cast<float>(std::tan(pitch_deg * std::numbers::pi / 180.0));
    roof.spills = true;
    roof.edge_limit = 10.0f;
    const SurfaceId r = sim.add_surface(roof);
    constexpr int steps = 100;
    const auto per_step = static_cast<std::uint32_t>(
        std::lround(design_ground_load * ground.cell * ground.cell / unit_kg / steps));
    const std::uint32_t cells = sim.surface(g).nx;
    double roof_sum = 0.0, ground_sum = 0.0;
    for (int step = 0; step < steps; ++step) {
        for (std::uint32_t ix = 0; ix < cells; ++ix) {
            for (std::uint32_t iz = 0; iz < cells; ++iz) {
                sim.add_settled_snow(g, ix, iz, per_step);
                sim.add_settled_snow(r, ix, iz, per_step);
            }
        }
        sim.run(3);
        roof_sum += load(sim.surface(r));
        ground_sum += load(sim.surface(g));
    }
    return roof_sum / ground_sum;
}

} // namespace snow
