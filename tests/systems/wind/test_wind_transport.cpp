// Snow the wind moves (issue #15, transport; issue #30, the saltation flux):
// above the threshold snow leaves its cell downwind, below it stays; units only move (the ledger is
// exact every tick); a roof in a gale loses its snow over the lee edge as flakes; deterministic
// across threads and restore; bad settings are refused.
#include "systems/api/simulation_internals.hpp"
#include "tests/scenes/drifting_snow.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/even_snow.hpp"
#include "tests/support/snapshot_check.hpp"
#include "tests/support/steady_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace snow {
namespace {

constexpr float snow_depth = 0.05f; // m, laid on every cell before the wind starts

/// A 12 m × 4 m open yard, a steady wind of `speed` m/s along +x through a
/// coarse field, and a 4 m × 2 m snow surface (10 cm cells) with 5 cm of snow,
/// on the ground (`raised` false, not spilling) or on a 1 m box (a roof that
/// spills over its edges).
std::unique_ptr<Simulation> snowy_patch(float speed, bool raised, unsigned threads = 1) {
    SimConfig cfg;
    cfg.bounds = {{-6.0f, 0.0f, -2.0f}, {6.0f, 4.0f, 2.0f}};
    cfg.max_flakes = 200000;
    cfg.threads = threads;
    auto sim = std::make_unique<Simulation>(cfg);
    test::blow_steadily_through_field(*sim, speed, {48, 8, 16, 2});
    SurfaceDef patch;
    patch.x0 = -2.0f;
    patch.z0 = -1.0f;
    patch.size_x = 4.0f;
    patch.size_z = 2.0f;
    patch.cell = 0.1f;
    patch.edge_limit = 1.0f; // nothing spills by the edge rule: only the wind moves snow
    ColliderId owner;
    if (raised) {
        owner = sim->add_box({{-2.0f, 0.0f, -1.0f}, {2.0f, 1.0f, 1.0f}});
        patch.base_y = 1.0f;
    } else {
        patch.spills = false;
    }
    const SurfaceId s = sim->add_surface(patch, owner);
    const SnowSurface& surface = snow_surface(*sim, s);
    const auto units = static_cast<std::uint32_t>(std::lround(snow_depth / surface.unit_height));
    test::snow_every_cell(*sim, s, units);
    return sim;
}

/// The flux at its full rate within the tests' few-metre patches: a short
/// adjustment length (FluxBuildsUpAlongTheFetch holds the default's).
WindTransportDef drifting() {
    WindTransportDef t;
    t.adjustment_length = 0.1f;
    return t;
}

const SnowSurface& patch_of(const Simulation& sim) {
    const SnowSurface* s = nullptr;
    world_of(sim).each<SnowSurface>([&](Entity, const SnowSurface& surface) { s = &surface; });
    return *s;
}

/// Mean x (m) of the patch's snow, weighted by units.
double snow_centre_x(const SnowSurface& s) {
    double sum = 0.0, weight = 0.0;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const double u = s.snow[s.index(ix, iz)];
            sum += u * (s.x0 + (ix + 0.5) * s.cell);
            weight += u;
        }
    }
    return weight > 0.0 ? sum / weight : std::numeric_limits<double>::quiet_NaN();
}

TEST(WindTransport, SnowDriftsDownwindAndEveryUnitStaysInTheLedger) {
    auto sim = snowy_patch(10.0f, false);
    sim->set_wind_transport(drifting());
    const std::uint64_t settled = patch_of(*sim).settled_units();
    const double start_x = snow_centre_x(patch_of(*sim));
    for (int t = 0; t < 1200; ++t) {
        sim->tick();
        ASSERT_TRUE(sim->mass().balanced()) << "tick " << t;
    }
    const SnowSurface& s = patch_of(*sim);
    EXPECT_EQ(s.settled_units(), settled) << "on a surface that never spills snow only moves";
    // About 0.4 kg of the patch's 30 kg moved some metres downwind.
    EXPECT_GT(snow_centre_x(s), start_x + 0.02) << "the snow's centre moved downwind (+x)";
    // The windward column lost snow, the lee column gained it.
    const auto column = [&](std::uint32_t ix) {
        std::uint64_t u = 0;
        for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
            u += s.snow[s.index(ix, iz)];
        }
        return u;
    };
    const std::uint64_t even = settled / s.nx;
    EXPECT_LT(column(0), even * 3 / 4);
    EXPECT_GT(column(s.nx - 1), even * 5 / 4);
}

TEST(WindTransport, BelowTheThresholdSnowStays) {
    // Fresh snow (75 kg/m³ at -5 °C) drifts from u*t = 0.125 m/s [Lis07]: a
    // wind of 1.7 m/s 0.25 m above it by the log law with z0 = 1 mm.
    auto calm = snowy_patch(1.2f, false);
    calm->set_wind_transport(drifting());
    auto plain = snowy_patch(1.2f, false);
    calm->run(400);
    plain->run(400);
    EXPECT_EQ(patch_of(*calm).snow, patch_of(*plain).snow);
}

TEST(WindTransport, ARoofInAGaleLosesItsSnowOverTheLeeEdgeAsFlakes) {
    auto sim = snowy_patch(14.0f, true);
    sim->set_wind_transport(drifting());
    const std::uint64_t settled = patch_of(*sim).settled_units();
    for (int t = 0; t < 1200; ++t) {
        sim->tick();
        ASSERT_TRUE(sim->mass().balanced()) << "tick " << t;
    }
    const SnowSurface& s = patch_of(*sim);
    // A saltation flux of about 10 g/(m·s) off a 2 m wide roof for 20 s.
    EXPECT_LT(s.settled_units(), settled - settled / 200) << "the roof kept its snow";
    const MassReport m = sim->mass();
    EXPECT_GT(m.airborne + m.removed, 0u) << "what left the roof became flakes";
    // The windward half keeps less than the lee half.
    std::uint64_t windward = 0, lee = 0;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            (ix < s.nx / 2 ? windward : lee) += s.snow[s.index(ix, iz)];
        }
    }
    EXPECT_LT(windward, lee);
}

TEST(WindTransport, OneAndTwoThreadsAgreeAndRestoreReplays) {
    auto one = snowy_patch(12.0f, true, 1);
    auto two = snowy_patch(12.0f, true, 2);
    one->set_wind_transport(drifting());
    two->set_wind_transport(drifting());
    for (int t = 0; t < 300; ++t) {
        one->tick();
        two->tick();
        ASSERT_EQ(one->state_hash(), two->state_hash()) << "tick " << t;
    }
    test::expect_restore_replays(*one, 101, 150);
}

TEST(WindTransport, SettingsAreHashedAndKeptWhenTheFieldIsReplaced) {
    auto a = snowy_patch(10.0f, false);
    auto b = snowy_patch(10.0f, false);
    a->set_wind_transport(drifting());
    EXPECT_NE(a->state_hash(), b->state_hash());
    b->set_wind_transport(drifting());
    EXPECT_EQ(a->state_hash(), b->state_hash());
    WindFieldDef finer;
    finer.cells_x = 64;
    finer.cells_y = 8;
    finer.cells_z = 16;
    a->set_wind_field(finer);
    ASSERT_TRUE(world_of(*a).resource<WindField>().transport.has_value());
    a->clear_wind_transport();
    EXPECT_FALSE(world_of(*a).resource<WindField>().transport.has_value());
}

TEST(WindTransport, BadSettingsNameTheFieldAndChangeNothing) {
    auto sim = snowy_patch(10.0f, false);
    const std::uint64_t before = sim->state_hash();
    const auto rejects = [&](WindTransportDef t, const char* field) {
        try {
            sim->set_wind_transport(t);
            ADD_FAILURE() << "accepted a bad " << field;
        } catch (const SimulationError& e) {
            EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
        }
        EXPECT_EQ(sim->state_hash(), before);
    };
    WindTransportDef t;
    t.roughness = std::numeric_limits<float>::quiet_NaN();
    rejects(t, "wind.field.transport.roughness");
    t = {};
    t.roughness = 0.0f;
    rejects(t, "wind.field.transport.roughness");
    t = {};
    t.height = std::numeric_limits<float>::infinity();
    rejects(t, "wind.field.transport.height");
    t = {};
    t.height = 0.5f * t.roughness; // the log law needs z > z0
    rejects(t, "wind.field.transport.height");
    for (const float bad : {0.5f, 2.0e5f, std::numeric_limits<float>::quiet_NaN()}) {
        t = {};
        t.fast_forward = bad;
        rejects(t, "wind.field.transport.fast_forward");
    }
    Simulation no_field;
    EXPECT_THROW(no_field.set_wind_transport(drifting()), SimulationError);
}

// Item 5 of issue #30: the flux a snow field carries is a property of the
// wind and the snow, not of the grid: the same (within 10%) at half the cell,
// twice the depth, half the step and half the field's cells; and within
// 0.3–3× of Pomeroy & Gray's saltation law [PG90] at 8–15 m/s.
TEST(WindTransport, FluxIsTheSameAtAnyCellSizeDepthStepAndFieldResolution) {
    const DriftingSnow base;
    const DriftFlux reference = drifting_snow(base);
    ASSERT_TRUE(reference.balanced);
    ASSERT_GT(reference.flux, 0.0);
    const auto within_10_percent = [&](DriftingSnow run, const char* what) {
        const DriftFlux f = drifting_snow(run);
        EXPECT_TRUE(f.balanced) << what;
        EXPECT_NEAR(f.flux / reference.flux, 1.0, 0.1)
            << what << ": " << f.flux << " vs " << reference.flux << " kg/(m·s)";
    };
    DriftingSnow run = base;
    run.cell = 0.1f;
    within_10_percent(run, "10 cm cells");
    run = base;
    run.cell = 0.025f;
    within_10_percent(run, "2.5 cm cells");
    run = base;
    run.depth = 0.06f;
    within_10_percent(run, "twice the depth");
    run = base;
    run.dt = base.dt / 2.0f;
    within_10_percent(run, "half the step");
    run = base;
    run.field_cell = base.field_cell / 2.0f;
    within_10_percent(run, "half the field's cells");
}

// Blowing snow builds up along its fetch [Kob72]: with the default 20 m
// adjustment length, the flux 5 m into the strip is 1 − e^(−5/20) = 0.22 of
// the saturated one, at any cell size.
TEST(WindTransport, FluxBuildsUpAlongTheFetch) {
    const DriftFlux saturated = drifting_snow({});
    for (const float cell : {0.05f, 0.1f}) {
        DriftingSnow run;
        run.cell = cell;
        run.adjustment_length = WindTransportDef{}.adjustment_length;
        const DriftFlux f = drifting_snow(run);
        EXPECT_TRUE(f.balanced);
        EXPECT_NEAR(f.flux / saturated.flux, -std::expm1(-5.0 / 20.0), 0.03) << cell << " m cells";
    }
}

TEST(WindTransport, SnowTheWindLaysDownIsWindPacked) {
    const DriftFlux f = drifting_snow({});
    EXPECT_GE(f.laid_density, 350.0); // wind-packed snow, [CP10]
    EXPECT_LE(f.laid_density, 400.0);
}

TEST(WindTransport, FluxIsWithinTheBandOfPomeroyAndGray) {
    for (const float wind : {8.0f, 12.0f, 15.0f}) {
        DriftingSnow run;
        run.wind = wind;
        const DriftFlux f = drifting_snow(run);
        EXPECT_TRUE(f.balanced);
        const double ratio = f.flux / f.published;
        EXPECT_GE(ratio, 0.3) << wind << " m/s: " << f.flux << " vs " << f.published;
        EXPECT_LE(ratio, 3.0) << wind << " m/s: " << f.flux << " vs " << f.published;
    }
}

} // namespace
} // namespace snow
