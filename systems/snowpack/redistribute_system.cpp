// redistribute: the Laplacian cap of [WF §3]. Where a cell stands more
// than the cap above its neighbours (n·h_c − Σh_nb > limit, in integer levels),
// snow moves from it to its lower neighbours.
//
// [WF §4, §6] reports blow-ups when snow lands faster than one smoothing
// step per tick can spread it. Here a tick sub-iterates until no snow moves
// (or an iteration cap, then it goes on next tick), and every step is a
// two-buffer (Jacobi) update whose per-edge flow is at most 1/8 of the height
// difference: each cell's new level is a convex combination of the old levels
// around it, so no new maximum or minimum appears, there is no sweep-direction
// bias, and integer units keep the mass exact.
//
// Work follows the snow, not the surface: the grid is cut into 8×8 tiles. The
// first step of a tick evaluates, per tile, the box of the cells marked dirty
// since the last tick (SnowSurface::mark_dirty) and their neighbours; each
// later step the box of cells whose inputs changed in the step before or that
// still send snow. Scattered landings therefore cost per landing, and a pile
// costs by the area it spreads over, whatever the surface's size (issue #8).
#include "systems/api/systems.hpp"
#include "systems/core/jobs.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>

namespace snow {

namespace {

/// Largest share of a height difference one edge may carry per step (1/8):
/// four edges then move at most half a cell's difference, so the update is
/// monotone (no checkerboard oscillation) as well as bounded.
constexpr std::int64_t edge_divisor = 8;
/// Tiles are the surface's dirty tiles, 2^tile_shift cells on a side.
constexpr std::uint32_t tile_shift = dirty_tile_shift;
constexpr std::uint32_t tile_cells = 1u << tile_shift;

__extension__ using wide = __int128; // q·d products of 50-bit levels

using Box = CellBox;

/// A tile and the cells of it one step evaluates.
struct TileWork {
    std::uint32_t tile;
    Box cells;
};

/// World resource, sized to the largest surface (prepare_redistribute).
/// Between steps `delta` is all zero and `box` all empty.
struct RedistributeScratch {
    Vector<std::int64_t> delta;          ///< net change per cell of one step
    Vector<Box> box;                     ///< per tile: cells to evaluate next step
    Vector<std::uint8_t> touched;        ///< per tile: listed in touched_tiles
    Vector<TileWork> active;             ///< this step's work
    Vector<std::uint32_t> next;          ///< tiles with a non-empty box
    Vector<std::uint32_t> touched_tiles; ///< tiles whose cells got a delta
    Vector<std::uint8_t> scan_flags;     ///< scan_step: per cell, may send (flag_row)

    void fit(std::size_t cells, std::size_t tiles) {
        if (delta.size() < cells) {
            delta.resize(cells, 0);
            scan_flags.resize(cells);
        }
        if (box.size() < tiles) {
            box.resize(tiles);
            touched.resize(tiles, 0);
            active.reserve(tiles);
            next.reserve(tiles);
            touched_tiles.reserve(tiles);
        }
    }
};

/// Tile bookkeeping of one surface for one tick.
struct TileGrid {
    const SnowSurface& s;
    RedistributeScratch& r;
    std::uint32_t tx; ///< tiles per row

    /// Cell (ix, iz) is evaluated next step.
    void want(std::uint32_t ix, std::uint32_t iz) {
        const std::uint32_t t = s.tile_of(ix, iz);
        if (r.box[t].empty()) {
            r.next.push_back(t);
        }
        r.box[t].include(ix, iz);
    }
    /// Every cell of `b` (inside the grid) is evaluated next step.
    void want_box(const Box& b) {
        for (std::uint32_t tz = b.z0 >> tile_shift; tz <= b.z1 >> tile_shift; ++tz) {
            for (std::uint32_t tx0 = b.x0 >> tile_shift; tx0 <= b.x1 >> tile_shift; ++tx0) {
                const std::uint32_t t = tz * tx + tx0;
                if (r.box[t].empty()) {
                    r.next.push_back(t);
                }
                r.box[t].include(std::max(b.x0, tx0 << tile_shift),
                                 std::max(b.z0, tz << tile_shift));
                r.box[t].include(std::min(b.x1, ((tx0 + 1) << tile_shift) - 1),
                                 std::min(b.z1, ((tz + 1) << tile_shift) - 1));
            }
        }
    }
    /// Cell (ix, iz) changed: it and its neighbours see new inputs next step.
    void changed(std::uint32_t ix, std::uint32_t iz) {
        want(ix, iz);
        if (ix > 0) {
            want(ix - 1, iz);
        }
        if (ix + 1 < s.nx) {
            want(ix + 1, iz);
        }
        if (iz > 0) {
            want(ix, iz - 1);
        }
        if (iz + 1 < s.nz) {
            want(ix, iz + 1);
        }
    }
    void touch(std::size_t cell) {
        const std::uint32_t t = s.tile_of(static_cast<std::uint32_t>(cell % s.nx),
                                          static_cast<std::uint32_t>(cell / s.nx));
        if (r.touched[t] == 0) {
            r.touched[t] = 1;
            r.touched_tiles.push_back(t);
        }
    }
    /// Moves the next-step boxes into `active` (emptying them).
    void take_next() {
        r.active.clear();
        for (const std::uint32_t t : r.next) {
            r.active.push_back({t, r.box[t]});
            r.box[t] = Box{};
        }
        r.next.clear();
    }
};

/// Flows out of cell (ix, iz) for one step, added to `delta` (indexed by
/// cell); returns the units it sends and touches the cells it writes.
/// Reads only `s` (the old levels).
std::int64_t cell_outflow(TileGrid& g, std::uint32_t ix, std::uint32_t iz) {
    const SnowSurface& s = g.s;
    const std::size_t c = s.index(ix, iz);
    const std::int64_t have = s.snow[c];
    if (have == 0) {
        return 0; // bare cells have nothing to give, whatever their base shape
    }
    std::size_t nb[4];
    const std::uint32_t n = s.neighbours(ix, iz, nb);
    const std::int64_t h = s.level(c);
    std::int64_t d[4];
    std::int64_t sum = 0, lower_sum = 0, steepest = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        d[k] = h - s.level(nb[k]);
        sum += d[k];
        lower_sum += d[k] > 0 ? d[k] : 0;
        steepest = std::max(steepest, d[k]);
    }
    // [WF §3]: n·h_c − Σh_nb (the discrete Laplacian, grid edges use the neighbours they have).
    const std::int64_t excess = sum - s.laplacian_limit_units;
    const std::int64_t talus = s.talus_units;
    // Without an angle of repose nothing moves below the cap, nor over
    // edges whose 1/8 rounds to nothing.
    if (talus == 0 && (excess <= 0 || steepest < edge_divisor)) {
        return 0;
    }
    // Moving q units off the cell lowers its own excess by (n + 1)·q.
    const std::int64_t q = excess > 0 ? (excess + n) / (n + 1) : 0;
    std::int64_t f[4] = {0, 0, 0, 0};
    std::int64_t total = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        if (d[k] <= 0) {
            continue;
        }
        // Share of q in proportion to the drop, rounded up; a step steeper
        // than the angle of repose sends what stands above it; capped per edge.
        auto share = static_cast<std::int64_t>((wide{q} * d[k] + lower_sum - 1) / lower_sum);
        share = talus > 0 && d[k] > talus ? std::max(share, d[k] - talus) : share;
        f[k] = std::min(share, d[k] / edge_divisor);
        total += f[k];
    }
    if (total > have) {
        // Never take more than the cell holds; scaling down keeps every edge within its cap.
        std::int64_t scaled = 0;
        for (std::uint32_t k = 0; k < n; ++k) {
            f[k] = static_cast<std::int64_t>(wide{f[k]} * have / total);
            scaled += f[k];
        }
        total = scaled;
    }
    if (total == 0) {
        return 0;
    }
    std::int64_t* delta = g.r.delta.data();
    delta[c] -= total;
    g.touch(c);
    for (std::uint32_t k = 0; k < n; ++k) {
        delta[nb[k]] += f[k];
        g.touch(nb[k]);
    }
    return total;
}

/// Applies and clears the deltas of one tile; changed cells schedule
/// themselves and their neighbours for the next step.
void apply_tile(TileGrid& g, SnowSurface& s, std::uint32_t t) {
    const std::uint32_t bx = (t % g.tx) << tile_shift;
    const std::uint32_t bz = (t / g.tx) << tile_shift;
    const std::uint32_t ex = std::min(bx + tile_cells, s.nx);
    const std::uint32_t ez = std::min(bz + tile_cells, s.nz);
    std::int64_t* delta = g.r.delta.data();
    for (std::uint32_t iz = bz; iz < ez; ++iz) {
        for (std::uint32_t ix = bx; ix < ex; ++ix) {
            const std::size_t c = s.index(ix, iz);
            if (delta[c] != 0) {
                s.snow[c] = static_cast<std::uint32_t>(s.snow[c] + delta[c]);
                if (delta[c] < 0) {
                    s.fit_compaction(c);
                }
                delta[c] = 0;
                g.changed(ix, iz);
            }
        }
    }
}

/// Second half of a step: applies the deltas of every touched tile.
void apply_touched(TileGrid& g, SnowSurface& s) {
    for (const std::uint32_t t : g.r.touched_tiles) {
        g.r.touched[t] = 0;
        apply_tile(g, s, t);
    }
    g.r.touched_tiles.clear();
}

/// A cell that sent snow stays wanted (it may still have excess), so no
/// flowing cell is ever dropped; when nothing moved, nothing is wanted.
void visit(TileGrid& g, std::uint32_t ix, std::uint32_t iz) {
    if (cell_outflow(g, ix, iz) > 0) {
        g.want(ix, iz);
    }
}

/// Whether flag_row's test holds on this surface: every edge open, so only a
/// cell over the cap with a neighbour at least edge_divisor levels lower
/// (each edge carries at most 1/8 of its drop, rounded down), or with a step
/// steeper than the angle of repose, can send.
bool prefiltered(const SnowSurface& s) {
    return s.closed.empty();
}

/// The interior columns of a box's rows (1 <= x0, x1 + 1 < nx): flag_row's range.
struct Interior {
    std::uint32_t x0, x1;
    bool any;
};
Interior interior(const SnowSurface& s, const Box& b) {
    const std::uint32_t x0 = std::max(b.x0, 1u);
    const std::uint32_t x1 = std::min(b.x1, s.nx - 2);
    return {x0, x1, s.nx >= 3 && x0 <= x1};
}

/// The levels of a surface's cells read straight from its arrays, for the
/// prefilter of a prefiltered() surface and for prefetching on any:
/// `Packed`, it holds compacted snow, which lowers the levels;
/// `Uniform`, every base level is the same (SnowSurface::uniform_base), so
/// the differences the prefilter takes are those of the snow alone and the
/// base array (twice the snow's bytes) is not read.
template <bool Packed, bool Uniform>
struct Levels {
    const std::int64_t* base;
    const std::uint32_t* snow;
    const std::uint32_t* packed;
    std::size_t nx;
    std::int64_t limit;
    std::int64_t talus; ///< the angle of repose's step; never reached without one

    explicit Levels(const SnowSurface& s)
        : base(s.base_level.data()), snow(s.snow.data()), packed(s.compacted.data()), nx(s.nx),
          limit(s.laplacian_limit_units),
          talus(s.talus_units > 0 ? s.talus_units : std::numeric_limits<std::int64_t>::max()) {}
    /// The level of cell c, less the common base when Uniform.
    [[gnu::always_inline]] std::int64_t level(std::size_t c) const {
        const std::int64_t bottom = Uniform ? 0 : base[c];
        if constexpr (Packed) {
            return bottom + snow[c] - std::int64_t{packed[c]};
        } else {
            return bottom + snow[c];
        }
    }
    /// Starts loading what level(c) reads.
    void prefetch(std::size_t c) const {
        __builtin_prefetch(snow + c);
        if constexpr (!Uniform) {
            __builtin_prefetch(base + c);
        }
        if constexpr (Packed) {
            __builtin_prefetch(packed + c);
        }
    }
    /// Whether cell_outflow can move snow from interior cell c: it holds
    /// snow, and stands over the cap with a neighbour edge_divisor levels
    /// lower or has a step down steeper than the angle of repose. Selects
    /// only, so a loop of it vectorises.
    [[gnu::always_inline]] bool may_send(std::size_t c) const {
        const std::int64_t h = level(c);
        const std::int64_t l = level(c - 1), r = level(c + 1), d = level(c - nx), u = level(c + nx);
        const std::int64_t lower_lr = l < r ? l : r, lower_du = d < u ? d : u;
        const std::int64_t lowest = lower_lr < lower_du ? lower_lr : lower_du;
        const std::int64_t drop = h - lowest;
        return (snow[c] != 0) &
               (((4 * h - (l + r + d + u) > limit) & (drop >= edge_divisor)) | (drop > talus));
    }
};

/// Calls fn with the Levels that fit surface s.
template <typename Fn>
void with_levels(const SnowSurface& s, const Fn& fn) {
    const bool packed = !s.compacted.empty();
    if (s.uniform_base) {
        packed ? fn(Levels<true, true>(s)) : fn(Levels<false, true>(s));
    } else {
        packed ? fn(Levels<true, false>(s)) : fn(Levels<false, false>(s));
    }
}

/// Flags the interior cells x0..x1 of row iz (1 <= x0, x1 + 1 < nx,
/// 0 < iz < nz - 1) that Levels::may_send picks.
template <typename L>
void flag_row(const L& lv, std::size_t row, std::uint32_t x0, std::uint32_t x1,
              std::uint8_t* __restrict flags) {
    for (std::size_t ix = x0; ix <= x1; ++ix) {
        flags[ix] = lv.may_send(row + ix) ? 1 : 0;
    }
}

/// flag_row over the interior rows of `b` into flags (one byte per cell of
/// the surface). It only reads the surface, so the rows are split between
/// two tasks when the box is large; the flags are the same either way.
void flag_rows(World& w, const SnowSurface& s, const Box& b, std::uint8_t* flags) {
    const Interior in = interior(s, b);
    const std::uint32_t z0 = std::max(b.z0, 1u);
    const std::uint32_t z1 = std::min(b.z1, s.nz - 2);
    if (!in.any || z0 > z1) {
        return;
    }
    const std::uint32_t rows = z1 - z0 + 1;
    // In the units of for_tasks' threshold (a flake slot of a pass): a
    // scanned cell reads five cells' levels, about two slots' work, so large
    // boxes share the scan and small ones stay on one core
    // (docs/performance.md "Measurements the code relies on").
    for_tasks(w, 2, 2 * b.cells(), [&](std::size_t half) {
        const std::uint32_t first = z0 + static_cast<std::uint32_t>(half * rows / 2);
        const std::uint32_t last = z0 + static_cast<std::uint32_t>((half + 1) * rows / 2);
        with_levels(s, [&](const auto& lv) {
            for (std::uint32_t iz = first; iz < last; ++iz) {
                flag_row(lv, s.index(0, iz), in.x0, in.x1, flags + s.index(0, iz));
            }
        });
    });
}

/// Visits the flagged cells of `b` (flag_rows) and its cells on the grid's
/// edges, in row order.
void visit_flagged(TileGrid& g, const Box& b, const std::uint8_t* flags) {
    const SnowSurface& s = g.s;
    const Interior in = interior(s, b);
    for (std::uint32_t iz = b.z0; iz <= b.z1; ++iz) {
        const bool edge_row = iz == 0 || iz + 1 == s.nz;
        if (edge_row || !in.any) {
            for (std::uint32_t ix = b.x0; ix <= b.x1; ++ix) {
                visit(g, ix, iz);
            }
            continue;
        }
        if (b.x0 < in.x0) {
            visit(g, b.x0, iz); // column 0
        }
        // Eight flags per word: a row with nothing to move costs a few tests.
        const std::uint8_t* row = flags + s.index(0, iz);
        for (std::uint32_t j = in.x0; j <= in.x1; j += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, row + j, std::min<std::uint32_t>(8, in.x1 + 1 - j));
            for (; word != 0; word &= word - 1) {
                visit(g, j + static_cast<std::uint32_t>(std::countr_zero(word)) / 8, iz);
            }
        }
        if (b.x1 > in.x1) {
            visit(g, b.x1, iz); // column nx - 1
        }
    }
}

/// Visits the cells of a tile's box that may send snow, in row order: on a
/// prefiltered() surface the interior ones Levels::may_send picks (most of a
/// scattered landing's neighbours fail it, cheaper than cell_outflow's
/// general test), otherwise every cell.
template <typename L>
void visit_box(TileGrid& g, const L& lv, const Box& b) {
    const SnowSurface& s = g.s;
    const bool tested = prefiltered(s);
    for (std::uint32_t iz = b.z0; iz <= b.z1; ++iz) {
        const bool inner_row = iz > 0 && iz + 1 < s.nz;
        for (std::uint32_t ix = b.x0; ix <= b.x1; ++ix) {
            const bool inner = tested && inner_row && ix > 0 && ix + 1 < s.nx;
            if (!inner || lv.may_send(s.index(ix, iz))) {
                visit(g, ix, iz);
            }
        }
    }
}

/// Boxes ahead of the one visited whose cells are prefetched: scattered
/// landings' boxes lie far apart in a surface larger than the cache, and
/// the flake pass has just streamed the pool through it.
constexpr std::size_t prefetch_ahead = 4;

/// One Jacobi step over the boxes wanted by the previous step.
void smooth_step(TileGrid& g, SnowSurface& s) {
    g.take_next();
    with_levels(s, [&](const auto& lv) {
        const Vector<TileWork>& boxes = g.r.active;
        for (std::size_t k = 0; k < boxes.size(); ++k) {
            if (k + prefetch_ahead < boxes.size()) {
                const Box& b = boxes[k + prefetch_ahead].cells;
                const std::uint32_t last = std::min(b.z1 + 1, s.nz - 1);
                for (std::uint32_t iz = b.z0 > 0 ? b.z0 - 1 : 0; iz <= last; ++iz) {
                    lv.prefetch(s.index(b.x0, iz));
                    lv.prefetch(s.index(b.x1, iz));
                }
            }
            visit_box(g, lv, boxes[k].cells);
        }
    });
    apply_touched(g, s);
}

/// The first step of a tick when the marked tiles' boxes cover much of the
/// marked rectangle `b`: one scan of it (flag_rows on both cores when it is
/// large), cheaper than box by box.
void scan_step(World& w, TileGrid& g, SnowSurface& s, const Box& b) {
    flag_rows(w, s, b, g.r.scan_flags.data());
    visit_flagged(g, b, g.r.scan_flags.data());
    apply_touched(g, s);
}

/// Cells the first step would visit box by box: the marked boxes and their
/// neighbours.
std::size_t marked_area(const SnowSurface& s) {
    std::size_t area = 0;
    for (const std::uint32_t t : s.dirty_tiles) {
        area += s.tile_dirty[t].grown(s.nx, s.nz).cells();
    }
    return area;
}

} // namespace

void prepare_redistribute(World& w) {
    if (w.count<SnowSurface>() == 0) {
        return;
    }
    auto* scratch = w.try_resource<RedistributeScratch>();
    if (scratch == nullptr) {
        scratch = &w.set_resource<RedistributeScratch>();
    }
    for (const SnowSurface& s : w.pool<SnowSurface>().components()) {
        scratch->fit(s.cell_count(), static_cast<std::size_t>(s.tiles_x()) * s.tiles_z());
    }
}

void redistribute_system(World& w) {
    prepare_redistribute(w);
    auto& surfaces = w.pool<SnowSurface>().components();
    auto& counters = w.resource<SimCounters>();
    // Sub-iterations per surface per tick; a pile still moving after that
    // keeps its cells marked and continues next tick.
    const std::uint32_t max_iterations = w.resource<SimConfig>().smoothing_iterations;
    auto* scratch = &w.resource<RedistributeScratch>();
    for (SnowSurface& s : surfaces) {
        if (s.dirty_empty()) {
            continue;
        }
        TileGrid g{s, *scratch, s.tiles_x()};
        // First step: the cells whose cap may now fail, the marked ones and
        // their neighbours; per tile, or in one scan when most tiles are marked.
        ++counters.smoothing_iterations;
        // A scan visits the whole rectangle: worth it only where its
        // prefilter holds and the boxes cover much of it (a scanned cell
        // costs a few times less than one of a box).
        const Box r = Box{s.dirty_x0, s.dirty_z0, s.dirty_x1, s.dirty_z1}.grown(s.nx, s.nz);
        if (prefiltered(s) && 4 * marked_area(s) >= r.cells()) {
            s.clear_dirty();
            scan_step(w, g, s, r);
        } else {
            for (const std::uint32_t t : s.dirty_tiles) {
                g.want_box(s.tile_dirty[t].grown(s.nx, s.nz));
            }
            s.clear_dirty();
            smooth_step(g, s);
        }
        for (std::uint32_t it = 1; it < max_iterations && !scratch->next.empty(); ++it) {
            ++counters.smoothing_iterations;
            smooth_step(g, s);
        }
        // Still moving after the cap: the wanted cells carry over as dirty
        // cells. Flows never raise the highest level, so level_bound stays valid.
        for (const std::uint32_t t : scratch->next) {
            const Box b = scratch->box[t]; // within tile t: its two corners mark it all
            s.mark_dirty(b.x0, b.z0);
            s.mark_dirty(b.x1, b.z1);
            scratch->box[t] = Box{};
        }
        scratch->next.clear();
    }
}

} // namespace snow
