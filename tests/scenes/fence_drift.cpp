#include "tests/scenes/fence_drift.hpp"

#include "systems/api/simulation_internals.hpp"
#include "systems/core/units.hpp"
#include "systems/wind/wind_field.hpp"
#include "tests/support/steady_field.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace snow {

namespace {

constexpr float fence_h = 1.0f;
constexpr float cell = 0.1f;             // snow cells (m)
constexpr float field_cell = 0.25f;      // field cells, every axis (m)
constexpr std::uint32_t field_every = 4; // ticks per field step

} // namespace

FenceDrift towards_equilibrium(float seconds) {
    FenceDrift run;
    run.wind = 10.0f;
    run.upwind = 100.0f;
    run.fetch = 70.0f; // the flux saturates along it [Kob72]
    run.downwind = 45.0f;
    run.fast_forward = 5000.0f;
    run.endless_fetch = true;
    run.seconds = seconds;
    return run;
}

FenceDriftResult fence_drift(const FenceDrift& run) {
    SimConfig cfg;
    cfg.bounds = {{-run.upwind * fence_h, 0.0f, -0.5f},
                  {run.downwind * fence_h, 6.0f * fence_h, 0.5f}};
    Simulation sim(cfg);
    const glm::vec3 size = cfg.bounds.size();
    const auto across = [&](float extent) {
        return static_cast<std::uint32_t>(std::lround(extent / field_cell));
    };
    test::blow_steadily_through_field(
        sim, run.wind,
        {across(size.x), across(size.y), across(size.z), field_every, /*tunnel=*/true});
    WindTransportDef transport;
    transport.fast_forward = run.fast_forward;
    sim.set_wind_transport(transport);
    SurfaceDef ground;
    ground.x0 = cfg.bounds.min.x;
    ground.z0 = cfg.bounds.min.z;
    ground.size_x = size.x;
    ground.size_z = size.z;
    ground.cell = cell;
    ground.edge_limit = 10.0f; // only the wind moves snow here, and off the far end
    const SurfaceId id = sim.add_surface(ground, {});
    if (run.porosity < 1.0f) {
        sim.add_box({{0.0f, 0.0f, cfg.bounds.min.z}, {field_cell, fence_h, cfg.bounds.max.z}},
                    run.porosity);
    }
    const SnowSurface& s = snow_surface(sim, id);
    const auto column = [&](float x) {
        return static_cast<std::uint32_t>(std::floor((x - ground.x0) / cell));
    };
    const float fetch_from = (1.0f - run.upwind) * fence_h,
                fetch_to = fetch_from + run.fetch * fence_h;
    const auto fresh_units = static_cast<std::uint32_t>(std::lround(0.1 / s.unit_height));
    std::int64_t topped_up = 0;
    // Fills the fetch's cells up to the fresh depth.
    const auto fill_fetch = [&] {
        for (std::uint32_t ix = column(fetch_from); ix < column(fetch_to); ++ix) {
            for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
                const std::uint32_t has = s.snow[s.index(ix, iz)];
                if (has < fresh_units) {
                    sim.add_settled_snow(id, ix, iz, fresh_units - has);
                    topped_up += fresh_units - has;
                }
            }
        }
    };
    fill_fetch();
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
    // Mean snow top of column ix (m).
    const auto top = [&](std::uint32_t ix) {
        double sum_top = 0.0;
        for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
            sum_top += s.top_y(s.index(ix, iz));
        }
        return sum_top / s.nz;
    };
    // The air settles round the fence before the snow is counted.
    sim.run(ticks(10.0));
    const std::int64_t fetch = sum(fetch_from, fetch_to), lee = sum(0.0f, 15.0f),
                       windward = sum(-5.0f, 0.0f);
    topped_up = 0;
    std::vector<double> top_before(s.nx);
    for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
        top_before[ix] = top(ix);
    }
    // The drifts' shape now (DriftShape): from the fence out, a drift ends
    // where no cell of the next H stands H/50 above where it stood.
    const auto shape = [&](float seconds) {
        constexpr double least = 0.02 * fence_h;
        const auto gap = static_cast<std::uint32_t>(std::lround(fence_h / cell));
        DriftShape d;
        d.seconds = seconds;
        const auto walk = [&](std::uint32_t from, int step, std::uint32_t end, double& length,
                              double& depth) {
            std::uint32_t low = 0;
            for (std::uint32_t ix = from; ix != end && low <= gap; ix += step) {
                const double gain = top(ix) - top_before[ix];
                low = gain >= least ? 0 : low + 1;
                if (gain >= least) {
                    const double x = ground.x0 + (ix + (step > 0 ? 1.0 : 0.0)) * cell;
                    length = std::abs(x) / fence_h;
                    depth = std::max(depth, gain / fence_h);
                }
            }
        };
        walk(column(0.0f), 1, s.nx, d.lee_length, d.lee_depth);
        walk(column(0.0f) - 1, -1, column(fetch_to) - 1, d.windward_length, d.windward_depth);
        return d;
    };
    FenceDriftResult out;
    const WindField& f = world_of(sim).resource<WindField>();
    double lee_u = 0.0, free_u = 0.0;
    int lee_reads = 0, free_reads = 0;
    std::size_t next_shape = 0;
    for (int t = 0; t < ticks(run.seconds); ++t) {
        if (run.endless_fetch && t % field_every == 0) {
            fill_fetch();
        }
        sim.tick();
        out.balanced = out.balanced && sim.mass().balanced();
        if (t % field_every == 0) {
            for (float x = 2.0f; x <= 6.0f; x += field_cell, ++lee_reads) {
                lee_u += f.at(x, 0.5f * fence_h, 0.0f).x;
            }
            free_u += f.at(-10.0f * fence_h, 0.5f * fence_h, 0.0f).x;
            ++free_reads;
        }
        if (next_shape < run.shape_at.size() &&
            t + 1 == ticks(static_cast<double>(run.shape_at[next_shape]))) {
            out.shapes.push_back(shape(run.shape_at[next_shape++]));
        }
    }
    out.lee_wind_over_free = (lee_u / lee_reads) / (free_u / free_reads);
    out.fetch_loss = kg_per_m(fetch + topped_up - sum(fetch_from, fetch_to));
    out.lee_gain = kg_per_m(sum(0.0f, 15.0f) - lee);
    out.windward_gain = kg_per_m(sum(-5.0f, 0.0f) - windward);
    return out;
}

} // namespace snow
