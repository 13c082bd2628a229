// deposit: a flake that reached the snow top of a surface becomes snow there
// ([WF §4]: the height field grows by the flake's mass), then rolls at most
// one cell by the deposition rules of [ZCL §IV].
//
// Detection runs in parallel over fixed chunks of flake slots and only writes
// landing records; the records are applied in slot order afterwards, so the
// result is the same for any thread count.
#include "ecs/rng.hpp"
#include "systems/flake_pool.hpp"
#include "systems/integrator.hpp"
#include "systems/jobs.hpp"
#include "systems/random_streams.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"
#include "systems/wind.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace snow {

namespace {

/// Metres a flake may be off a snow top and still count as on it: the collide
/// system places flakes on tops, and tops are rounded to float.
constexpr float landing_tolerance = 1.0e-3f;
/// Resolution of the prefilter grid over the union of the surface rectangles.
constexpr float bins_per_side = 64.0f;

struct LandingRecord {
    std::uint32_t slot;
    std::uint32_t surface; ///< dense index in the SnowSurface pool
    std::uint32_t cell;
};

/// What the prefilter grid was built from; a change rebuilds it.
struct SurfaceKey {
    std::uint32_t entity;
    float x0, z0, cell;
    std::uint32_t nx, nz;
    std::uint64_t base_version;
    friend bool operator==(const SurfaceKey&, const SurfaceKey&) = default;
};

/// Placement of the prefilter grid: square bins over the union of the
/// surface rectangles plus one bin of margin.
struct BinGrid {
    float gx0 = 0.0f, gz0 = 0.0f, inv = 1.0f, fnx = 0.0f, fnz = 0.0f;
    std::uint32_t nbx = 0, nbz = 0;

    /// Bin of world (x, z), or false when outside the grid. Branch-free so the
    /// prefilter vectorises; monotone in x and in z.
    bool bin_of(float x, float z, std::uint32_t& bin) const {
        const float fx = (x - gx0) * inv;
        const float fz = (z - gz0) * inv;
        const bool in = (fx >= 0.0f) & (fz >= 0.0f) & (fx < fnx) & (fz < fnz);
        bin = in ? static_cast<std::uint32_t>(fz) * nbx + static_cast<std::uint32_t>(fx) : 0u;
        return in;
    }
    /// The same column / row computation, clamped into the grid.
    [[nodiscard]] std::uint32_t column(float x) const { return clamped((x - gx0) * inv, nbx); }
    [[nodiscard]] std::uint32_t row(float z) const { return clamped((z - gz0) * inv, nbz); }

  private:
    static std::uint32_t clamped(float f, std::uint32_t n) {
        return !(f >= 0.0f)                 ? 0u
               : f >= static_cast<float>(n) ? n - 1
                                            : static_cast<std::uint32_t>(f);
    }
};

/// World resource (a cache, rebuilt from the surfaces whenever they change).
/// A coarse XZ grid: each bin lists the surfaces overlapping it and the
/// highest y at which a flake over it can still land, so a flake far above
/// every surface costs one lookup.
///
/// Under a raised surface (a roof over the ground) the bin's highest y is the
/// roof's, yet a flake between the ground and the roof, not crossing the roof
/// this tick, can land on neither (flakes sliding down walls, [WF §4]).
/// Two scene-wide heights exclude it: every flake that lands on the lowest
/// surface of its bin is at or below `floor_top`; every flake that lands on
/// another one is, now or a tick ago, at or above `upper_bare`.
struct DepositScratch {
    std::vector<SurfaceKey> keys;
    std::vector<std::int64_t> bounds; ///< level_bound per surface when bin_top was built
    std::vector<float> min_bare;      ///< lowest bare top (m) per surface
    float floor_top = 0.0f;  ///< max over bins: highest y landing on the bin's lowest surface
    float upper_bare = 0.0f; ///< min over bins: lowest bare top of the others, less tolerance
    BinGrid grid;
    std::vector<float> bin_top;           ///< -inf where no surface
    std::vector<std::uint32_t> bin_start; ///< bin b lists bin_items[bin_start[b], bin_start[b+1])
    std::vector<std::uint32_t> bin_items; ///< surface indices, ascending
    std::vector<std::vector<LandingRecord>> chunks; ///< one buffer per chunk of flake_grain slots
};

/// Far end of a surface along one axis, a little past it: cell_at() accepts
/// x >= x0 exactly, and at most rounding past x0 + n·cell.
float far_edge(float x0, float cell, std::uint32_t n) {
    const double end = static_cast<double>(x0) + static_cast<double>(cell) * n;
    return static_cast<float>(end + 1.0e-4 * (std::abs(static_cast<double>(x0)) + cell * n) +
                              1.0e-6);
}

void rebuild_grid(DepositScratch& d, const std::vector<SnowSurface>& surfaces) {
    float ux0 = std::numeric_limits<float>::max(), uz0 = ux0;
    float ux1 = std::numeric_limits<float>::lowest(), uz1 = ux1;
    for (const SnowSurface& s : surfaces) {
        ux0 = std::min(ux0, s.x0);
        uz0 = std::min(uz0, s.z0);
        ux1 = std::max(ux1, far_edge(s.x0, s.cell, s.nx));
        uz1 = std::max(uz1, far_edge(s.z0, s.cell, s.nz));
    }
    const float bin = std::max({ux1 - ux0, uz1 - uz0, 1.0e-3f}) / bins_per_side;
    BinGrid& g = d.grid;
    g.inv = 1.0f / bin;
    g.gx0 = ux0 - bin;
    g.gz0 = uz0 - bin;
    g.nbx = static_cast<std::uint32_t>((ux1 - ux0) * g.inv) + 3;
    g.nbz = static_cast<std::uint32_t>((uz1 - uz0) * g.inv) + 3;
    g.fnx = static_cast<float>(g.nbx);
    g.fnz = static_cast<float>(g.nbz);
    const std::size_t bins = static_cast<std::size_t>(g.nbx) * g.nbz;

    // A flake cell_at() accepts lies in [x0, far_edge] and the bin computation
    // is monotone, so its bin lies in the bins of those two ends.
    auto for_each_bin = [&](const SnowSurface& s, auto&& fn) {
        const std::uint32_t bx1 = g.column(far_edge(s.x0, s.cell, s.nx));
        const std::uint32_t bz1 = g.row(far_edge(s.z0, s.cell, s.nz));
        for (std::uint32_t bz = g.row(s.z0); bz <= bz1; ++bz) {
            for (std::uint32_t bx = g.column(s.x0); bx <= bx1; ++bx) {
                fn(static_cast<std::size_t>(bz) * g.nbx + bx);
            }
        }
    };
    std::vector<std::uint32_t> count(bins + 1, 0);
    for (const SnowSurface& s : surfaces) {
        for_each_bin(s, [&](std::size_t b) { ++count[b + 1]; });
    }
    for (std::size_t b = 0; b < bins; ++b) {
        count[b + 1] += count[b];
    }
    d.bin_start = count;
    d.bin_items.assign(count[bins], 0);
    for (std::uint32_t i = 0; i < surfaces.size(); ++i) {
        for_each_bin(surfaces[i], [&](std::size_t b) { d.bin_items[count[b]++] = i; });
    }
    d.bin_top.assign(bins, -std::numeric_limits<float>::infinity());
    d.bounds.assign(surfaces.size(), std::numeric_limits<std::int64_t>::min());
    // Bare tops change only with base_version (part of the key); void cells catch nothing.
    d.min_bare.clear();
    for (const SnowSurface& s : surfaces) {
        std::int64_t lowest = std::numeric_limits<std::int64_t>::max();
        for (const std::int64_t b : s.base_level) {
            lowest = b != void_level ? std::min(lowest, b) : lowest;
        }
        d.min_bare.push_back(lowest == std::numeric_limits<std::int64_t>::max()
                                 ? std::numeric_limits<float>::infinity()
                                 : s.height(lowest));
    }
}

/// Raises bin tops to each surface's level_bound (plus tolerance), and
/// recomputes floor_top and upper_bare; only when a bound moved.
void refresh_tops(DepositScratch& d, const std::vector<SnowSurface>& surfaces) {
    bool changed = false;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        changed = changed || d.bounds[i] != surfaces[i].level_bound;
        d.bounds[i] = surfaces[i].level_bound;
    }
    if (!changed) {
        return;
    }
    constexpr float inf = std::numeric_limits<float>::infinity();
    d.floor_top = -inf;
    d.upper_bare = inf;
    for (std::size_t b = 0; b + 1 < d.bin_start.size(); ++b) {
        float top = -inf;
        std::uint32_t lowest = d.bin_start[b]; // the item with the lowest bare top (first on ties)
        for (std::uint32_t k = d.bin_start[b]; k < d.bin_start[b + 1]; ++k) {
            const SnowSurface& s = surfaces[d.bin_items[k]];
            top = std::max(top, s.height(s.level_bound) + 2.0f * landing_tolerance);
            lowest = d.min_bare[d.bin_items[k]] < d.min_bare[d.bin_items[lowest]] ? k : lowest;
        }
        d.bin_top[b] = top;
        for (std::uint32_t k = d.bin_start[b]; k < d.bin_start[b + 1]; ++k) {
            const std::uint32_t i = d.bin_items[k];
            if (k == lowest) {
                d.floor_top = std::max(d.floor_top, surfaces[i].height(surfaces[i].level_bound) +
                                                        2.0f * landing_tolerance);
            } else {
                d.upper_bare = std::min(d.upper_bare, d.min_bare[i] - 2.0f * landing_tolerance);
            }
        }
    }
}

/// Updates the cache to the current surfaces (pool order) and flake capacity.
void prepare(DepositScratch& d, World& w, const std::vector<SnowSurface>& surfaces,
             std::size_t chunk_count) {
    const auto& entities = w.pool<SnowSurface>().entities();
    bool same = d.keys.size() == surfaces.size();
    for (std::size_t i = 0; same && i < surfaces.size(); ++i) {
        const SnowSurface& s = surfaces[i];
        same = d.keys[i] == SurfaceKey{entities[i].bits, s.x0, s.z0, s.cell, s.nx, s.nz, s.base_version};
    }
    if (!same) {
        d.keys.clear();
        for (std::size_t i = 0; i < surfaces.size(); ++i) {
            const SnowSurface& s = surfaces[i];
            d.keys.push_back({entities[i].bits, s.x0, s.z0, s.cell, s.nx, s.nz, s.base_version});
        }
        rebuild_grid(d, surfaces);
    }
    refresh_tops(d, surfaces);
    if (d.chunks.size() != chunk_count) {
        d.chunks.resize(chunk_count);
        for (auto& c : d.chunks) {
            c.reserve(256);
        }
    }
}

/// Everything a detection chunk reads; passed by one pointer so the job
/// closure needs no allocation.
struct DetectPass {
    const DepositScratch* d;
    const FlakePool* pool;
    const SnowSurface* surfaces;
    float dt;
    Integrator integrator;
    float gravity_y;
    float wind_y;
    std::vector<std::vector<LandingRecord>>* out;
};

/// Height at which flake `slot` started this tick: where the integrator
/// really moved it from (the exact and RK4 rules move by the mean velocity),
/// as collide's swept tests use it.
float start_y(const DetectPass& p, std::uint32_t slot) {
    const FlakePool& f = *p.pool;
    return integrate::path_start(p.integrator, f.py[slot], f.vy[slot], f.k_over_m[slot],
                                 p.gravity_y, p.wind_y, p.dt);
}

/// The surface flake `slot` lands on this tick, if any: it reached the snow
/// top from above (crossed it this tick, sits on it, or is inside the snow
/// layer). A flake below a surface's bare top never lands on it. The highest
/// such surface wins; ties go to the first in pool order.
bool find_landing(const DetectPass& p, std::uint32_t bin, std::uint32_t slot, float y_prev,
                  LandingRecord& rec) {
    const FlakePool& f = *p.pool;
    const float x = f.px[slot], y = f.py[slot], z = f.pz[slot];
    float best = -std::numeric_limits<float>::infinity();
    bool found = false;
    for (std::uint32_t k = p.d->bin_start[bin]; k < p.d->bin_start[bin + 1]; ++k) {
        const std::uint32_t si = p.d->bin_items[k];
        const SnowSurface& s = p.surfaces[si];
        std::uint32_t ix = 0, iz = 0;
        if (!s.cell_at(x, z, ix, iz)) {
            continue;
        }
        const std::size_t c = s.index(ix, iz);
        const float top = s.top_y(c);
        const float bare = s.height(s.base_level[c]);
        const bool on_top = std::abs(y - top) <= landing_tolerance;
        // Reached the top this tick, or started it inside the snow layer (the
        // snow may have grown over a hovering flake): either way it lands.
        const bool from_above = y <= top && std::max(y, y_prev) >= bare - landing_tolerance;
        if ((on_top || from_above) && top > best) {
            best = top;
            found = true;
            rec = {slot, si, static_cast<std::uint32_t>(c)};
        }
    }
    return found;
}

/// False when a flake at y (y_prev a tick ago, from start_y)
/// can land on no surface: above every bin's lowest surface and below every
/// other bare top, not crossing one (flakes sliding down walls, [WF §4]).
/// One read of vy for a flagged flake instead of the surface lookups.
bool reaches(const DepositScratch& d, float y, float y_prev) {
    return y <= d.floor_top || y >= d.upper_bare || y_prev >= d.upper_bare;
}

/// Slots tested per prefilter block (a multiple of 8: flags are scanned 8 at a time).
constexpr std::size_t block = 512;

/// Detection over slots [b, e). A branch-free pass over positions (it
/// vectorises) flags flakes low enough to land on some surface under them;
/// only those get the exact test.
void detect_chunk(const DetectPass& p, std::size_t chunk, std::size_t b, std::size_t e) {
    const DepositScratch& d = *p.d;
    std::vector<LandingRecord>& out = (*p.out)[chunk];
    out.clear();
    const BinGrid g = d.grid; // a local copy: the flag stores cannot alias it
    const float* __restrict px = p.pool->px.data();
    const float* __restrict py = p.pool->py.data();
    const float* __restrict pz = p.pool->pz.data();
    const float* __restrict bin_top = d.bin_top.data();
    const float* vy = p.pool->vy.data();
    alignas(64) std::uint8_t flag[block];
    for (std::size_t base = b; base < e; base += block) {
        const std::size_t m = std::min(block, e - base);
        for (std::size_t j = 0; j < m; ++j) {
            std::uint32_t bin = 0;
            const bool in = g.bin_of(px[base + j], pz[base + j], bin);
            flag[j] = static_cast<std::uint8_t>(in & (py[base + j] <= bin_top[bin]));
        }
        std::fill(flag + m, flag + block, std::uint8_t{0});
        // reaches() reads vy, which the pass above did not stream: request the
        // flagged ones first, so their cache misses overlap.
        for (std::size_t j = 0; j < m; j += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, flag + j, sizeof word);
            for (; word != 0; word &= word - 1) {
                __builtin_prefetch(vy + base + j + std::countr_zero(word) / 8);
            }
        }
        for (std::size_t j = 0; j < m; j += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, flag + j, sizeof word);
            for (; word != 0; word &= word - 1) {
                const auto slot = static_cast<std::uint32_t>(base + j + std::countr_zero(word) / 8);
                const float y_prev = start_y(p, slot);
                if (!reaches(d, py[slot], y_prev)) {
                    continue;
                }
                std::uint32_t bin = 0;
                LandingRecord rec{};
                if (p.pool->mass_units[slot] != 0 && g.bin_of(px[slot], pz[slot], bin) &&
                    find_landing(p, bin, slot, y_prev, rec)) {
                    out.push_back(rec);
                }
            }
        }
    }
}

/// [ZCL §IV] deposition rules for snow arriving on cell c: no lower
/// neighbour -> stays (rule 1); otherwise one of the n lower neighbours with
/// probability 1/n each, which is 25% each when all four are equal and lower
/// (rule 2) and 1/n in general (rule 3). Returns the cell that receives it.
std::size_t roll_target(const SnowSurface& s, std::size_t c, const RngKey& key) {
    const auto ix = static_cast<std::uint32_t>(c % s.nx);
    const auto iz = static_cast<std::uint32_t>(c / s.nx);
    std::size_t nb[4];
    const std::uint32_t n = s.neighbours(ix, iz, nb);
    const std::int64_t h = s.level(c);
    std::size_t lower[4];
    std::uint32_t n_lower = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        if (s.level(nb[k]) < h) {
            lower[n_lower++] = nb[k];
        }
    }
    return n_lower == 0 ? c : lower[rng_below(key, 0, n_lower)];
}

} // namespace

void deposit_system(World& w) {
    auto& surfaces = w.pool<SnowSurface>().components();
    auto& pool = w.resource<FlakePool>();
    if (surfaces.empty() || pool.alive == 0) {
        return;
    }
    const auto& cfg = w.resource<SimConfig>();
    const std::uint64_t tick = w.resource<SimClock>().tick;
    auto& counters = w.resource<SimCounters>();
    auto* d = w.try_resource<DepositScratch>();
    if (d == nullptr) {
        d = &w.set_resource<DepositScratch>();
    }
    // Buffers for the whole pool (allocated once); work only up to slot_end.
    prepare(*d, w, surfaces, JobPool::chunk_count(pool.capacity(), flake_grain));
    const std::size_t n = pool.slot_end;

    const auto* wind = w.try_resource<Wind>();
    const DetectPass pass{d,
                          &pool,
                          surfaces.data(),
                          cfg.dt,
                          cfg.integrator,
                          cfg.gravity.y,
                          wind != nullptr ? wind->current.y : 0.0f,
                          &d->chunks};
    for_chunks(w, n, flake_grain, [p = &pass](std::size_t c, std::size_t b, std::size_t e) {
        detect_chunk(*p, c, b, e);
    });

    // Apply in chunk order = slot order: later landings see earlier ones' snow.
    // Only this tick's chunks: those past slot_end hold nothing from this tick.
    const std::size_t chunks = JobPool::chunk_count(n, flake_grain);
    for (std::size_t c = 0; c < chunks; ++c) {
        for (const LandingRecord& r : d->chunks[c]) {
            SnowSurface& s = surfaces[r.surface];
            const std::size_t dst =
                roll_target(s, r.cell, {cfg.seed, tick, r.slot, random_stream::roll});
            s.snow[dst] += pool.mass_units[r.slot];
            s.mark_dirty(static_cast<std::uint32_t>(dst % s.nx),
                         static_cast<std::uint32_t>(dst / s.nx));
            pool.release(r.slot);
            ++counters.landed;
            counters.rolled += dst != r.cell ? 1 : 0;
        }
    }
}

} // namespace snow
