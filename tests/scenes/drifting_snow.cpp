#include "tests/scenes/drifting_snow.hpp"

#include "systems/api/simulation_internals.hpp"
#include "systems/core/units.hpp"
#include "systems/wind/saltation.hpp"
#include "tests/support/even_snow.hpp"
#include "tests/support/steady_field.hpp"

#include <cmath>

namespace snow {

DriftFlux drifting_snow(const DriftingSnow& run) {
    SimConfig cfg;
    cfg.bounds = {{-6.0f, 0.0f, -2.0f}, {6.0f, 2.0f, 2.0f}};
    cfg.dt = run.dt;
    Simulation sim(cfg);
    const auto across = [&](float extent) {
        return static_cast<std::uint32_t>(std::lround(extent / run.field_cell));
    };
    test::blow_steadily_through_field(sim, run.wind, {across(12.0f), 4, across(4.0f), 4});
    WindTransportDef transport;
    transport.adjustment_length = run.adjustment_length;
    sim.set_wind_transport(transport);
    SurfaceDef strip;
    strip.x0 = -5.0f;
    strip.z0 = -0.5f;
    strip.size_x = 10.0f;
    strip.size_z = 1.0f;
    strip.cell = run.cell;
    strip.spills = false;
    strip.edge_limit = 10.0f; // only the wind moves snow here
    const SurfaceId id = sim.add_surface(strip, {});
    const SnowSurface& s = snow_surface(sim, id);
    test::snow_every_cell(sim, id,
                          static_cast<std::uint32_t>(std::lround(run.depth / s.unit_height)));
    // Units and levels of the upwind (x < 0) or the downwind half.
    const auto half = [&](bool upwind, bool levels) {
        std::int64_t sum = 0;
        for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
            for (std::uint32_t ix = upwind ? 0 : s.nx / 2; ix < (upwind ? s.nx / 2 : s.nx); ++ix) {
                const std::size_t i = s.index(ix, iz);
                sum += levels ? s.depth_levels(i) : std::int64_t{s.snow[i]};
            }
        }
        return sum;
    };
    DriftFlux out;
    const std::int64_t before = half(true, false);
    const std::int64_t lee_units = half(false, false), lee_levels = half(false, true);
    const auto ticks = static_cast<int>(std::lround(run.seconds / run.dt));
    for (int t = 0; t < ticks; ++t) {
        sim.tick();
        out.balanced = out.balanced && sim.mass().balanced();
    }
    const double lost_kg = static_cast<double>(before - half(true, false)) * unit_kg;
    const double fresh = fresh_snow_density(cfg);
    out.laid_density = fresh * static_cast<double>(half(false, false) - lee_units) /
                       static_cast<double>(half(false, true) - lee_levels);
    out.flux = lost_kg / (static_cast<double>(ticks) * run.dt * strip.size_z);
    out.u_star_10m = run.wind * friction_per_wind(10.0, transport.roughness);
    out.u_star_t = threshold_friction_velocity(fresh);
    out.published = saltation_flux(out.u_star_10m, out.u_star_t, air_density(cfg.air_temperature),
                                   std::abs(cfg.gravity.y));
    return out;
}

} // namespace snow
