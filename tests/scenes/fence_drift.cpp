#include "tests/scenes/fence_drift.hpp"

#include "systems/api/simulation_internals.hpp"
#include "systems/core/units.hpp"
#include "systems/wind/wind_field.hpp"
#include "tests/support/steady_field.hpp"

#include <cmath>

namespace snow {

namespace {

constexpr float fence_h = 1.0f;
constexpr float cell = 0.1f;        // snow cells (m)
constexpr float field_cell = 0.25f; // field cells, every axis (m)

} // namespace

FenceDriftResult fence_drift(const FenceDrift& run) {
    SimConfig cfg;
    cfg.bounds = {{-16.0f * fence_h, 0.0f, -0.5f}, {24.0f * fence_h, 6.0f * fence_h, 0.5f}};
    Simulation sim(cfg);
    const glm::vec3 size = cfg.bounds.size();
    const auto across = [&](float extent) {
        return static_cast<std::uint32_t>(std::lround(extent / field_cell));
    };
    test::blow_steadily_through_field(sim, run.wind,
                                      {across(size.x), across(size.y), across(size.z), 4});
    sim.set_wind_transport(WindTransportDef{});
    SurfaceDef ground;
    ground.x0 = cfg.bounds.min.x;
    ground.z0 = cfg.bounds.min.z;
    ground.size_x = size.x;
    ground.size_z = size.z;
    ground.cell = cell;
    ground.spills = false;
    ground.edge_limit = 10.0f; // only the wind moves snow here
    const SurfaceId id = sim.add_surface(ground, {});
    if (run.porosity < 1.0f) {
        sim.add_box({{0.0f, 0.0f, cfg.bounds.min.z}, {field_cell, fence_h, cfg.bounds.max.z}},
                    run.porosity);
    }
    const SnowSurface& s = snow_surface(sim, id);
    const auto column = [&](float x) {
        return static_cast<std::uint32_t>(std::floor((x - ground.x0) / cell));
    };
    const auto fresh_units = static_cast<std::uint32_t>(std::lround(0.1 / s.unit_height));
    for (std::uint32_t ix = column(-15.0f * fence_h); ix < column(-6.0f * fence_h); ++ix) {
        for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
            sim.add_settled_snow(id, ix, iz, fresh_units);
        }
    }
    // Units and levels from x = a to b.
    const auto sum = [&](float a, float b, bool levels) {
        std::int64_t n = 0;
        for (std::uint32_t ix = column(a); ix < column(b); ++ix) {
            for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
                const std::size_t i = s.index(ix, iz);
                n += levels ? s.depth_levels(i) : std::int64_t{s.snow[i]};
            }
        }
        return n;
    };
    const auto kg_per_m = [&](std::int64_t units) {
        return static_cast<double>(units) * unit_kg / static_cast<double>(ground.size_z);
    };
    const int every = 4;
    const auto ticks = [&](double seconds) {
        return static_cast<int>(std::lround(seconds / static_cast<double>(cfg.dt)));
    };
    // The air settles round the fence before the snow is counted.
    sim.run(ticks(10.0));
    const std::int64_t fetch = sum(-15.0f, -6.0f, false), lee = sum(0.0f, 15.0f, false),
                       windward = sum(-5.0f, 0.0f, false);
    std::vector<std::int64_t> before;
    for (float x = -5.0f; x < 15.0f; x += 0.5f) {
        before.push_back(sum(x, x + 0.5f, true));
    }
    FenceDriftResult out;
    const WindField& f = world_of(sim).resource<WindField>();
    double lee_u = 0.0, free_u = 0.0;
    int samples = 0;
    for (int t = 0; t < ticks(run.seconds); ++t) {
        sim.tick();
        out.balanced = out.balanced && sim.mass().balanced();
        if (t % every == 0) {
            for (float x = 2.0f; x <= 6.0f; x += field_cell) {
                lee_u += f.at(x, 0.5f * fence_h, 0.0f).x;
            }
            free_u += f.at(-10.0f * fence_h, 0.5f * fence_h, 0.0f).x;
            ++samples;
        }
    }
    const double lee_points = std::floor(4.0 / field_cell) + 1.0;
    out.lee_wind_over_free = lee_u / lee_points / free_u;
    out.fetch_loss = kg_per_m(fetch - sum(-15.0f, -6.0f, false));
    out.lee_gain = kg_per_m(sum(0.0f, 15.0f, false) - lee);
    out.windward_gain = kg_per_m(sum(-5.0f, 0.0f, false) - windward);
    std::size_t bin = 0;
    for (float x = -5.0f; x < 15.0f; x += 0.5f, ++bin) {
        const double levels = static_cast<double>(sum(x, x + 0.5f, true) - before[bin]);
        out.profile.push_back(levels * s.unit_height / (0.5 / cell * s.nz));
    }
    (void)samples;
    return out;
}

} // namespace snow
