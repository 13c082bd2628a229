// deposit_bins: the deposit system's prefilter grid over the surfaces.
#include "systems/flakes/deposit_bins.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

namespace {

/// Resolution of the grid over the union of the surface rectangles.
constexpr float bins_per_side = 64.0f;

/// Far end of a surface along one axis, a little past it: cell_at() accepts
/// x >= x0 exactly, and at most rounding past x0 + n·cell.
float far_edge(float x0, float cell, std::uint32_t n) {
    const double end = static_cast<double>(x0) + static_cast<double>(cell) * n;
    return static_cast<float>(end + 1.0e-4 * (std::abs(static_cast<double>(x0)) + cell * n) +
                              1.0e-6);
}

void rebuild(DepositBins& d, const Vector<SnowSurface>& surfaces) {
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
    // Counted, summed, then filled with bin_start[b] as bin b's cursor; the
    // cursors end one bin on, so the starts are shifted back. No buffer but
    // the bins' own: a cover's new base rebuilds them inside a tick.
    Vector<std::uint32_t>& start = d.bin_start;
    start.assign(bins + 1, 0);
    for (const SnowSurface& s : surfaces) {
        for_each_bin(s, [&](std::size_t b) { ++start[b + 1]; });
    }
    for (std::size_t b = 0; b < bins; ++b) {
        start[b + 1] += start[b];
    }
    d.bin_items.assign(start[bins], 0);
    for (std::uint32_t i = 0; i < surfaces.size(); ++i) {
        for_each_bin(surfaces[i], [&](std::size_t b) { d.bin_items[start[b]++] = i; });
    }
    for (std::size_t b = bins; b > 0; --b) {
        start[b] = start[b - 1];
    }
    start[0] = 0;
    d.bin_top.assign(bins, -std::numeric_limits<float>::infinity());
    d.bounds.assign(surfaces.size(), std::numeric_limits<std::int64_t>::min());
    // Bare tops change only with base_version (part of the key); void cells catch nothing.
    d.min_bare.clear();
    d.base_versions.clear();
    for (const SnowSurface& s : surfaces) {
        std::int64_t lowest = std::numeric_limits<std::int64_t>::max();
        for (const std::int64_t b : s.base_level) {
            lowest = b != void_level ? std::min(lowest, b) : lowest;
        }
        d.min_bare.push_back(lowest == std::numeric_limits<std::int64_t>::max()
                                 ? std::numeric_limits<float>::infinity()
                                 : s.height(lowest));
        d.base_versions.push_back(s.base_version);
    }
}

/// The bins' surfaces and bare tops are the current ones.
bool current(const DepositBins& d, const Vector<SnowSurface>& surfaces,
             std::uint64_t surfaces_version) {
    if (!d.built || d.surfaces_version != surfaces_version ||
        d.base_versions.size() != surfaces.size()) {
        return false;
    }
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        if (d.base_versions[i] != surfaces[i].base_version) {
            return false;
        }
    }
    return true;
}

/// Raises bin tops to each surface's level_bound (plus tolerance), and
/// recomputes floor_top and upper_bare; only when a bound moved.
void refresh_tops(DepositBins& d, const Vector<SnowSurface>& surfaces) {
    bool changed = false;
    for (std::size_t i = 0; i < surfaces.size(); ++i) {
        changed = changed || d.bounds[i] != surfaces[i].level_bound;
        d.bounds[i] = surfaces[i].level_bound;
    }
    if (!changed) {
        return;
    }
    ++d.tops_version;
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

} // namespace

void update_deposit_bins(DepositBins& bins, const Vector<SnowSurface>& surfaces,
                         std::uint64_t surfaces_version) {
    if (!current(bins, surfaces, surfaces_version)) {
        rebuild(bins, surfaces);
        bins.surfaces_version = surfaces_version;
        bins.built = true;
    }
    refresh_tops(bins, surfaces);
}

void flag_deposit_candidates(const DepositBins& bins, const float* __restrict px,
                             const float* __restrict py, const float* __restrict pz, std::size_t n,
                             std::uint8_t* __restrict flags) {
    const BinGrid g = bins.grid; // a local copy: the flag stores cannot alias it
    const float* __restrict bin_top = bins.bin_top.data();
    for (std::size_t j = 0; j < n; ++j) {
        std::uint32_t bin = 0;
        flags[j] = static_cast<std::uint8_t>(g.under_top(px[j], py[j], pz[j], bin_top, bin));
    }
}

} // namespace snow
