// BM_SpeedOfLight (issue 16): the bare core of a tick in one pass and
// nothing else, on the project's own layout (a FlakePool's SoA arrays, fixed
// chunks of flake_grain slots on the JobPool), so one snow_bench run shows how
// far BM_SimTick is from the limit on any machine (docs/performance.md).
//
// Per tick, in L1-sized blocks of each chunk: explicit Euler with gravity and
// drag towards a steady wind ([WF §3], integrate::explicit_euler), x and z
// wrapped over a 16 m square, a bilinear test against the 512² snow tops at
// the cell centres, and one flag byte per slot; then, while the block is in
// cache, a scalar pass over the flagged (rare) slots records a deposit into
// the nearest cell and respawns the flake at the top (a draw keyed by seed,
// tick and slot). Deposits are applied per chunk in chunk order, in integer
// units ([WF §4]), so the tops are the same for any thread count. No
// colliders, no landing rules, no rolling, smoothing, spill or spawning.
#include "bench_scene.hpp"
#include "systems/api/simulation_internals.hpp"

#include "ecs/job_pool.hpp"
#include "ecs/rng.hpp"
#include "systems/core/jobs.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/core/units.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/flakes/integrator.hpp"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

namespace snow::bench {
namespace {

constexpr std::uint32_t side = 512;      ///< cells per side, as BM_SimTick's ground
constexpr float extent = 16.0f;          ///< metres per side
constexpr float origin = -0.5f * extent; ///< the square is [origin, origin + extent)²
constexpr float top_y = 10.0f;           ///< flakes respawn just below this height
constexpr float dt = 1.0f / 60.0f;       ///< s
constexpr float gravity = -9.81f;        ///< m/s²
constexpr float wind_x = 2.0f;           ///< m/s along +x, as the yard's
constexpr std::size_t block = 512;       ///< slots per block: 8 arrays × 2 KiB fit L1
constexpr std::uint64_t seed = 1;

/// The snow tops (m) at the cell centres and the integer snow under them.
struct Tops {
    float unit_height = 0.0f; ///< metres one mass unit adds to a cell
    std::vector<float> top;
    std::vector<std::uint32_t> snow;
};

struct Deposit {
    std::uint32_t cell;
    std::uint32_t units;
};

/// Everything a chunk job reads; the closure captures only a pointer to it.
struct Pass {
    FlakePool* pool;
    const float* top;
    Deposit* deposits;     ///< chunk c writes from c · flake_grain
    std::uint32_t* counts; ///< deposits per chunk
    std::uint64_t tick;
};

/// Moves the m slots of one block and flags those now below the snow top
/// under them. One branch-free loop over distinct arrays: it vectorises
/// (the four height taps are gathers).
void move_and_test(float* __restrict px, float* __restrict py, float* __restrict pz,
                   float* __restrict vx, float* __restrict vy, float* __restrict vz,
                   const float* __restrict kom, const std::uint32_t* __restrict mass,
                   const float* __restrict top, std::size_t m, std::uint8_t* __restrict hit) {
    constexpr float inv_cell = static_cast<float>(side) / extent;
    constexpr auto last = static_cast<int>(side) - 2;
    for (std::size_t i = 0; i < m; ++i) {
        const float c = kom[i];
        float x = px[i], y = py[i], z = pz[i], u = vx[i], v = vy[i], s = vz[i];
        integrate::explicit_euler(x, u, c, 0.0f, wind_x, dt);
        integrate::explicit_euler(y, v, c, gravity, 0.0f, dt);
        integrate::explicit_euler(z, s, c, 0.0f, 0.0f, dt);
        x = x < origin ? x + extent : x;
        x = x >= origin + extent ? x - extent : x;
        z = z < origin ? z + extent : z;
        z = z >= origin + extent ? z - extent : z;
        px[i] = x;
        py[i] = y;
        pz[i] = z;
        vx[i] = u;
        vy[i] = v;
        vz[i] = s;
        // Bilinear between the four cell centres around (x, z), clamped at the border.
        const float fx = (x - origin) * inv_cell - 0.5f;
        const float fz = (z - origin) * inv_cell - 0.5f;
        const int ix = std::min(std::max(static_cast<int>(fx), 0), last);
        const int iz = std::min(std::max(static_cast<int>(fz), 0), last);
        const float wx = std::min(std::max(fx - static_cast<float>(ix), 0.0f), 1.0f);
        const float wz = std::min(std::max(fz - static_cast<float>(iz), 0.0f), 1.0f);
        const int o = iz * static_cast<int>(side) + ix;
        const float near_row = top[o] + (top[o + 1] - top[o]) * wx;
        const float far_row = top[o + side] + (top[o + side + 1] - top[o + side]) * wx;
        hit[i] =
            static_cast<std::uint8_t>((mass[i] != 0) & (y < near_row + (far_row - near_row) * wz));
    }
}

/// The cell holding (x, z), clamped.
std::uint32_t cell_of(float x, float z) {
    constexpr float inv_cell = static_cast<float>(side) / extent;
    const auto ix = std::min(static_cast<std::uint32_t>((x - origin) * inv_cell), side - 1);
    const auto iz = std::min(static_cast<std::uint32_t>((z - origin) * inv_cell), side - 1);
    return iz * side + ix;
}

void run_chunk(const Pass& p, std::size_t chunk, std::size_t b, std::size_t e) {
    FlakePool& f = *p.pool;
    Deposit* out = p.deposits + chunk * flake_grain;
    std::uint32_t n = 0;
    alignas(64) std::uint8_t hit[block];
    for (std::size_t base = b; base < e; base += block) {
        const std::size_t m = std::min(block, e - base);
        move_and_test(f.px.data() + base, f.py.data() + base, f.pz.data() + base,
                      f.vx.data() + base, f.vy.data() + base, f.vz.data() + base,
                      f.k_over_m.data() + base, f.mass_units.data() + base, p.top, m, hit);
        std::fill(hit + m, hit + block, std::uint8_t{0});
        for (std::size_t j = 0; j < m; j += 8) { // 8 flags per word, in slot order
            std::uint64_t word = 0;
            std::memcpy(&word, hit + j, sizeof word);
            for (; word != 0; word &= word - 1) {
                const auto i = static_cast<std::uint32_t>(base + j + std::countr_zero(word) / 8);
                out[n++] = {cell_of(f.px[i], f.pz[i]), f.mass_units[i]};
                const RngKey key{seed, p.tick, i, random_stream::spawn_position};
                f.px[i] = origin + extent * rng_uniform(key, 0);
                f.pz[i] = origin + extent * rng_uniform(key, 1);
                f.py[i] = top_y - 0.5f * rng_uniform(key, 2);
                f.vx[i] = f.vy[i] = f.vz[i] = 0.0f;
            }
        }
    }
    p.counts[chunk] = n;
}

class SpeedOfLight {
  public:
    SpeedOfLight(std::uint32_t flakes, unsigned threads) : jobs_(threads) {
        pool_.reset(flakes);
        for (std::uint32_t n = 0; n < flakes; ++n) {
            std::uint32_t i = 0;
            (void)pool_.acquire(i);
            const RngKey key{seed, ~0ull, i, random_stream::spawn_position};
            // Terminal speeds of 0.5–1.5 m/s, as the yard's flakes (k/m = g / speed).
            pool_.k_over_m[i] = -gravity / rng_range(key, 0, 0.5f, 1.5f);
            pool_.px[i] = origin + extent * rng_uniform(key, 1);
            pool_.pz[i] = origin + extent * rng_uniform(key, 2);
            pool_.py[i] = top_y * rng_uniform(key, 3);
            pool_.vx[i] = wind_x;
            pool_.vy[i] = gravity / pool_.k_over_m[i];
            pool_.mass_units[i] = 1 + rng_below(key, 4, 40);
        }
        tops_.unit_height =
            static_cast<float>(unit_kg / (fresh_snow_density(SimConfig{}.air_temperature) *
                                          (extent / side) * (extent / side)));
        tops_.top.assign(static_cast<std::size_t>(side) * side, 0.0f);
        tops_.snow.assign(tops_.top.size(), 0);
        deposits_.resize(flakes);
        counts_.resize(chunk_count(flakes, flake_grain));
    }

    void tick() {
        const Pass pass{&pool_, tops_.top.data(), deposits_.data(), counts_.data(), tick_};
        const std::size_t n = pool_.slot_end;
        jobs_.parallel_for(chunk_count(n, flake_grain), [p = &pass, n](std::size_t c) {
            run_chunk(*p, c, c * flake_grain, std::min(n, (c + 1) * flake_grain));
        });
        for (std::size_t c = 0; c < counts_.size(); ++c) { // chunk order: slot order
            for (std::uint32_t k = 0; k < counts_[c]; ++k) {
                const Deposit& d = deposits_[c * flake_grain + k];
                tops_.snow[d.cell] += d.units;
                tops_.top[d.cell] = static_cast<float>(tops_.snow[d.cell]) * tops_.unit_height;
            }
        }
        ++tick_;
    }

    [[nodiscard]] std::uint32_t flakes() const { return pool_.alive; }

  private:
    JobPool jobs_;
    FlakePool pool_;
    Tops tops_;
    std::vector<Deposit> deposits_;
    std::vector<std::uint32_t> counts_;
    std::uint64_t tick_ = 0;
};

void speed_of_light(benchmark::State& state) {
    SpeedOfLight sol(static_cast<std::uint32_t>(state.range(0)),
                     static_cast<unsigned>(state.range(1)));
    for (int k = 0; k < 8; ++k) { // warm the caches and the pool's threads
        sol.tick();
    }
    FlakeClock clock;
    for (auto _ : state) {
        clock.time(sol.flakes(), [&] { sol.tick(); });
    }
    clock.report(state);
}

} // namespace

BENCHMARK(speed_of_light)->Name("BM_SpeedOfLight")->Apply([](benchmark::internal::Benchmark* b) {
    flake_args(b, {100000, 1000000});
});

} // namespace snow::bench
