// deposit: a flake that reached the snow top of a surface becomes snow there
// ([WF §4]: the height field grows by the flake's mass), then rolls at most
// one cell by the deposition rules of [ZCL §IV].
//
// Detection runs in parallel over fixed chunks of flake slots, block by block
// (flake_stages.hpp): it reads the surfaces, writes landing records (with the
// roll target by the levels the tick began with) and parks each landed
// flake's own slot. The records are applied in slot order afterwards, each on
// the snow the ones before it left, so the result is the same for any thread
// count.
#include "ecs/rng.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/jobs.hpp"
#include "systems/core/random_streams.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/source_versions.hpp"
#include "systems/flakes/deposit_bins.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/flakes/flake_stages.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

namespace {

struct LandingRecord {
    std::uint32_t slot;
    std::uint32_t surface; ///< dense index in the SnowSurface pool
    std::uint32_t cell;
    /// The flake's id and mass, read while its block is in cache: applying
    /// the landings (deposit_end, one thread) would otherwise miss on both.
    std::uint32_t id;
    std::uint32_t units;
    /// Where it rolls (roll_target) by the levels as they stood when the
    /// pass began: deposit_end keeps it unless an earlier landing of the
    /// tick changed a cell the rule reads.
    std::uint32_t target;
};

} // namespace

/// World resource: the prefilter bins, one landing buffer per chunk of
/// flake_grain slots (room for every slot of it, cleared every tick), and
/// what a detection block reads this tick.
struct DepositTick {
    DepositBins bins;
    mutable Vector<Vector<LandingRecord>> chunks; ///< each written by its chunk's blocks
    /// Per chunk: the slots its bin test passed this tick (each written by
    /// its chunk's blocks).
    mutable Vector<std::uint32_t> passed;
    std::uint64_t scanned = 0; ///< slots this tick's blocks cover
    /// Last tick's bin test passed at most 1 slot in sparse_share: the pass
    /// then shares collide's prefilter (every flake it lists costs a second
    /// test, which pays only while they are few).
    bool sparse = false;
    FlakePool* pool = nullptr; ///< a block parks the flakes it lands (each its own slots)
    const SnowSurface* surfaces = nullptr;
    std::uint64_t seed = 0;
    std::uint64_t tick = 0;
    /// deposit_end's: per surface, per dirty tile, the last application
    /// (`applied`) that added snow to one of its cells (sized by prepare_deposit).
    mutable Vector<Vector<std::uint64_t>> touched;
    mutable std::uint64_t applied = 0;
};

namespace {

/// See DepositTick::sparse: sharing pays where few slots pass the bin test
/// (the yard benchmark) and costs where many do (the village); the counts
/// and times are in docs/performance.md.
constexpr std::uint64_t sparse_share = 50;

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

/// The surface flake `slot` lands on this tick, if any: it reached the snow
/// top from above (crossed it this tick, sits on it, or is inside the snow
/// layer). A flake below a surface's bare top never lands on it. The highest
/// such surface wins (its index and cell go to `rec`); ties go to the first
/// in pool order.
bool find_landing(const DepositTick& p, std::uint32_t bin, std::uint32_t slot, float y_start,
                  LandingRecord& rec) {
    const FlakePool& f = *p.pool;
    const DepositBins& d = p.bins;
    const float x = f.px[slot], y = f.py[slot], z = f.pz[slot];
    float best = -std::numeric_limits<float>::infinity();
    bool found = false;
    for (std::uint32_t k = d.bin_start[bin]; k < d.bin_start[bin + 1]; ++k) {
        const std::uint32_t si = d.bin_items[k];
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
        const bool from_above = y <= top && std::max(y, y_start) >= bare - landing_tolerance;
        if ((on_top || from_above) && top > best) {
            best = top;
            found = true;
            rec.surface = si;
            rec.cell = static_cast<std::uint32_t>(c);
        }
    }
    return found;
}

/// The next slot of `removed` at or after `slot` is `slot` (advancing `next`).
bool skipped(std::span<const std::uint32_t> removed, std::size_t& next, std::uint32_t slot) {
    while (next < removed.size() && removed[next] < slot) {
        ++next;
    }
    return next < removed.size() && removed[next] == slot;
}

/// Starts loading what the deposition rules read of cell c.
void prefetch_cell(const SnowSurface& s, std::size_t c) {
    __builtin_prefetch(s.base_level.data() + c);
    __builtin_prefetch(s.snow.data() + c);
    if (!s.compacted.empty()) {
        __builtin_prefetch(s.compacted.data() + c);
    }
}

/// Starts loading what find_landing and roll_target read for a flake at
/// (x, z) in `bin`: the cell of each surface of the bin under it and its
/// neighbours. The few flakes of a block that may land lie scattered over
/// cells its other flakes never touch, so each would wait for its cells in
/// turn; loaded a block ahead, the waits overlap with other work.
void prefetch_landing(const DepositTick& p, std::uint32_t bin, float x, float z) {
    const DepositBins& d = p.bins;
    for (std::uint32_t k = d.bin_start[bin]; k < d.bin_start[bin + 1]; ++k) {
        const SnowSurface& s = p.surfaces[d.bin_items[k]];
        std::uint32_t ix = 0, iz = 0;
        if (!s.cell_at(x, z, ix, iz)) {
            continue;
        }
        // The cell and the rows above and below it (roll_target's neighbours).
        for (const std::uint32_t row : {iz > 0 ? iz - 1 : iz, iz, iz + 1 < s.nz ? iz + 1 : iz}) {
            prefetch_cell(s, s.index(ix, row));
        }
    }
}

} // namespace

/// Detection over slots [b, e), first half. The bins' branch-free pass over
/// positions flags flakes low enough to land on some surface under them (or,
/// with `shared`, the same test on the slots the pass's shared prefilter
/// listed: every flake it would flag is among them); those that may land are
/// listed, and what their exact test will read starts loading.
void deposit_list(const DepositTick& p, std::size_t chunk, const PathStarts& st, std::size_t b,
                  std::size_t e, std::span<const std::uint32_t> removed,
                  const BlockCandidates* shared, DepositCandidates& out) {
    const DepositBins& d = p.bins;
    const float* px = p.pool->px.data();
    const float* py = p.pool->py.data();
    const float* pz = p.pool->pz.data();
    out.count = 0;
    std::size_t next_removed = 0;
    // A flake the bin test passed, over `bin`.
    const auto list = [&](std::uint32_t slot, std::uint32_t bin) {
        if (d.may_land(py[slot], st.y[slot - st.base]) && p.pool->mass_units[slot] != 0 &&
            !skipped(removed, next_removed, slot)) {
            prefetch_landing(p, bin, px[slot], pz[slot]);
            __builtin_prefetch(p.pool->id.data() + slot);
            out.slots[out.count] = slot;
            out.bins[out.count++] = bin;
        }
    };
    std::uint32_t& passed = p.passed[chunk];
    if (shared != nullptr) {
        for (std::size_t k = 0; k < shared->count; ++k) {
            const std::uint32_t slot = shared->slots[k];
            std::uint32_t bin = 0;
            if (d.grid.under_top(px[slot], py[slot], pz[slot], d.bin_top.data(), bin)) {
                ++passed;
                list(slot, bin);
            }
        }
        return;
    }
    alignas(64) std::uint8_t flag[flake_block];
    const std::size_t m = e - b;
    flag_deposit_candidates(d, px + b, py + b, pz + b, m, flag);
    std::uint32_t flagged[flake_block];
    const std::uint32_t count = list_flagged(flag, m, b, flagged);
    passed += count;
    for (std::uint32_t k = 0; k < count; ++k) {
        const std::uint32_t slot = flagged[k];
        std::uint32_t bin = 0;
        (void)d.grid.bin_of(px[slot], pz[slot], bin); // flagged: over a bin
        list(slot, bin);
    }
}

/// Second half: the exact test of each listed flake against the start of
/// its path this tick; a landing is recorded (with its roll target) and its
/// flake parked.
void deposit_land(const DepositTick& p, std::size_t chunk, const PathStarts& st,
                  const DepositCandidates& listed) {
    Vector<LandingRecord>& out = p.chunks[chunk];
    for (std::size_t k = 0; k < listed.count; ++k) {
        const std::uint32_t slot = listed.slots[k];
        LandingRecord rec{slot, 0, 0, 0, p.pool->mass_units[slot], 0};
        if (find_landing(p, listed.bins[k], slot, st.y[slot - st.base], rec)) {
            rec.id = p.pool->id[slot];
            rec.target = static_cast<std::uint32_t>(roll_target(
                p.surfaces[rec.surface], rec.cell, {p.seed, p.tick, rec.id, random_stream::roll}));
            out.push_back(rec);
            p.pool->park(slot); // deposit_end frees it in slot order
        }
    }
}

bool deposit_prefilter_sparse(const World& w) {
    const auto* t = w.try_resource<DepositTick>();
    return t != nullptr && t->sparse;
}

const DepositBins& deposit_bins(const DepositTick& t) {
    return t.bins;
}

namespace {

/// Landings ahead of the one applied whose target cell deposit_end prefetches.
constexpr std::size_t landing_lookahead = 8;

/// Whether a landing applied since stamp `first` added snow to a tile that
/// holds cell c or one of its neighbours (the cells roll_target reads), so
/// the target the pass found may be stale. Tiles, not cells: the stamps stay
/// in cache; a stale-looking target is only recomputed.
bool changed_near(const SnowSurface& s, const Vector<std::uint64_t>& touched, std::uint64_t first,
                  std::size_t c) {
    const auto ix = static_cast<std::uint32_t>(c % s.nx);
    const auto iz = static_cast<std::uint32_t>(c / s.nx);
    const std::uint32_t x0 = ix > 0 ? ix - 1 : 0, x1 = std::min(ix + 1, s.nx - 1);
    const std::uint32_t z0 = iz > 0 ? iz - 1 : 0, z1 = std::min(iz + 1, s.nz - 1);
    for (const std::uint32_t t :
         {s.tile_of(x0, iz), s.tile_of(x1, iz), s.tile_of(ix, z0), s.tile_of(ix, z1)}) {
        if (touched[t] >= first) {
            return true;
        }
    }
    return false;
}

} // namespace

DepositTick* prepare_deposit(World& w) {
    auto* surface_pool = w.find_pool<SnowSurface>();
    if (surface_pool == nullptr || surface_pool->size() == 0) {
        return nullptr;
    }
    const auto& surfaces = surface_pool->components();
    const std::size_t capacity = w.resource<FlakePool>().capacity();
    auto* d = w.try_resource<DepositTick>();
    if (d == nullptr) {
        d = &w.set_resource<DepositTick>();
    }
    update_deposit_bins(d->bins, surfaces, source_versions(w).surfaces);
    // Buffers for the whole pool; work only up to slot_end. Each chunk has
    // room for all its slots to land in one tick.
    const std::size_t chunks = chunk_count(capacity, flake_grain);
    d->chunks.resize(chunks);
    for (std::size_t c = 0; c < chunks; ++c) {
        d->chunks[c].reserve(std::min(flake_grain, capacity - c * flake_grain));
    }
    d->passed.resize(chunks);
    d->touched.resize(surfaces.size());
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        const SnowSurface& s = surfaces[i];
        d->touched[i].resize(static_cast<std::size_t>(s.tiles_x()) * s.tiles_z(), d->applied);
    }
    return d;
}

DepositTick* deposit_begin(World& w) {
    auto& pool = w.resource<FlakePool>();
    DepositTick* d = pool.alive > 0 ? prepare_deposit(w) : nullptr;
    if (d == nullptr) {
        return nullptr;
    }
    for (auto& c : d->chunks) {
        c.clear();
    }
    // Last tick's share of slots that passed the bin test (the counts are
    // only a choice of path: both give the same landings).
    std::uint64_t passed = 0;
    for (const std::uint32_t n : d->passed) {
        passed += n;
    }
    d->sparse = d->scanned > 0 && passed * sparse_share <= d->scanned;
    std::fill(d->passed.begin(), d->passed.end(), 0u);
    d->scanned = pool.slot_end;
    d->pool = &pool;
    d->surfaces = w.find_pool<SnowSurface>()->components().data();
    d->seed = w.resource<SimConfig>().seed;
    d->tick = w.resource<SimClock>().tick;
    return d;
}

void deposit_end(World& w, const DepositTick& d) {
    auto& surfaces = w.pool<SnowSurface>().components();
    auto& pool = w.resource<FlakePool>();
    auto& counters = w.resource<SimCounters>();
    const std::uint64_t first = ++d.applied; // every stamp from before is older
    // Apply in chunk order = slot order: later landings see earlier ones' snow.
    for (const auto& chunk : d.chunks) {
        for (std::size_t k = 0; k < chunk.size(); ++k) {
            // The pass read these cells long ago: the target of a landing a
            // few ahead starts loading now.
            if (k + landing_lookahead < chunk.size()) {
                const LandingRecord& ahead = chunk[k + landing_lookahead];
                prefetch_cell(surfaces[ahead.surface], ahead.target);
            }
            const LandingRecord& r = chunk[k];
            SnowSurface& s = surfaces[r.surface];
            Vector<std::uint64_t>& touched = d.touched[r.surface];
            const std::size_t dst =
                changed_near(s, touched, first, r.cell)
                    ? roll_target(s, r.cell, {d.seed, d.tick, r.id, random_stream::roll})
                    : r.target;
            s.snow[dst] += r.units;
            s.mark_dirty(dst);
            touched[s.tile_of(static_cast<std::uint32_t>(dst % s.nx),
                              static_cast<std::uint32_t>(dst / s.nx))] = d.applied++;
            pool.free_parked(r.slot); // parked by deposit_land
            ++counters.landed;
            counters.rolled += dst != r.cell ? 1 : 0;
        }
    }
}

} // namespace snow
