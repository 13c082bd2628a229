// flake order: every flake_order_every ticks the alive flakes are stably
// sorted by ground column and packed into the lowest slots; every flake keeps
// all its data and its id, and the free slots are handed out lowest first.
#include "ecs/rng.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/api/systems.hpp"
#include "systems/flakes/flake_order.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/share_work.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace snow {
namespace {

/// Everything a flake carries, by id.
using FlakeData = std::tuple<float, float, float, float, float, float, float, float, std::uint32_t>;

std::map<std::uint32_t, FlakeData> flakes_by_id(const FlakePool& f) {
    std::map<std::uint32_t, FlakeData> out;
    for (std::uint32_t s = 0; s < f.slot_end; ++s) {
        if (f.is_alive(s)) {
            out[f.id[s]] = {f.px[s], f.py[s],       f.pz[s],   f.vx[s],        f.vy[s],
                            f.vz[s], f.k_over_m[s], f.size[s], f.mass_units[s]};
        }
    }
    return out;
}

/// Place in the order of the column of the ordering grid holding (x, z) in
/// bounds [-8, 8]²: square tiles of flake_order_tile columns in rows along x,
/// and the columns of a tile in rows along x.
std::uint32_t column_of(float x, float z) {
    const auto col = [](float u) {
        return std::min(flake_order_bins - 1,
                        static_cast<std::uint32_t>((u + 8.0f) / 16.0f * flake_order_bins));
    };
    constexpr std::uint32_t t = flake_order_tile;
    const std::uint32_t tile_row = col(z) / t, tile_col = col(x) / t;
    const std::uint32_t tile = tile_row * (flake_order_bins / t) + tile_col;
    return tile * t * t + (col(z) % t) * t + col(x) % t;
}

/// Every slot from the alive count on holds what reset() and release() leave.
void expect_free_from(const FlakePool& f, std::uint32_t from) {
    for (std::uint32_t s = from; s < f.capacity(); ++s) {
        ASSERT_EQ(f.mass_units[s], 0u) << "slot " << s;
        ASSERT_EQ(f.py[s], FlakePool::parked_y) << "slot " << s;
        for (const float v :
             {f.px[s], f.pz[s], f.vx[s], f.vy[s], f.vz[s], f.k_over_m[s], f.size[s]}) {
            ASSERT_EQ(v, 0.0f) << "slot " << s;
        }
        ASSERT_EQ(f.id[s], 0u) << "slot " << s;
    }
}

class FlakeOrderThreads : public ::testing::TestWithParam<unsigned> {};

TEST_P(FlakeOrderThreads, PacksTheAliveFlakesByColumnStablyAndKeepsEachOnesData) {
    SimConfig c;
    c.bounds = {{-8.0f, -1.0f, -8.0f}, {8.0f, 8.0f, 8.0f}};
    c.max_flakes = 4096;
    c.threads = GetParam();
    Simulation sim(c);
    test::share_work_at_any_size(sim); // both halves of the move on the pool
    for (std::uint32_t n = 0; n < 3000; ++n) {
        FlakeSpec f;
        const RngKey k{5, 0, n, 0};
        f.position = {rng_range(k, 0, -7.9f, 7.9f), rng_range(k, 1, 0.5f, 7.0f),
                      rng_range(k, 2, -7.9f, 7.9f)};
        f.velocity = {rng_range(k, 3, -1.0f, 1.0f), -1.0f, 0.0f};
        f.size = rng_range(k, 4, 0.002f, 0.02f);
        f.mass_units = 1 + n % 50;
        sim.place_flake(f);
    }
    World& w = InternalAccess::world(sim);
    FlakePool& pool = w.resource<FlakePool>();
    for (std::uint32_t s = 0; s < 3000; s += 3) { // holes, as landings leave them
        pool.release(s);
    }
    const auto before = flakes_by_id(pool);
    std::map<std::uint32_t, std::uint32_t> old_slot;
    for (std::uint32_t s = 0; s < pool.slot_end; ++s) {
        if (pool.is_alive(s)) {
            old_slot[pool.id[s]] = s;
        }
    }
    const std::uint32_t alive = pool.alive;
    ASSERT_EQ(alive, 2000u);
    ASSERT_EQ(sim.tick_count() % flake_order_every, 0u);
    flake_order_system(w);

    EXPECT_EQ(pool.alive, alive);
    EXPECT_EQ(pool.slot_end, alive) << "packed: no hole below slot_end";
    for (std::uint32_t s = 0; s < alive; ++s) {
        ASSERT_TRUE(pool.is_alive(s)) << "slot " << s;
    }
    EXPECT_EQ(flakes_by_id(pool), before) << "every flake kept its data and id";
    expect_free_from(pool, alive);
    for (std::uint32_t s = 1; s < alive; ++s) {
        const std::uint32_t a = column_of(pool.px[s - 1], pool.pz[s - 1]);
        const std::uint32_t b = column_of(pool.px[s], pool.pz[s]);
        ASSERT_LE(a, b) << "slot " << s;
        if (a == b) {
            ASSERT_LT(old_slot[pool.id[s - 1]], old_slot[pool.id[s]]) << "stable, slot " << s;
        }
    }
    // The free slots come out lowest first, each once.
    EXPECT_EQ(pool.free_stack.size(), pool.capacity() - alive);
    std::vector<std::uint32_t> got;
    std::uint32_t slot = 0;
    while (pool.acquire(slot)) {
        got.push_back(slot);
    }
    ASSERT_EQ(got.size(), pool.capacity() - alive);
    for (std::size_t k = 0; k < got.size(); ++k) {
        ASSERT_EQ(got[k], alive + k);
    }
    // Again with fewer flakes: the buffers the first ordering traded away
    // come back as pool arrays, and their old flakes must not show.
    for (const std::uint32_t s : got) {
        pool.release(s);
    }
    for (std::uint32_t s = 0; s < alive; s += 2) {
        pool.release(s);
    }
    const auto fewer = flakes_by_id(pool);
    flake_order_system(w);
    EXPECT_EQ(pool.alive, alive / 2);
    EXPECT_EQ(flakes_by_id(pool), fewer);
    expect_free_from(pool, pool.alive);
}

INSTANTIATE_TEST_SUITE_P(OneAndTwo, FlakeOrderThreads, ::testing::Values(1u, 2u));

TEST(FlakeOrder, RestoreAcrossAnOrderingTickReplaysExactly) {
    // The sample yard, snowing, orders its pool at ticks 64 and 128.
    YardOptions o;
    o.prefill = 5000;
    auto a = make_yard(o);
    auto b = make_yard(o);
    a->run(50);
    b->run(50);
    const auto snap = save_snapshot(*b);
    b->run(40);
    restore_snapshot(*b, *snap);
    a->run(100);
    b->run(100);
    EXPECT_EQ(a->state_hash(), b->state_hash());
    EXPECT_GT(flake_pool(*a).alive, 0u);
}

} // namespace
} // namespace snow
