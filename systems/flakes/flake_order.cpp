// Spatial order of the flake pool. Flakes spawn and land all over the sky and
// the ground, and a slot is reused wherever its last flake died, so in slot
// order neighbouring slots lie far apart: the flake pass's height and
// collider lookups then miss the cache on every flake, and the slots freed by
// landings are streamed for nothing. Every flake_order_every ticks a stable
// counting sort by (tile, z column, x column) of a grid over the bounds
// moves the alive flakes, in that order, into slots 0 .. alive − 1: the
// flakes of a block then lie in a compact patch of ground (one bound for
// the collision prefilter, few cells for the lookups) and the pool has no holes
// (docs/performance.md "Spatial order"). The order is a function of the state
// alone, so it is the same for any thread count and after a restore.
#include "systems/flakes/flake_order.hpp"

#include "systems/api/systems.hpp"
#include "systems/core/jobs.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/flakes/held_wind.hpp"

#include <algorithm>

namespace snow {

namespace {

/// The key of a free slot: one past the last column.
constexpr std::uint32_t free_key = flake_order_bins * flake_order_bins;

/// Column (0 .. bins − 1) of coordinate u given the grid's start and 1/width;
/// outside, infinite or NaN clamps to the nearest end (NaN: 0). Selects
/// only, so the key loop vectorises.
std::uint32_t column(float u, float start, float inv_width) {
    constexpr auto last = static_cast<float>(flake_order_bins - 1);
    float t = (u - start) * inv_width;
    t = t > 0.0f ? t : 0.0f; // NaN compares false: column 0
    t = t < last ? t : last;
    return static_cast<std::uint32_t>(static_cast<std::int32_t>(t));
}

/// The key of each of `count` slots: its tile, then its (z, x) column in the
/// tile (flake_order_tile), or free_key when free (sorting after every
/// column, so free slots land at or past `alive`, where nothing reads them).
void slot_keys(const float* __restrict px, const float* __restrict pz,
               const std::uint32_t* __restrict mass, std::uint32_t count, const Aabb bounds,
               std::uint32_t* __restrict key) {
    const float inv_x = static_cast<float>(flake_order_bins) / (bounds.max.x - bounds.min.x);
    const float inv_z = static_cast<float>(flake_order_bins) / (bounds.max.z - bounds.min.z);
    const float x0 = bounds.min.x, z0 = bounds.min.z;
    constexpr std::uint32_t t = flake_order_tile, tiles = flake_order_bins / t;
    for (std::uint32_t s = 0; s < count; ++s) {
        const std::uint32_t cz = column(pz[s], z0, inv_z), cx = column(px[s], x0, inv_x);
        const std::uint32_t tile = (cz / t) * tiles + cx / t;
        key[s] = mass[s] != 0 ? tile * t * t + (cz % t) * t + cx % t : free_key;
    }
}

/// a[new slot] = a[old slot] for the `alive` new slots, read through
/// `source` (sequential writes; the reads gather) into the spare, whose
/// other slots up to its dirty end are then set to `free` (the pool's free
/// slots hold what release() and reset() leave); then the two trade buffers.
template <typename T>
void permute(PoolArray<T>& a, SpareArray<T>& spare, const Vector<std::uint32_t>& source,
             std::uint32_t end, std::uint32_t alive, T free) {
    T* __restrict out = spare.buffer.data();
    const T* __restrict in = a.data();
    const std::uint32_t* __restrict from = source.data();
    for (std::uint32_t i = 0; i < alive; ++i) {
        out[i] = in[from[i]];
    }
    std::fill(out + alive, out + std::max(alive, spare.dirty_end), free);
    a.swap(spare.buffer);
    spare.dirty_end = end; // the old order: from `end` on it holds free values
}

} // namespace

void FlakeOrder::reset(std::uint32_t capacity) {
    for (auto& c : counts) {
        c.assign(static_cast<std::size_t>(free_key) + 1, 0);
    }
    keys.assign(capacity, 0);
    source.assign(capacity, 0);
    for (SpareArray<float>* spare : {&zeros[0], &zeros[1], &heights}) {
        spare->buffer.assign(capacity, 0.0f);
        spare->dirty_end = capacity;
    }
    words.buffer.assign(capacity, 0);
    words.dirty_end = capacity;
    held = {};
}

void prepare_flake_order(World& w) {
    const FlakePool& f = w.resource<FlakePool>();
    FlakeOrder& o = w.resource<FlakeOrder>();
    if (f.holds_wind() && o.held.buffer.size() != f.capacity()) {
        o.held.buffer.assign(f.capacity(), held_wind_unset); // once per field
        o.held.dirty_end = f.capacity();
    }
}

void flake_order_system(World& w) {
    if (w.resource<SimClock>().tick % flake_order_every != 0) {
        return;
    }
    prepare_flake_order(w);
    FlakePool& f = w.resource<FlakePool>();
    FlakeOrder& o = w.resource<FlakeOrder>();
    const Aabb& bounds = w.resource<SimConfig>().bounds;
    const std::uint32_t end = f.slot_end;
    // A stable counting sort in two halves of the slots, one per core when
    // the pool is large: each keys and counts its slots, the offsets put the
    // first half's flakes of a key before the second's, and each half places
    // its own. The same order as one pass in slot order.
    const std::uint32_t* key = o.keys.data();
    const std::uint32_t mid = end / 2;
    const auto half_range = [&](std::size_t half, std::uint32_t& b, std::uint32_t& e) {
        b = half == 0 ? 0 : mid;
        e = half == 0 ? mid : end;
    };
    for_tasks(w, 2, end, [&](std::size_t half) {
        std::uint32_t* count = o.counts[half].data();
        std::fill(count, count + o.counts[half].size(), 0u);
        std::uint32_t b = 0, e = 0;
        half_range(half, b, e);
        slot_keys(f.px.data() + b, f.pz.data() + b, f.mass_units.data() + b, e - b, bounds,
                  o.keys.data() + b);
        for (std::uint32_t s = b; s < e; ++s) {
            ++count[key[s]];
        }
    });
    std::uint32_t next = 0;
    for (std::size_t k = 0; k < o.counts[0].size(); ++k) {
        for (auto& count : o.counts) {
            const std::uint32_t n = count[k];
            count[k] = next;
            next += n;
        }
    }
    for_tasks(w, 2, end, [&](std::size_t half) {
        std::uint32_t* place = o.counts[half].data();
        std::uint32_t* source = o.source.data();
        std::uint32_t b = 0, e = 0;
        half_range(half, b, e);
        for (std::uint32_t s = b; s < e; ++s) { // in slot order: the sort is stable
            source[place[key[s]]++] = s;
        }
    });
    const std::uint32_t alive = f.alive;
    // Two halves of about equal work, each with its own spare buffers, for
    // the two cores when the pool is large (any split gives the same arrays).
    for_tasks(w, 2, end, [&](std::size_t half) {
        if (half == 0) {
            for (auto* a : {&f.px, &f.pz, &f.vx, &f.vy, &f.vz}) {
                permute(*a, o.zeros[0], o.source, end, alive, 0.0f);
            }
            return;
        }
        for (auto* a : {&f.k_over_m, &f.size}) {
            permute(*a, o.zeros[1], o.source, end, alive, 0.0f);
        }
        permute(f.py, o.heights, o.source, end, alive, FlakePool::parked_y);
        permute(f.mass_units, o.words, o.source, end, alive, 0u);
        permute(f.id, o.words, o.source, end, alive, 0u);
        if (f.holds_wind()) {
            for (auto& a : f.held_wind) {
                permute(a, o.held, o.source, end, alive, held_wind_unset);
            }
        }
    });
    // Free stack: slots never handed out (end .. capacity − 1) lie at its
    // bottom, highest first; the freed ones follow, so alive is taken next.
    f.free_stack.resize(f.capacity() - end);
    for (std::uint32_t s = end; s > alive; --s) {
        f.free_stack.push_back(s - 1);
    }
    f.slot_end = alive;
}

} // namespace snow
