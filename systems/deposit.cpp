// deposit: a flake that reached the snow top of a surface becomes snow there
// (seed 002 §4: the height field grows by the flake's mass), then rolls at most
// one cell by the deposition rules of seed 003 §IV.
//
// Detection runs in parallel over fixed chunks of flake slots and only writes
// landing records; the records are applied in slot order afterwards, so the
// result is the same for any thread count.
#include "ecs/rng.hpp"
#include "systems/flake_pool.hpp"
#include "systems/jobs.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"

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
struct DepositScratch {
    std::vector<SurfaceKey> keys;
    std::vector<std::int64_t> bounds; ///< level_bound per surface when bin_top was built
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
}

/// Raises bin tops to each surface's level_bound (plus tolerance); only when a bound moved.
void refresh_tops(DepositScratch& d, const std::vector<SnowSurface>& surfaces) {
    bool changed = false;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        changed = changed || d.bounds[i] != surfaces[i].level_bound;
        d.bounds[i] = surfaces[i].level_bound;
    }
    if (!changed) {
        return;
    }
    for (std::size_t b = 0; b + 1 < d.bin_start.size(); ++b) {
        float top = -std::numeric_limits<float>::infinity();
        for (std::uint32_t k = d.bin_start[b]; k < d.bin_start[b + 1]; ++k) {
            const SnowSurface& s = surfaces[d.bin_items[k]];
            const auto y = static_cast<float>(static_cast<double>(s.level_bound) * s.unit_height);
            top = std::max(top, y + 2.0f * landing_tolerance);
        }
        d.bin_top[b] = top;
    }
}

/// Updates the cache to the current surfaces (pool order) and flake capacity.
void prepare(DepositScratch& d, World& w, const std::vector<SnowSurface>& surfaces,
             std::size_t chunk_count) {
    const auto& entities = w.pool<SnowSurface>().entities();
    bool same = d.keys.size() == surfaces.size();
    for (std::size_t i = 0; same && i < surfaces.size(); ++i) {
        const SnowSurface& s = surfaces[i];
        same = d.keys[i] == SurfaceKey{entities[i].bits, s.x0, s.z0, s.cell, s.nx, s.nz};
    }
    if (!same) {
        d.keys.clear();
        for (std::size_t i = 0; i < surfaces.size(); ++i) {
            const SnowSurface& s = surfaces[i];
            d.keys.push_back({entities[i].bits, s.x0, s.z0, s.cell, s.nx, s.nz});
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
    std::vector<std::vector<LandingRecord>>* out;
};

/// The surface flake `slot` lands on this tick, if any: it reached the snow
/// top from above (crossed it this tick, sits on it, or is inside the snow
/// layer). A flake below a surface's bare top never lands on it. The highest
/// such surface wins; ties go to the first in pool order.
bool find_landing(const DetectPass& p, std::uint32_t bin, std::uint32_t slot, LandingRecord& rec) {
    const FlakePool& f = *p.pool;
    const float x = f.px[slot], y = f.py[slot], z = f.pz[slot];
    const float y_prev = y - f.vy[slot] * p.dt;
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
        const auto bare = static_cast<float>(static_cast<double>(s.base_level[c]) * s.unit_height);
        const bool on_top = std::abs(y - top) <= landing_tolerance;
        const bool from_above =
            y <= top && (y_prev >= top - landing_tolerance || y >= bare - landing_tolerance);
        if ((on_top || from_above) && top > best) {
            best = top;
            found = true;
            rec = {slot, si, static_cast<std::uint32_t>(c)};
        }
    }
    return found;
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
    alignas(64) std::uint8_t flag[block];
    for (std::size_t base = b; base < e; base += block) {
        const std::size_t m = std::min(block, e - base);
        for (std::size_t j = 0; j < m; ++j) {
            std::uint32_t bin = 0;
            const bool in = g.bin_of(px[base + j], pz[base + j], bin);
            flag[j] = static_cast<std::uint8_t>(in & (py[base + j] <= bin_top[bin]));
        }
        std::fill(flag + m, flag + block, std::uint8_t{0});
        for (std::size_t j = 0; j < m; j += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, flag + j, sizeof word);
            for (; word != 0; word &= word - 1) {
                const auto slot = static_cast<std::uint32_t>(base + j + std::countr_zero(word) / 8);
                std::uint32_t bin = 0;
                LandingRecord rec{};
                if (p.pool->mass_units[slot] != 0 && g.bin_of(px[slot], pz[slot], bin) &&
                    find_landing(p, bin, slot, rec)) {
                    out.push_back(rec);
                }
            }
        }
    }
}

/// Seed 003 §IV deposition rules for snow arriving on cell c: no lower
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
    const std::size_t n = pool.capacity();
    prepare(*d, w, surfaces, JobPool::chunk_count(n, flake_grain));

    const DetectPass pass{d, &pool, surfaces.data(), cfg.dt, &d->chunks};
    for_chunks(w, n, flake_grain, [p = &pass](std::size_t c, std::size_t b, std::size_t e) {
        detect_chunk(*p, c, b, e);
    });

    // Apply in chunk order = slot order: later landings see earlier ones' snow.
    for (const auto& chunk : d->chunks) {
        for (const LandingRecord& r : chunk) {
            SnowSurface& s = surfaces[r.surface];
            const std::size_t dst = roll_target(s, r.cell, {cfg.seed, tick, r.slot, Stream::roll});
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
