// carve: a body that sinks into snow pushes the snow above its lowest point
// out of its footprint into the ring of cells just outside it (the raised
// rims of a trail); a snowball takes it instead. A compacting body packs part
// of it in place: the same units stand lower (SnowSurface::compacted). The
// footprint is swept from last tick's pose to this one's in half-cell steps,
// so a fast body leaves a continuous trench. Units only move: cell to cell,
// or cell to `carried`; compaction changes heights, never units.
#include "systems/api/systems.hpp"
#include "systems/bodies/body.hpp"
#include "systems/core/limits.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

namespace {

/// World resource: the local cell mask of one body on one surface (reused),
/// with room for the largest surface.
struct CarveScratch {
    Vector<std::uint8_t> mask;  ///< 1 footprint, 0 outside
    Vector<std::int64_t> floor; ///< footprint: the level the body reaches down to
    Vector<float> bottom, top;  ///< the sweep's lowest and highest point over each cell (m)
    Vector<std::uint32_t> ring;
};

/// The cells of `s` a body may touch this tick: its swept footprint's
/// bounding box grown by the one-cell ring. False when it misses the grid.
bool cell_window(const SnowSurface& s, const Body& b, CellBox& box) {
    const float r = b.reach();
    const double fx0 = (std::min(b.previous.x, b.position.x) - r - s.x0) / s.cell - 1.0;
    const double fz0 = (std::min(b.previous.z, b.position.z) - r - s.z0) / s.cell - 1.0;
    const double fx1 = (std::max(b.previous.x, b.position.x) + r - s.x0) / s.cell + 1.0;
    const double fz1 = (std::max(b.previous.z, b.position.z) + r - s.z0) / s.cell + 1.0;
    if (!(fx1 >= 0.0 && fz1 >= 0.0 && fx0 < s.nx && fz0 < s.nz)) {
        return false; // NaN lands here too
    }
    box = {static_cast<std::uint32_t>(std::max(fx0, 0.0)),
           static_cast<std::uint32_t>(std::max(fz0, 0.0)),
           static_cast<std::uint32_t>(std::min(fx1, s.nx - 1.0)),
           static_cast<std::uint32_t>(std::min(fz1, s.nz - 1.0))};
    return true;
}

/// The level (unit_height steps) a height falls in, clamped to the grid's range.
std::int64_t level_of(const SnowSurface& s, float y) {
    const double level = std::floor(static_cast<double>(y) / s.unit_height);
    return static_cast<std::int64_t>(std::clamp(level, -max_surface_level, max_surface_level));
}

/// Marks the swept footprint in the window and, per footprint cell, the
/// level the body's lowest point reaches down to. A cell is in the footprint
/// only where the body reaches above its bare top: a body under a roof passes
/// beneath the roof's snow (whether it is below the snow's top is the floor).
/// Each pose of the sweep visits only the cells under it, so the work is
/// poses × footprint, not poses × window (a body that jumps far on a fine
/// grid would otherwise cost the cube of its jump in cells).
void mark_footprint(const Body& b, const SnowSurface& s, const CellBox& box,
                    CarveScratch& scratch) {
    const std::uint32_t w = box.x1 - box.x0 + 1, h = box.z1 - box.z0 + 1;
    const std::size_t n = static_cast<std::size_t>(w) * h;
    scratch.mask.assign(n, 0);
    scratch.floor.assign(n, 0);
    scratch.bottom.assign(n, std::numeric_limits<float>::infinity());
    scratch.top.assign(n, -std::numeric_limits<float>::infinity());
    const float travel = std::hypot(b.position.x - b.previous.x, b.position.z - b.previous.z);
    const auto steps = static_cast<std::uint32_t>(std::ceil(travel / (0.5f * s.cell))) + 1;
    const double r = b.reach();
    // The window's cells (box-relative) within the pose's reach, one cell to spare.
    const auto span = [&](double centre, float origin, std::uint32_t first, std::uint32_t last,
                          std::uint32_t& lo, std::uint32_t& hi) {
        const double c0 = (centre - r - origin) / s.cell - 1.0, c1 = (centre + r - origin) / s.cell;
        if (!(c1 >= first && c0 <= last)) {
            return false;
        }
        lo = static_cast<std::uint32_t>(std::max(c0, static_cast<double>(first))) - first;
        hi = static_cast<std::uint32_t>(std::min(c1, static_cast<double>(last))) - first;
        return true;
    };
    for (std::uint32_t k = 0; k <= steps; ++k) {
        const glm::vec3 at =
            b.previous + (b.position - b.previous) * (static_cast<float>(k) / steps);
        std::uint32_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
        if (!span(at.x, s.x0, box.x0, box.x1, i0, i1) ||
            !span(at.z, s.z0, box.z0, box.z1, j0, j1)) {
            continue;
        }
        for (std::uint32_t j = j0; j <= j1; ++j) {
            for (std::uint32_t i = i0; i <= i1; ++i) {
                const float x = s.x0 + (static_cast<float>(box.x0 + i) + 0.5f) * s.cell;
                const float z = s.z0 + (static_cast<float>(box.z0 + j) + 0.5f) * s.cell;
                float below = 0.0f, above = 0.0f;
                if (b.extent_at(x - at.x, z - at.z, below, above)) {
                    const std::size_t c = static_cast<std::size_t>(j) * w + i;
                    scratch.bottom[c] = std::min(scratch.bottom[c], at.y - below);
                    scratch.top[c] = std::max(scratch.top[c], at.y + above);
                }
            }
        }
    }
    for (std::uint32_t j = 0; j < h; ++j) {
        for (std::uint32_t i = 0; i < w; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            const std::size_t c = s.index(box.x0 + i, box.z0 + j);
            if (scratch.top[k] > -std::numeric_limits<float>::infinity() && !s.is_void(c) &&
                level_of(s, scratch.top[k]) > s.base_level[c]) {
                scratch.mask[k] = 1;
                scratch.floor[k] = level_of(s, scratch.bottom[k]);
            }
        }
    }
}

/// Levels the packed layer at the bottom of a cell stands: the fewest units
/// that hold its compaction, at packed_snow_density (fresh snow lies on top).
std::int64_t packed_layer(std::uint32_t units, std::uint32_t squeezed) {
    std::uint32_t m = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(units, (std::uint64_t{squeezed} * 4 + 2) / 3));
    while (m < units && max_compaction(m) < squeezed) {
        ++m;
    }
    return static_cast<std::int64_t>(m) - squeezed;
}

/// Lowers cell c's snow top to `target` (a level at or above its base),
/// cutting from the top: fresh snow first, then the packed layer at
/// max_packing units a level. Of what it cuts, the fraction `compaction`
/// stays, packed under the body: a compacting body stands on packed snow (it
/// cuts no lower than the packed layer, and the new one may stand above its
/// lowest point), so what it packed once it never cuts again. Adds the units
/// that leave the cell to `taken`; false when the cell is already that low.
bool lower_cell(SnowSurface& s, std::size_t c, std::int64_t target, float compaction,
                std::uint64_t& taken) {
    const std::int64_t units = s.snow[c];
    const std::uint32_t squeezed = s.compacted.empty() ? 0 : s.compacted[c];
    if (compaction > 0.0f) {
        target = std::max(target, s.base_level[c] + packed_layer(s.snow[c], squeezed));
    }
    if (s.level(c) <= target) {
        return false;
    }
    const std::int64_t keep = target - s.base_level[c]; // levels left standing under the cut
    const std::int64_t cut_left = std::min(squeezed + keep, keep * max_packing);
    const auto packed = static_cast<std::int64_t>(
        std::llround(static_cast<double>(compaction) * static_cast<double>(units - cut_left)));
    const std::int64_t left = cut_left + packed;
    const std::int64_t depth = std::max(keep, (left + max_packing - 1) / max_packing);
    s.snow[c] = static_cast<std::uint32_t>(left);
    if (!s.compacted.empty()) {
        s.compacted[c] = 0;
    }
    s.compact(c, static_cast<std::uint32_t>(left - depth));
    taken += static_cast<std::uint64_t>(units - left);
    return true;
}

/// Lowers the snow above the body's lowest point in the footprint cells;
/// returns the units taken out of them.
std::uint64_t take_footprint(SnowSurface& s, const CellBox& box, const CarveScratch& scratch,
                             float compaction) {
    const std::uint32_t w = box.x1 - box.x0 + 1, h = box.z1 - box.z0 + 1;
    std::uint64_t taken = 0;
    for (std::uint32_t j = 0; j < h; ++j) {
        for (std::uint32_t i = 0; i < w; ++i) {
            const std::size_t k = static_cast<std::size_t>(j) * w + i;
            const std::size_t c = s.index(box.x0 + i, box.z0 + j);
            if (scratch.mask[k] != 0 && s.snow[c] != 0 &&
                lower_cell(s, c, std::max(s.base_level[c], scratch.floor[k]), compaction, taken)) {
                s.mark_dirty(box.x0 + i, box.z0 + j);
            }
        }
    }
    return taken;
}

/// The ring: cells outside the footprint next to it (ascending index), not
/// void, and not behind where the body started this tick (that is the trail
/// it already cut).
void find_ring(const SnowSurface& s, const Body& b, const CellBox& box, CarveScratch& scratch) {
    const float dx = b.position.x - b.previous.x, dz = b.position.z - b.previous.z;
    const std::uint32_t w = box.x1 - box.x0 + 1, h = box.z1 - box.z0 + 1;
    scratch.ring.clear();
    const auto in = [&](std::int64_t i, std::int64_t j) {
        return i >= 0 && j >= 0 && i < w && j < h &&
               scratch.mask[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)] != 0;
    };
    for (std::uint32_t j = 0; j < h; ++j) {
        for (std::uint32_t i = 0; i < w; ++i) {
            const std::size_t c = s.index(box.x0 + i, box.z0 + j);
            const float x = s.x0 + (static_cast<float>(box.x0 + i) + 0.5f) * s.cell;
            const float z = s.z0 + (static_cast<float>(box.z0 + j) + 0.5f) * s.cell;
            const bool behind = (x - b.previous.x) * dx + (z - b.previous.z) * dz < 0.0f;
            if (!in(i, j) && !s.is_void(c) && !behind &&
                (in(i - 1, j) || in(i + 1, j) || in(i, j - 1) || in(i, j + 1))) {
                scratch.ring.push_back(static_cast<std::uint32_t>(c));
            }
        }
    }
}

/// Spreads `units` evenly over the ring; the first cells take the remainder.
void raise_rims(SnowSurface& s, const CarveScratch& scratch, std::uint64_t units) {
    const std::uint64_t n = scratch.ring.size();
    for (std::uint64_t k = 0; k < n; ++k) {
        const std::uint32_t c = scratch.ring[k];
        s.snow[c] += static_cast<std::uint32_t>(units / n + (k < units % n ? 1 : 0));
        s.mark_dirty(c);
    }
}

} // namespace

void prepare_carve(World& w) {
    if (w.count<Body>() == 0 || w.count<SnowSurface>() == 0) {
        return;
    }
    auto* scratch = w.try_resource<CarveScratch>();
    if (scratch == nullptr) {
        scratch = &w.set_resource<CarveScratch>();
    }
    // A body's window is clamped to the grid, however far it moves in a tick.
    std::size_t largest = 0;
    for (const SnowSurface& s : w.pool<SnowSurface>().components()) {
        largest = std::max(largest, s.cell_count());
    }
    scratch->mask.reserve(largest);
    scratch->floor.reserve(largest);
    scratch->bottom.reserve(largest);
    scratch->top.reserve(largest);
    scratch->ring.reserve(largest);
}

void carve_system(World& w) {
    prepare_carve(w);
    CarveScratch* scratch = &w.resource<CarveScratch>();
    auto& counters = w.resource<SimCounters>();
    for (Body& b : w.pool<Body>().components()) {
        for (SnowSurface& s : w.pool<SnowSurface>().components()) {
            CellBox box;
            if (!cell_window(s, b, box)) {
                continue;
            }
            mark_footprint(b, s, box, *scratch);
            if (!b.snowball) {
                find_ring(s, b, box, *scratch);
                if (scratch->ring.empty()) {
                    continue; // nowhere to push it: the footprint fills the grid
                }
            }
            const std::uint64_t taken = take_footprint(s, box, *scratch, b.compaction);
            counters.carved_units += taken;
            if (b.snowball) {
                b.carried += taken;
                b.radius = snowball_radius(b.bare_radius, b.carried);
                continue;
            }
            if (taken > 0) {
                raise_rims(s, *scratch, taken);
            }
        }
    }
}

} // namespace snow
