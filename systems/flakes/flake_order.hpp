/// @file flake_order.hpp
/// @brief Flakes kept in spatial order: every flake_order_every ticks the
/// pool's alive flakes are stably sorted by ground column, tile by tile, and
/// packed into the lowest slots (docs/performance.md "Spatial order").
#pragma once

#include "ecs/host_memory.hpp"
#include "systems/flakes/flake_pool.hpp"

#include <cstdint>

namespace snow {

/// Ticks between two orderings; the first tick (tick 0) orders too.
inline constexpr std::uint64_t flake_order_every = 64;
/// Columns of the ordering grid over the bounds, along x and along z.
inline constexpr std::uint32_t flake_order_bins = 256;
/// Columns on a side of the square tiles the order goes by: tile after tile
/// (rows of tiles along x), and within a tile column after column (rows along
/// x). A block of slots then covers a compact patch of ground (about 1 m
/// across in a 16 m scene) rather than a strip the width of the scene.
inline constexpr std::uint32_t flake_order_tile = 16;

/// A buffer the size of a pool array. Every pool array holds its free value
/// from slot_end on; a buffer traded away by an ordering keeps that from
/// the `end` it was ordered at, so only the slots below need resetting when
/// it becomes a pool array again.
template <typename T>
struct SpareArray {
    PoolArray<T> buffer;
    std::uint32_t dirty_end = 0; ///< slots from here on hold the free value
};

/// World resource: the ordering's scratch, sized with the pool, so no tick
/// allocates. Derived data: neither hashed nor saved.
struct FlakeOrder {
    /// Per key (column or free), for the slots of each half of the pool: the
    /// count, then where the half's next flake of that key goes.
    Vector<std::uint32_t> counts[2];
    Vector<std::uint32_t> keys;   ///< per slot: its column, or past the last when free
    Vector<std::uint32_t> source; ///< per new slot: the slot its flake comes from
    /// Where the new order of a pool array is written before the two trade
    /// buffers: for the float arrays but py (free value 0; one per half of
    /// the work, see flake_order_system), for py, and for mass and id.
    SpareArray<float> zeros[2], heights;
    SpareArray<std::uint32_t> words;
    /// For the held winds; sized once the pool holds them (prepare_flake_order).
    SpareArray<std::int16_t> held;
    void reset(std::uint32_t capacity);
};

} // namespace snow
