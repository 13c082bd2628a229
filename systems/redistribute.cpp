// redistribute: the Laplacian cap of seed 002 §3. Where a cell stands more
// than the cap above its neighbours (n·h_c − Σh_nb > limit, in integer levels),
// snow moves from it to its lower neighbours.
//
// Seed 002 §4/§6 reports blow-ups when snow lands faster than one smoothing
// step per tick can spread it. Here a tick sub-iterates until no snow moves
// (or an iteration cap, then it goes on next tick), and every step is a
// two-buffer (Jacobi) update whose per-edge flow is at most 1/8 of the height
// difference: each cell's new level is a convex combination of the old levels
// around it, so no new maximum or minimum appears, there is no sweep-direction
// bias, and integer units keep the mass exact.
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace snow {

namespace {

/// Sub-iterations per surface per tick; a pile still moving after that keeps
/// its dirty rectangle and continues next tick.
constexpr int max_iterations = 64;
/// Largest share of a height difference one edge may carry per step (1/8):
/// four edges then move at most half a cell's difference, so the update is
/// monotone (no checkerboard oscillation) as well as bounded.
constexpr std::int64_t edge_divisor = 8;

__extension__ using wide = __int128; // q·d products of 50-bit levels

/// Inclusive cell rectangle; empty when x0 > x1.
struct Rect {
    std::uint32_t x0 = 1, z0 = 1, x1 = 0, z1 = 0;
    [[nodiscard]] bool empty() const { return x0 > x1 || z0 > z1; }
    [[nodiscard]] std::uint32_t width() const { return x1 - x0 + 1; }
    /// This rectangle grown by one cell, clipped to an nx × nz grid.
    [[nodiscard]] Rect grown(std::uint32_t nx, std::uint32_t nz) const {
        return {x0 > 0 ? x0 - 1 : 0, z0 > 0 ? z0 - 1 : 0, std::min(x1 + 1, nx - 1),
                std::min(z1 + 1, nz - 1)};
    }
    void include(std::uint32_t x, std::uint32_t z) {
        if (empty()) {
            *this = {x, z, x, z};
            return;
        }
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        z0 = std::min(z0, z);
        z1 = std::max(z1, z);
    }
};

/// World resource: the net change per cell of one step (the second buffer),
/// sized to the largest surface once.
struct RedistributeScratch {
    std::vector<std::int64_t> delta;
};

/// Flows out of cell (ix, iz) for one step, added to `delta` (indexed over
/// rect `wr`); returns the units it sends. Reads only `s` (the old levels).
std::int64_t cell_outflow(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz, const Rect& wr,
                          std::int64_t* delta) {
    const std::size_t c = s.index(ix, iz);
    const std::int64_t have = s.snow[c];
    if (have == 0) {
        return 0; // bare cells have nothing to give, whatever their base shape
    }
    std::size_t nb[4];
    const std::uint32_t n = s.neighbours(ix, iz, nb);
    const std::int64_t h = s.level(c);
    std::int64_t d[4];
    std::int64_t sum = 0, lower_sum = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        d[k] = h - s.level(nb[k]);
        sum += d[k];
        lower_sum += d[k] > 0 ? d[k] : 0;
    }
    // seed 002 §3: n·h_c − Σh_nb (the discrete Laplacian, grid edges use the neighbours they have).
    const std::int64_t excess = sum - s.laplacian_limit_units;
    if (excess <= 0) {
        return 0;
    }
    // Moving q units off the cell lowers its own excess by (n + 1)·q.
    const std::int64_t q = (excess + n) / (n + 1);
    std::int64_t f[4] = {0, 0, 0, 0};
    std::int64_t total = 0;
    for (std::uint32_t k = 0; k < n; ++k) {
        if (d[k] <= 0) {
            continue;
        }
        // Share of q in proportion to the drop, rounded up, capped per edge.
        const auto share = static_cast<std::int64_t>((wide{q} * d[k] + lower_sum - 1) / lower_sum);
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
    const std::uint32_t w = wr.width();
    auto at = [&](std::size_t cell) {
        const auto x = static_cast<std::uint32_t>(cell % s.nx) - wr.x0;
        const auto z = static_cast<std::uint32_t>(cell / s.nx) - wr.z0;
        return static_cast<std::size_t>(z) * w + x;
    };
    delta[at(c)] -= total;
    for (std::uint32_t k = 0; k < n; ++k) {
        delta[at(nb[k])] += f[k];
    }
    return total;
}

/// One Jacobi step over the cells of `active`; returns the cells that changed.
Rect smooth_step(SnowSurface& s, const Rect& active, std::vector<std::int64_t>& delta) {
    const Rect wr = active.grown(s.nx, s.nz);
    const std::uint32_t w = wr.width();
    std::fill_n(delta.begin(), static_cast<std::size_t>(w) * (wr.z1 - wr.z0 + 1), 0);
    std::int64_t moved = 0;
    for (std::uint32_t iz = active.z0; iz <= active.z1; ++iz) {
        for (std::uint32_t ix = active.x0; ix <= active.x1; ++ix) {
            moved += cell_outflow(s, ix, iz, wr, delta.data());
        }
    }
    Rect changed;
    if (moved == 0) {
        return changed;
    }
    for (std::uint32_t iz = wr.z0; iz <= wr.z1; ++iz) {
        for (std::uint32_t ix = wr.x0; ix <= wr.x1; ++ix) {
            const std::int64_t dv = delta[static_cast<std::size_t>(iz - wr.z0) * w + (ix - wr.x0)];
            if (dv != 0) {
                std::uint32_t& cell = s.snow[s.index(ix, iz)];
                cell = static_cast<std::uint32_t>(cell + dv);
                changed.include(ix, iz);
            }
        }
    }
    return changed;
}

} // namespace

void redistribute_system(World& w) {
    auto& surfaces = w.pool<SnowSurface>().components();
    auto& counters = w.resource<SimCounters>();
    auto* scratch = w.try_resource<RedistributeScratch>();
    if (scratch == nullptr) {
        scratch = &w.set_resource<RedistributeScratch>();
    }
    for (SnowSurface& s : surfaces) {
        if (s.dirty_empty() || s.nx == 0 || s.nz == 0) {
            continue;
        }
        if (scratch->delta.size() < s.cell_count()) {
            scratch->delta.resize(s.cell_count()); // once per larger surface (warm-up)
        }
        // Cells whose cap may now fail: the changed ones and their neighbours.
        Rect changed{s.dirty_x0, s.dirty_z0, std::min(s.dirty_x1, s.nx - 1),
                     std::min(s.dirty_z1, s.nz - 1)};
        for (int it = 0; it < max_iterations && !changed.empty(); ++it) {
            ++counters.smoothing_iterations;
            changed = smooth_step(s, changed.grown(s.nx, s.nz), scratch->delta);
        }
        // Flows never raise the highest level, so level_bound stays valid.
        s.dirty_x0 = changed.x0;
        s.dirty_z0 = changed.z0;
        s.dirty_x1 = changed.x1;
        s.dirty_z1 = changed.z1;
    }
}

} // namespace snow
