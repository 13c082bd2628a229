// redistribute: the Laplacian cap of [WF §3] must smooth any pile with no
// negative cell, exact mass, no new maximum (a mass check alone misses a
// blow-up: docs/design.md "Numerical stability") and no sweep-direction bias.
#include "systems/api/simulation_internals.hpp"
#include "tests/support/settle.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace snow {
namespace {

struct Field {
    Simulation sim;
    SurfaceId e;
    explicit Field(const SurfaceDef& def) : sim(SimConfig{}), e(sim.add_surface(def)) {}
    [[nodiscard]] const SnowSurface& s() const { return snow_surface(sim, e); }
    void put(std::uint32_t ix, std::uint32_t iz, std::uint32_t units) {
        sim.add_settled_snow(e, ix, iz, units);
    }
    int settle(int max_calls) { return test::settle_surface(sim, e, max_calls); }
    [[nodiscard]] std::uint32_t peak() {
        return *std::max_element(s().snow.begin(), s().snow.end());
    }
    /// n·h − Σ neighbour levels of the cell (the discrete Laplacian of [WF §3]).
    std::int64_t laplacian(std::uint32_t ix, std::uint32_t iz) {
        std::size_t nb[4];
        const std::uint32_t n = s().neighbours(ix, iz, nb);
        std::int64_t lap = n * s().level(s().index(ix, iz));
        for (std::uint32_t k = 0; k < n; ++k) {
            lap -= s().level(nb[k]);
        }
        return lap;
    }
    /// Largest Laplacian over cells that hold snow.
    std::int64_t worst_laplacian() {
        std::int64_t worst = std::numeric_limits<std::int64_t>::min();
        for (std::uint32_t iz = 0; iz < s().nz; ++iz) {
            for (std::uint32_t ix = 0; ix < s().nx; ++ix) {
                if (s().snow[s().index(ix, iz)] > 0) {
                    worst = std::max(worst, laplacian(ix, iz));
                }
            }
        }
        return worst;
    }
};

SurfaceDef square(std::uint32_t cells, float laplacian_limit = 20.0f) {
    SurfaceDef d;
    d.size_x = d.size_z = 0.05f * static_cast<float>(cells);
    d.cell = 0.05f;
    d.spills = false;
    d.laplacian_limit = laplacian_limit;
    return d;
}

TEST(Redistribute, SpikeSmoothsSymmetricallyWithExactMass) {
    Field f(square(31));
    const std::uint32_t spike = 10000;
    f.put(15, 15, spike);
    const int calls = f.settle(100);
    const SnowSurface& s = f.s();
    EXPECT_TRUE(s.dirty_empty()) << "still smoothing after " << calls << " ticks";
    EXPECT_EQ(s.settled_units(), spike);
    EXPECT_LE(f.peak(), spike); // no cell wrapped below zero (it would read huge)
    EXPECT_LT(s.snow[s.index(15, 15)], spike);
    EXPECT_GT(s.snow[s.index(14, 15)], 0u);
    EXPECT_LE(f.worst_laplacian(), s.laplacian_limit_units);
    EXPECT_GT(f.sim.counters().smoothing_iterations, 0u);
    // 90° rotation about the centre maps (x, z) to (n-1-z, x): the result must not care.
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            ASSERT_EQ(s.snow[s.index(ix, iz)], s.snow[s.index(s.nx - 1 - iz, ix)])
                << ix << "," << iz;
            ASSERT_EQ(s.snow[s.index(ix, iz)], s.snow[s.index(iz, ix)]) << ix << "," << iz;
        }
    }
}

TEST(Redistribute, CornerSpikeUsesOnlyExistingNeighbours) {
    Field f(square(12));
    f.put(0, 0, 20000);
    f.settle(200);
    const SnowSurface& s = f.s();
    EXPECT_TRUE(s.dirty_empty());
    EXPECT_EQ(s.settled_units(), 20000u);
    EXPECT_LE(f.peak(), 20000u);
    EXPECT_LE(f.worst_laplacian(), s.laplacian_limit_units);
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) { // mirror symmetric about the diagonal
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            ASSERT_EQ(s.snow[s.index(ix, iz)], s.snow[s.index(iz, ix)]);
        }
    }
}

TEST(Redistribute, FlatSnowWithinTheCapDoesNotMove) {
    Field f(square(8));
    for (std::uint32_t iz = 0; iz < 8; ++iz) {
        for (std::uint32_t ix = 0; ix < 8; ++ix) {
            f.put(ix, iz, 700 + 10 * ((ix + iz) % 2)); // ripples of 10 units, cap is 2500
        }
    }
    const auto before = f.s().snow;
    redistribute_system(InternalAccess::world(f.sim));
    EXPECT_EQ(f.s().snow, before);
    EXPECT_TRUE(f.s().dirty_empty());
    EXPECT_EQ(f.sim.counters().smoothing_iterations, 1u);
}

TEST(Redistribute, HugePileNeverOvershootsAcrossTicks) {
    // Far more than one tick's iterations can spread: the work continues on
    // later ticks, and every intermediate state stays bounded and exact.
    Field f(square(64));
    const std::uint32_t pile = 50'000'000;
    f.put(32, 32, pile);
    std::uint32_t previous_peak = pile;
    int ticks = 0;
    for (; ticks < 2000 && !f.s().dirty_empty(); ++ticks) {
        redistribute_system(InternalAccess::world(f.sim));
        ASSERT_EQ(f.s().settled_units(), pile) << "tick " << ticks;
        const std::uint32_t peak = f.peak();
        ASSERT_LE(peak, previous_peak) << "tick " << ticks; // the maximum never grows
        previous_peak = peak;
    }
    EXPECT_GT(ticks, 1); // it needed more than one tick
    EXPECT_TRUE(f.s().dirty_empty());
    EXPECT_LE(f.worst_laplacian(), f.s().laplacian_limit_units);
}

TEST(Redistribute, TinyCapStaysStableAndTerminates) {
    // A cap of one unit: integer flows can stall short of it, but never oscillate or blow up.
    Field f(square(16, 1.0e-4f));
    ASSERT_EQ(f.s().laplacian_limit_units, 1);
    f.put(8, 8, 1000);
    f.put(3, 12, 1000);
    f.settle(500);
    EXPECT_TRUE(f.s().dirty_empty());
    EXPECT_EQ(f.s().settled_units(), 2000u);
    EXPECT_LE(f.peak(), 1000u);
    // Where it stalled, every lower neighbour is within 7 levels (flow is d/8 per edge).
    EXPECT_LE(f.worst_laplacian(), 4 * 7);
}

TEST(Redistribute, SlopedBaseNeverTakesMoreThanACellHolds) {
    // A steep base: bare cells along the upper edge violate the cap by shape
    // alone and must not give snow they do not have.
    SurfaceDef d = square(20);
    d.slope_x = 3.0f;
    d.base_y = 1.0f;
    Field f(d);
    for (std::uint32_t iz = 0; iz < 20; iz += 3) {
        f.put(19, iz, 30000);
    }
    const std::uint64_t total = f.s().settled_units();
    f.settle(1000);
    EXPECT_TRUE(f.s().dirty_empty());
    EXPECT_EQ(f.s().settled_units(), total);
    EXPECT_LE(f.peak(), 30000u);
    // The snow moved downhill (towards -x).
    std::uint64_t moment = 0;
    for (std::uint32_t iz = 0; iz < 20; ++iz) {
        for (std::uint32_t ix = 0; ix < 20; ++ix) {
            moment += static_cast<std::uint64_t>(ix) * f.s().snow[f.s().index(ix, iz)];
        }
    }
    EXPECT_LT(moment, 19 * total);
}

TEST(Redistribute, LevelBaseShortcutMovesTheSameSnow) {
    // A level rectangle's prefilter reads the snow alone (SnowSurface::
    // uniform_base); with the flag cleared it reads the base too. Scattered
    // piles (box by box) and piles on most tiles (one scan) move the same
    // snow either way, tick for tick.
    for (const std::uint32_t step : {97u, 3u}) {
        SurfaceDef d = square(48, 1.0e-4f); // a cap of one unit: flows stop at the 1/8 rule
        d.base_y = 0.75f;
        Field level(d), general(d);
        ASSERT_TRUE(level.s().uniform_base);
        InternalAccess::world(general.sim).get<SnowSurface>(entity_of(general.e)).uniform_base =
            false;
        for (std::uint32_t n = 0; n < 48 * 48; n += step) {
            const std::uint32_t units = 4000 + 997 * (n % 7);
            level.put(n % 48, n / 48, units);
            general.put(n % 48, n / 48, units);
        }
        const Vector<std::uint32_t> put = level.s().snow;
        for (int tick = 0; tick < 40; ++tick) {
            redistribute_system(InternalAccess::world(level.sim));
            redistribute_system(InternalAccess::world(general.sim));
            ASSERT_EQ(level.s().snow, general.s().snow) << "every " << step << ", tick " << tick;
        }
        EXPECT_NE(level.s().snow, put) << "every " << step; // the piles did move
        EXPECT_TRUE(level.s().dirty_empty()) << "every " << step;
    }
}

TEST(Redistribute, OnlyTheDirtyRegionIsTouched) {
    Field f(square(40));
    // Snow that is not marked dirty (no facade call leaves it so): left alone.
    SnowSurface& raw = InternalAccess::world(f.sim).get<SnowSurface>(entity_of(f.e));
    raw.snow[raw.index(5, 5)] = 9000;
    f.put(30, 30, 9000);
    f.settle(100);
    EXPECT_EQ(f.s().snow[f.s().index(5, 5)], 9000u);
    EXPECT_LT(f.s().snow[f.s().index(30, 30)], 9000u);
}

} // namespace
} // namespace snow
