// Density and settling (issue #30 item 2): fresh snow lands at the density of
// the declared air temperature [HP98]; every cell keeps its snow's density
// exactly (units over levels) and settles under its own weight [And76]
// (docs/references.md), with mass exact and the same result for any thread
// count and after a restore.
#include "systems/api/simulation_internals.hpp"
#include "systems/core/units.hpp"
#include "tests/support/snapshot_check.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace snow {
namespace {

SimConfig config_at(float air_c, float dt = SimConfig{}.dt) {
    SimConfig c;
    c.air_temperature = air_c;
    c.dt = dt;
    return c;
}

const SnowSurface& only_surface(const Simulation& sim) {
    const SnowSurface* first = nullptr;
    world_of(sim).each<SnowSurface>([&](Entity, const SnowSurface& s) { first = &s; });
    return *first;
}

/// Mean density (kg/m³) of cell i: its mass over its depth times its area.
double density(const SnowSurface& s, std::size_t i) {
    return s.snow[i] * unit_kg / (s.depth_levels(i) * double{s.unit_height} * s.cell * s.cell);
}

/// A 10 cm cell of ground (it keeps its snow) with `metres` of fresh snow.
SurfaceId one_cell(Simulation& sim, double metres) {
    SurfaceDef def;
    def.size_x = def.size_z = def.cell = 0.1f;
    def.spills = false;
    const SurfaceId id = sim.add_surface(def);
    const auto units =
        static_cast<std::uint32_t>(std::llround(metres / sim.surface(id).unit_height));
    sim.add_settled_snow(id, 0, 0, units);
    return id;
}

TEST(Density, FreshSnowLandsAtTheDensityOfTheAirTemperature) {
    for (const float t : {-30.0f, -10.0f, -5.0f, -1.0f, 0.0f, 5.0f}) {
        Simulation sim(config_at(t));
        one_cell(sim, 0.1);
        const double hp98 = 67.92 + 51.25 * std::exp(std::min(t, 0.0f) / 2.59);
        EXPECT_NEAR(density(only_surface(sim), 0), hp98, 1e-3 * hp98) << t << " °C";
    }
}

TEST(Density, MixingSnowOfTwoDensitiesIsExact) {
    Simulation sim(config_at(-5.0f, 1.0f));
    const SurfaceId id = one_cell(sim, 0.5);
    sim.run(86400); // a day: the cell settles
    const SnowSurface& s = only_surface(sim);
    const std::uint32_t units = s.snow[0];
    const std::int64_t levels = s.depth_levels(0);
    ASSERT_LT(levels, std::int64_t{units});
    sim.add_settled_snow(id, 0, 0, 1000); // fresh snow on top: one level per unit
    EXPECT_EQ(s.snow[0], units + 1000);
    EXPECT_EQ(s.depth_levels(0), levels + 1000);
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(Settling, DaysOfSettlingTakeFreshSnowTowardsSettledSnow) {
    Simulation sim(config_at(-5.0f, 1.0f));
    one_cell(sim, 1.0);
    const SnowSurface& s = only_surface(sim);
    const std::uint32_t units = s.snow[0];
    double before = density(s, 0);
    for (int day = 1; day <= 5; ++day) {
        sim.run(86400);
        const double now = density(s, 0);
        EXPECT_GT(now, before) << "day " << day;
        before = now;
        EXPECT_EQ(s.snow[0], units); // settling moves no mass
        EXPECT_TRUE(sim.mass().balanced());
    }
    // [And76] integrated for 1 m at -5 °C: about 240 kg/m³ after 5 days;
    // settled snow is 200–300 kg/m³ [CP10].
    EXPECT_GE(before, 200.0);
    EXPECT_LE(before, 300.0);
}

TEST(Settling, WarmSnowSettlesFasterThanColdSnow) {
    const auto gain = [](float t) {
        Simulation sim(config_at(t, 1.0f));
        one_cell(sim, 0.3);
        const double fresh = density(only_surface(sim), 0);
        sim.run(86400);
        return density(only_surface(sim), 0) / fresh;
    };
    EXPECT_GT(gain(-1.0f), gain(-10.0f));
    EXPECT_GT(gain(-10.0f), 1.1);
}

/// A 2 m square of 10 cm cells with uneven snow, settling every second.
std::unique_ptr<Simulation> uneven_pack(unsigned threads) {
    SimConfig c = config_at(-2.0f);
    c.threads = threads;
    c.settle_interval = 1.0f;
    auto sim = std::make_unique<Simulation>(c);
    SurfaceDef def;
    def.size_x = def.size_z = 2.0f;
    def.cell = 0.1f;
    const SurfaceId id = sim->add_surface(def);
    for (std::uint32_t iz = 0; iz < 20; ++iz) {
        for (std::uint32_t ix = 0; ix < 20; ++ix) {
            sim->add_settled_snow(id, ix, iz, 2000 + 500 * ((ix * 7 + iz * 3) % 11));
        }
    }
    return sim;
}

TEST(Settling, SameForAnyThreadCountAndAfterARestore) {
    auto one = uneven_pack(1);
    one->run(600);
    EXPECT_FALSE(only_surface(*one).compacted.empty());
    EXPECT_TRUE(one->mass().balanced());
    auto two = uneven_pack(2);
    two->run(600);
    EXPECT_EQ(one->state_hash(), two->state_hash());
    test::expect_restore_replays(*one, 60, 300);
}

TEST(Settling, BadTemperatureOrStepNeverMakesASimulation) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    for (const float t : {nan, inf, -inf, -80.5f, 40.5f}) {
        try {
            Simulation sim(config_at(t));
            ADD_FAILURE() << t << " °C accepted";
        } catch (const SimulationError& e) {
            EXPECT_NE(std::string(e.what()).find("simulation.air_temperature"), std::string::npos)
                << e.what();
        }
    }
    for (const float step : {nan, 0.0f, -1.0f, 3601.0f}) {
        SimConfig c;
        c.settle_interval = step;
        try {
            Simulation sim(c);
            ADD_FAILURE() << step << " s accepted";
        } catch (const SimulationError& e) {
            EXPECT_NE(std::string(e.what()).find("simulation.settle_interval"), std::string::npos)
                << e.what();
        }
    }
}

} // namespace
} // namespace snow
