// Spatial order of the flake pool. Flakes spawn and land all over the sky and
// the ground, and a slot is reused wherever its last flake died, so in slot
// order neighbouring slots lie far apart: the flake pass's height and
// collider lookups then miss the cache on every flake, and the slots freed by
// landings are streamed for nothing. Every flake_order_every ticks a stable
// counting sort by (z column, x column) of a grid over the bounds moves the
// alive flakes, in that order, into slots 0 .. alive − 1: the flakes of a
// block then lie in a few neighbouring columns and the pool has no holes
// (docs/performance.md "Spatial order"). The order is a function of the state
// alone, so it is the same for any thread count and after a restore.
#include "systems/flake_order.hpp"

#include "systems/sim_config.hpp"
#include "systems/systems.hpp"

#include <algorithm>
#include <bit>

namespace snow {

namespace {

constexpr std::uint32_t free_slot = ~std::uint32_t{0};

/// Column (0 .. bins − 1) of coordinate u given the grid's start and 1/width;
/// outside, infinite or NaN clamps to the nearest end (NaN: 0).
std::uint32_t column(float u, float start, float inv_width) {
    const float t = (u - start) * inv_width;
    constexpr auto last = static_cast<float>(flake_order_bins - 1);
    return !(t >= 1.0f) ? 0u : (t >= last ? flake_order_bins - 1 : static_cast<std::uint32_t>(t));
}

/// a[new slot] = a[old slot] for every alive slot below `end`.
template <typename T>
void permute(PoolArray<T>& a, FlakeOrder& o, std::uint32_t end, std::uint32_t alive) {
    for (std::uint32_t s = 0; s < end; ++s) {
        if (o.dest[s] != free_slot) {
            o.moved[o.dest[s]] = std::bit_cast<std::uint32_t>(a[s]);
        }
    }
    for (std::uint32_t i = 0; i < alive; ++i) {
        a[i] = std::bit_cast<T>(o.moved[i]);
    }
}

} // namespace

void FlakeOrder::reset(std::uint32_t capacity) {
    counts.assign(static_cast<std::size_t>(flake_order_bins) * flake_order_bins + 1, 0);
    dest.assign(capacity, 0);
    moved.assign(capacity, 0);
}

void flake_order_system(World& w) {
    if (w.resource<SimClock>().tick % flake_order_every != 0) {
        return;
    }
    FlakePool& f = w.resource<FlakePool>();
    FlakeOrder& o = w.resource<FlakeOrder>();
    const Aabb& bounds = w.resource<SimConfig>().bounds;
    const float inv_x = static_cast<float>(flake_order_bins) / (bounds.max.x - bounds.min.x);
    const float inv_z = static_cast<float>(flake_order_bins) / (bounds.max.z - bounds.min.z);
    const std::uint32_t end = f.slot_end;
    std::fill(o.counts.begin(), o.counts.end(), 0u);
    for (std::uint32_t s = 0; s < end; ++s) {
        if (!f.is_alive(s)) {
            o.dest[s] = free_slot;
            continue;
        }
        const std::uint32_t c = column(f.pz[s], bounds.min.z, inv_z) * flake_order_bins +
                                column(f.px[s], bounds.min.x, inv_x);
        o.dest[s] = c;
        ++o.counts[c + 1];
    }
    for (std::size_t c = 1; c < o.counts.size(); ++c) {
        o.counts[c] += o.counts[c - 1];
    }
    for (std::uint32_t s = 0; s < end; ++s) { // in slot order: the sort is stable
        if (o.dest[s] != free_slot) {
            o.dest[s] = o.counts[o.dest[s]]++;
        }
    }
    const std::uint32_t alive = f.alive;
    for (auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz, &f.k_over_m, &f.size}) {
        permute(*a, o, end, alive);
    }
    permute(f.mass_units, o, end, alive);
    permute(f.id, o, end, alive);
    // The slots above the packed flakes are free, as release() leaves them.
    for (std::uint32_t i = alive; i < end; ++i) {
        f.mass_units[i] = 0;
        f.vx[i] = f.vy[i] = f.vz[i] = 0.0f;
        f.py[i] = FlakePool::parked_y;
    }
    // Free stack: slots never handed out (end .. capacity − 1) lie at its
    // bottom, highest first; the freed ones follow, so alive is taken next.
    f.free_stack.resize(f.capacity() - end);
    for (std::uint32_t s = end; s > alive; --s) {
        f.free_stack.push_back(s - 1);
    }
    f.slot_end = alive;
}

} // namespace snow
