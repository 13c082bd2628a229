// deposit: landing on the right surface and cell, the rolling rules of
// [ZCL §IV] at their stated frequencies, surface validation, concentrated
// landing [WF §4, §6] and thread-count independence.
#include "ecs/rng.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/core/units.hpp"
#include "systems/flakes/flake_stages.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <vector>

namespace snow {
namespace {

SimConfig small_config(std::uint32_t max_flakes = 64, unsigned threads = 1) {
    SimConfig c;
    c.seed = 11;
    c.bounds = {{-4.0f, -1.0f, -4.0f}, {4.0f, 6.0f, 4.0f}};
    c.max_flakes = max_flakes;
    c.threads = threads;
    return c;
}

SurfaceDef flat(float x0, float z0, float size, float cell, float y = 0.0f) {
    SurfaceDef d;
    d.x0 = x0;
    d.z0 = z0;
    d.size_x = d.size_z = size;
    d.cell = cell;
    d.base_y = y;
    d.spills = false;
    return d;
}

/// Adds an airborne flake (and its mass to the ledger) as if it had moved at
/// v this tick (its path started at p − v·dt); returns its slot.
std::uint32_t place_flake(Simulation& sim, glm::vec3 p, glm::vec3 v, std::uint32_t units) {
    FlakePool& f = InternalAccess::world(sim).resource<FlakePool>();
    const PathStarts st = stage_path_starts(InternalAccess::world(sim));
    std::uint32_t slot = 0;
    EXPECT_TRUE(f.acquire(slot));
    f.px[slot] = p.x;
    f.py[slot] = p.y;
    f.pz[slot] = p.z;
    const float dt = sim.config().dt;
    st.x[slot] = p.x - v.x * dt;
    st.y[slot] = p.y - v.y * dt;
    st.z[slot] = p.z - v.z * dt;
    f.vx[slot] = v.x;
    f.vy[slot] = v.y;
    f.vz[slot] = v.z;
    f.k_over_m[slot] = 9.81f;
    f.size[slot] = 0.01f;
    f.mass_units[slot] = units;
    InternalAccess::world(sim).resource<MassLedger>().spawned += units;
    return slot;
}

/// World centre of cell (ix, iz).
glm::vec3 centre(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz) {
    return {s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell, s.top_y(s.index(ix, iz)),
            s.z0 + (static_cast<float>(iz) + 0.5f) * s.cell};
}

TEST(SnowSurfaceDef, BadValuesNameTheField) {
    const auto error_of = [](auto edit) {
        SurfaceDef d;
        edit(d);
        try {
            (void)make_surface(d);
        } catch (const SimulationError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(error_of([](SurfaceDef& d) { d.cell = 0.0f; }), "surface.cell must be > 0 (got 0)");
    EXPECT_EQ(error_of([](SurfaceDef& d) { d.size_x = -1.0f; }),
              "surface.size_x must be > 0 (got -1)");
    EXPECT_EQ(error_of([](SurfaceDef& d) { d.x0 = std::nanf(""); }),
              "surface.x0 must be finite (got nan)");
    EXPECT_EQ(error_of([](SurfaceDef& d) { d.slope_z = INFINITY; }),
              "surface.slope_z must be finite (got inf)");
    EXPECT_EQ(error_of([](SurfaceDef& d) { d.edge_limit = -0.5f; }),
              "surface.edge_limit must be >= 0 (got -0.5)");
    EXPECT_EQ(error_of([](SurfaceDef& d) { d.laplacian_limit = 0.0f; }),
              "surface.laplacian_limit must be > 0 (got 0)");
    EXPECT_NE(error_of([](SurfaceDef& d) { d.size_z = 1000.0f; }).find("surface.size_z"),
              std::string::npos);
    EXPECT_NE(error_of([](SurfaceDef& d) { d.size_x = 0.01f; }).find(">= 1"), std::string::npos);
    EXPECT_NE(error_of([](SurfaceDef& d) {
                  d.cell = d.size_x = d.size_z = 1.0f; // 5e-8 m per unit: 1e8 m is 2e15 units
                  d.base_y = 1.0e8f;
              }).find("surface.base_y"),
              std::string::npos);
    // Through the facade: SimulationError, scene unchanged.
    Simulation sim(small_config());
    SurfaceDef bad;
    bad.cell = 0.0f;
    EXPECT_THROW(sim.add_surface(bad), SimulationError);
    EXPECT_EQ(world_of(sim).count<SnowSurface>(), 0u);
}

TEST(SnowSurfaceDef, LevelsAndLimitsInUnits) {
    SurfaceDef d = flat(-1.0f, 2.0f, 1.0f, 0.1f, 0.5f);
    d.slope_x = 0.2f;
    d.edge_limit = 0.05f;
    d.laplacian_limit = 20.0f;
    const SnowSurface s = make_surface(d);
    EXPECT_EQ(s.nx, 10u);
    EXPECT_EQ(s.nz, 10u);
    // 6.6e-6 m per unit at the default -5 °C's fresh density (75 kg/m³).
    const double uh = unit_kg / (fresh_snow_density(SimConfig{}.air_temperature) * 0.1 * 0.1);
    EXPECT_FLOAT_EQ(s.unit_height, static_cast<float>(uh));
    EXPECT_EQ(s.base_level[s.index(3, 7)], std::llround((0.5 + 0.2 * 0.35) / uh));
    EXPECT_EQ(s.edge_limit_units, static_cast<std::uint32_t>(std::llround(double{0.05f} / uh)));
    EXPECT_EQ(s.laplacian_limit_units, std::llround(20.0 * 0.01 / uh));
    std::uint32_t ix = 0, iz = 0;
    EXPECT_TRUE(s.cell_at(-0.95f, 2.99f, ix, iz));
    EXPECT_EQ(ix, 0u);
    EXPECT_EQ(iz, 9u);
    EXPECT_FALSE(s.cell_at(-1.01f, 2.5f, ix, iz));
    EXPECT_FALSE(s.cell_at(0.0f, 2.5f, ix, iz));
    EXPECT_FALSE(s.cell_at(std::nanf(""), 2.5f, ix, iz));
}

TEST(Deposit, FlakeInStillAirLandsInTheCellBelow) {
    Simulation sim(small_config());
    const SurfaceId g = sim.add_surface(flat(-1.0f, -1.0f, 2.0f, 0.1f));
    place_flake(sim, {0.23f, 1.0f, -0.41f}, {0.0f, -1.0f, 0.0f}, 40);
    for (int t = 0; t < 200 && sim.counters().landed == 0; ++t) {
        sim.tick();
    }
    const SnowSurface& s = snow_surface(sim, g);
    EXPECT_EQ(sim.counters().landed, 1u);
    EXPECT_EQ(sim.counters().rolled, 0u); // flat and bare: rule 1, it stays
    EXPECT_EQ(s.snow[s.index(12, 5)], 40u);
    EXPECT_EQ(s.settled_units(), 40u);
    EXPECT_EQ(flake_pool(sim).alive, 0u);
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(Deposit, FlakeBelowARoofDoesNotLandOnIt) {
    Simulation sim(small_config());
    const SurfaceId ground = sim.add_surface(flat(-2.0f, -2.0f, 4.0f, 0.1f));
    const SurfaceId roof = sim.add_surface(flat(-1.0f, -1.0f, 2.0f, 0.1f, 2.0f));
    // Under the roof, drifting sideways and falling: it must reach the ground.
    place_flake(sim, {-1.5f, 1.5f, 0.0f}, {1.0f, -0.2f, 0.0f}, 7);
    // Just under the roof's bare top, at rest: not on the roof either.
    place_flake(sim, {0.5f, 2.0f - 0.01f, 0.5f}, {0.0f, 0.0f, 0.0f}, 5);
    sim.run(600);
    EXPECT_EQ(snow_surface(sim, roof).settled_units(), 0u);
    EXPECT_EQ(snow_surface(sim, ground).settled_units(), 12u);
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(Deposit, FastFlakeLandsOnTheHighestSurfaceItCrossed) {
    Simulation sim(small_config());
    const SurfaceId ground = sim.add_surface(flat(-2.0f, -2.0f, 4.0f, 0.1f));
    const SurfaceId roof = sim.add_surface(flat(-1.0f, -1.0f, 2.0f, 0.1f, 0.5f));
    // Moved this tick from y = 1 to y = -0.01: it crossed the roof (0.5) and the ground (0).
    place_flake(sim, {0.05f, -0.01f, 0.05f}, {0.0f, -1.01f / sim.config().dt, 0.0f}, 3);
    deposit_system(InternalAccess::world(sim));
    EXPECT_EQ(snow_surface(sim, roof).settled_units(), 3u);
    EXPECT_EQ(snow_surface(sim, ground).settled_units(), 0u);
}

TEST(Deposit, FlakeInsideTheSnowLayerLands) {
    // The collide system sets flakes that hit a box top onto the bare top with
    // vy = 0; under deep snow that is inside the layer and must count as landed.
    Simulation sim(small_config());
    const SurfaceId roof = sim.add_surface(flat(-1.0f, -1.0f, 2.0f, 0.1f, 1.0f));
    sim.add_settled_snow(roof, 4, 4, 40000); // 0.2 m of snow
    const SnowSurface& s = snow_surface(sim, roof);
    place_flake(sim, {-0.55f, 1.0f, -0.55f}, {0.0f, 0.0f, 0.0f}, 9);
    deposit_system(InternalAccess::world(sim));
    EXPECT_EQ(sim.counters().landed, 1u);
    EXPECT_EQ(s.settled_units(), 40009u);
}

TEST(Deposit, SurfacesAddedOrRemovedMidRunAreSeen) {
    Simulation sim(small_config());
    const SurfaceId ground = sim.add_surface(flat(-2.0f, -2.0f, 4.0f, 0.1f));
    place_flake(sim, {0.5f, 1.0f, 0.5f}, {0.0f, -1.0f, 0.0f}, 4);
    sim.run(120);
    ASSERT_EQ(snow_surface(sim, ground).settled_units(), 4u);
    // A shelf appears under the next flake: the landing cache must notice.
    const SurfaceId shelf = sim.add_surface(flat(0.0f, 0.0f, 1.0f, 0.1f, 0.5f));
    place_flake(sim, {0.5f, 1.0f, 0.5f}, {0.0f, -1.0f, 0.0f}, 6);
    sim.run(120);
    EXPECT_EQ(snow_surface(sim, shelf).settled_units(), 6u);
    // And goes again: its snow leaves the books as removed, flakes reach the ground.
    sim.remove(shelf);
    place_flake(sim, {0.5f, 1.0f, 0.5f}, {0.0f, -1.0f, 0.0f}, 8);
    sim.run(120);
    EXPECT_EQ(snow_surface(sim, ground).settled_units(), 12u);
    EXPECT_EQ(sim.mass().removed, 6u);
    EXPECT_TRUE(sim.mass().balanced());
}

/// Lands one 1-unit flake on cell `c` of a 5×5 surface shaped by `snow`, for
/// `trials` ticks, restoring the shape each time; returns where each one went.
std::map<std::size_t, int> roll_counts(const std::array<std::uint32_t, 25>& shape, std::size_t c,
                                       int trials) {
    Simulation sim(small_config(4));
    const SurfaceId e = sim.add_surface(flat(0.0f, 0.0f, 0.5f, 0.1f));
    // Reshapes the cells each trial, outside the mass books: deposit alone is under test.
    SnowSurface& s = InternalAccess::world(sim).get<SnowSurface>(entity_of(e));
    std::map<std::size_t, int> hits;
    for (int t = 0; t < trials; ++t) {
        std::copy(shape.begin(), shape.end(), s.snow.begin());
        s.mark_dirty(static_cast<std::uint32_t>(c % 5), static_cast<std::uint32_t>(c / 5));
        InternalAccess::world(sim).resource<SimClock>().tick = static_cast<std::uint64_t>(t);
        place_flake(sim, centre(s, c % 5, c / 5), {0.0f, 0.0f, 0.0f}, 1);
        deposit_system(InternalAccess::world(sim));
        for (std::size_t i = 0; i < shape.size(); ++i) {
            if (s.snow[i] != shape[i]) {
                ++hits[i];
            }
        }
    }
    EXPECT_EQ(sim.counters().landed, static_cast<std::uint64_t>(trials));
    return hits;
}

/// Pearson chi-square of observed counts against equal expected shares.
double chi_square(const std::map<std::size_t, int>& hits, const std::vector<std::size_t>& cells,
                  int trials) {
    const double expected = static_cast<double>(trials) / static_cast<double>(cells.size());
    double chi = 0.0;
    for (const std::size_t c : cells) {
        const auto it = hits.find(c);
        const double d = (it == hits.end() ? 0.0 : it->second) - expected;
        chi += d * d / expected;
    }
    return chi;
}

/// Observed hits only on `cells` (everything that moved went there).
int total_on(const std::map<std::size_t, int>& hits, const std::vector<std::size_t>& cells) {
    int n = 0;
    for (const std::size_t c : cells) {
        n += hits.count(c) ? hits.at(c) : 0;
    }
    return n;
}

constexpr int roll_trials = 4000;
// 99.9% quantiles of chi-square with 1, 2 and 3 degrees of freedom.
constexpr double chi_999[] = {0.0, 10.83, 13.82, 16.27};

TEST(Deposit, RuleOneNoLowerNeighbourStays) {
    std::array<std::uint32_t, 25> shape{};
    shape.fill(50);
    shape[12] = 50; // level with all neighbours
    shape[7] = 80;
    const auto hits = roll_counts(shape, 12, 500);
    EXPECT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits.count(12) ? hits.at(12) : 0, 500);
}

TEST(Deposit, RuleTwoPeakRollsToEachEqualNeighbourAtAQuarter) {
    std::array<std::uint32_t, 25> shape{};
    shape[12] = 100; // a peak over four equal, lower neighbours
    const std::vector<std::size_t> nbrs{11, 13, 7, 17};
    const auto hits = roll_counts(shape, 12, roll_trials);
    EXPECT_EQ(total_on(hits, nbrs), roll_trials);
    EXPECT_LT(chi_square(hits, nbrs, roll_trials), chi_999[3]);
    for (const std::size_t c : nbrs) {
        EXPECT_NEAR(hits.at(c) / static_cast<double>(roll_trials), 0.25, 0.03);
    }
}

TEST(Deposit, RuleThreeRollsToTheLowerNeighboursEvenly) {
    std::array<std::uint32_t, 25> shape{};
    shape.fill(0);
    shape[12] = 100;
    shape[13] = 200; // higher: never chosen
    shape[7] = 100;  // level: never chosen
    // Two lower neighbours of different heights: 1/2 each.
    shape[11] = 10;
    shape[17] = 60;
    const std::vector<std::size_t> two{11, 17};
    auto hits = roll_counts(shape, 12, roll_trials);
    EXPECT_EQ(total_on(hits, two), roll_trials);
    EXPECT_LT(chi_square(hits, two, roll_trials), chi_999[1]);
    // Three lower neighbours: 1/3 each.
    shape[7] = 30;
    const std::vector<std::size_t> three{11, 17, 7};
    hits = roll_counts(shape, 12, roll_trials);
    EXPECT_EQ(total_on(hits, three), roll_trials);
    EXPECT_LT(chi_square(hits, three, roll_trials), chi_999[2]);
}

TEST(Deposit, RollsAtTheGridEdgeUseOnlyExistingNeighbours) {
    std::array<std::uint32_t, 25> shape{};
    shape[0] = 100; // corner peak: two neighbours, 1/2 each
    const std::vector<std::size_t> nbrs{1, 5};
    const auto hits = roll_counts(shape, 0, roll_trials);
    EXPECT_EQ(total_on(hits, nbrs), roll_trials);
    EXPECT_LT(chi_square(hits, nbrs, roll_trials), chi_999[1]);
}

TEST(Deposit, LaterLandingsOfATickSeeEarlierOnesSnow) {
    // Landings apply in slot order, each on the snow the ones before it left
    // (the pass finds roll targets by the levels it began with and
    // deposit_end recomputes those a landing of the tick made stale).
    Simulation sim(small_config());
    const SurfaceId e = sim.add_surface(flat(-1.0f, -1.0f, 2.0f, 0.05f));
    const SnowSurface& s = snow_surface(sim, e);
    for (int k = 0; k < 3; ++k) {
        place_flake(sim, centre(s, 20, 20), {0.0f, 0.0f, 0.0f}, 30);
    }
    sim.tick();
    // The first finds its cell level with its neighbours and stays (rule 1);
    // the next two find it higher and roll to a neighbour (rule 2).
    EXPECT_EQ(sim.counters().landed, 3u);
    EXPECT_EQ(sim.counters().rolled, 2u);
    EXPECT_EQ(s.snow[s.index(20, 20)], 30u);
    EXPECT_EQ(s.settled_units(), 90u);
}

TEST(Deposit, ConcentratedLandingStaysBounded) {
    // [WF §4, §6]: heavy flakes hitting one spot made the field blow up.
    // 100 000 units on one cell in four ticks, through the whole tick.
    Simulation sim(small_config(256));
    const SurfaceId e = sim.add_surface(flat(-1.0f, -1.0f, 2.0f, 0.05f));
    const SnowSurface& s = snow_surface(sim, e);
    const std::size_t c = s.index(20, 20);
    const std::uint64_t total = 100000;
    for (int t = 0; t < 200; ++t) {
        if (t < 4) {
            for (int k = 0; k < 25; ++k) {
                place_flake(sim, centre(s, 20, 20), {0.0f, 0.0f, 0.0f}, max_flake_units);
            }
        }
        sim.tick();
        const MassReport m = sim.mass();
        ASSERT_TRUE(m.balanced()) << "tick " << t;
        const std::uint32_t peak = *std::max_element(s.snow.begin(), s.snow.end());
        ASSERT_LE(peak, total) << "tick " << t; // a wrapped (negative) cell would be huge
    }
    EXPECT_EQ(sim.counters().landed, 100u);
    EXPECT_EQ(s.settled_units(), total);
    EXPECT_TRUE(s.dirty_empty()); // smoothing finished
    // The cap holds everywhere: n·h − Σ neighbours <= limit.
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            std::size_t nb[4];
            const std::uint32_t n = s.neighbours(ix, iz, nb);
            std::int64_t lap = n * s.level(s.index(ix, iz));
            for (std::uint32_t k = 0; k < n; ++k) {
                lap -= s.level(nb[k]);
            }
            ASSERT_LE(lap, s.laplacian_limit_units) << ix << "," << iz;
        }
    }
    // Spread over a paraboloid-like mound: the centre holds a small share.
    EXPECT_LT(s.snow[c], total / 10);
}

/// A scene with three surfaces, spill and heavy landing over > 2 chunks of flakes.
std::unique_ptr<Simulation> busy(unsigned threads) {
    auto sim = std::make_unique<Simulation>(small_config(3 * 16384, threads));
    sim->add_surface(flat(-4.0f, -4.0f, 8.0f, 0.1f));
    const ColliderId box = sim->add_box({{-1.0f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}});
    SurfaceDef roof = flat(-1.0f, -1.0f, 2.0f, 0.1f, 1.0f);
    roof.spills = true;
    roof.edge_limit = 0.0005f;
    sim->add_surface(roof, box);
    sim->add_surface(flat(2.0f, 2.0f, 1.0f, 0.05f, 0.3f));
    for (std::uint32_t i = 0; i < 40000; ++i) {
        const RngKey k{99, 0, i, random_stream::test};
        place_flake(*sim,
                    {rng_range(k, 0, -3.9f, 3.9f), rng_range(k, 1, 0.0f, 1.6f),
                     rng_range(k, 2, -3.9f, 3.9f)},
                    {0.0f, -1.0f, 0.0f}, 1 + rng_below(k, 3, 60));
    }
    return sim;
}

TEST(Deposit, OneAndTwoThreadsAgreeEveryTick) {
    auto one = busy(1);
    auto two = busy(2);
    for (int t = 0; t < 120; ++t) {
        one->tick();
        two->tick();
        ASSERT_EQ(one->state_hash(), two->state_hash()) << "tick " << t;
        ASSERT_TRUE(two->mass().balanced()) << "tick " << t;
    }
    EXPECT_EQ(one->counters().landed, two->counters().landed);
    EXPECT_EQ(one->counters().rolled, two->counters().rolled);
    EXPECT_EQ(one->counters().spilled_units, two->counters().spilled_units);
    EXPECT_GT(one->counters().landed, 30000u);
    EXPECT_GT(one->counters().rolled, 0u);
    EXPECT_GT(one->counters().spilled_units, 0u);
}

} // namespace
} // namespace snow
