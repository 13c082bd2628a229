#include "tests/scenes/fence_drift.hpp"

#include "systems/api/simulation_internals.hpp"
#include "systems/core/units.hpp"
#include "systems/wind/wind_field.hpp"
#include "tests/support/steady_field.hpp"

#include <cmath>

namespace snow {

namespace {

constexpr float fence_h = 1.0f;
constexpr float cell = 0.1f;             // snow cells (m)
constexpr float field_cell = 0.25f;      // field cells, every axis (m)
constexpr std::uint32_t field_every = 4; // ticks per field step

} // namespace

FenceDriftResult fence_drift(const FenceDrift& run) {
    SimConfig cfg;
    cfg.bounds = {{-16.0f * fence_h, 0.0f, -0.5f}, {24.0f * fence_h, 6.0f * fence_h, 0.5f}};
    Simulation sim(cfg);
    const glm::vec3 size = cfg.bounds.size();
    const auto across = [&](float extent) {
        return static_cast<std::uint32_t>(std::lround(extent / field_cell));
    };
    test::blow_steadily_through_field(
        sim, run.wind,
        {across(size.x), across(size.y), across(size.z), field_every, /*tunnel=*/true});
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
    // Units from x = a to b.
    const auto sum = [&](float a, float b) {
        std::int64_t n = 0;
        for (std::uint32_t ix = column(a); ix < column(b); ++ix) {
            for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
                n += s.snow[s.index(ix, iz)];
            }
        }
        return n;
    };
    const auto kg_per_m = [&](std::int64_t units) {
        return static_cast<double>(units) * unit_kg / static_cast<double>(ground.size_z);
    };
    const auto ticks = [&](double seconds) {
        return static_cast<int>(std::lround(seconds / static_cast<double>(cfg.dt)));
    };
    // The air settles round the fence before the snow is counted.
    sim.run(ticks(10.0));
    const std::int64_t fetch = sum(-15.0f, -6.0f), lee = sum(0.0f, 15.0f),
                       windward = sum(-5.0f, 0.0f);
    FenceDriftResult out;
    const WindField& f = world_of(sim).resource<WindField>();
    double lee_u = 0.0, free_u = 0.0;
    int lee_reads = 0, free_reads = 0;
    for (int t = 0; t < ticks(run.seconds); ++t) {
        sim.tick();
        out.balanced = out.balanced && sim.mass().balanced();
        if (t % field_every == 0) {
            for (float x = 2.0f; x <= 6.0f; x += field_cell, ++lee_reads) {
                lee_u += f.at(x, 0.5f * fence_h, 0.0f).x;
            }
            free_u += f.at(-10.0f * fence_h, 0.5f * fence_h, 0.0f).x;
            ++free_reads;
        }
    }
    out.lee_wind_over_free = (lee_u / lee_reads) / (free_u / free_reads);
    out.fetch_loss = kg_per_m(fetch - sum(-15.0f, -6.0f));
    out.lee_gain = kg_per_m(sum(0.0f, 15.0f) - lee);
    out.windward_gain = kg_per_m(sum(-5.0f, 0.0f) - windward);
    return out;
}

} // namespace snow
