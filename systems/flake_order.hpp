/// @file flake_order.hpp
/// @brief Flakes kept in spatial order: every flake_order_every ticks the
/// pool's alive flakes are stably sorted by ground column and packed into the
/// lowest slots (docs/performance.md "Spatial order").
#pragma once

#include "systems/flake_pool.hpp"

#include <cstdint>
#include <vector>

namespace snow {

/// Ticks between two orderings; the first tick (tick 0) orders too.
inline constexpr std::uint64_t flake_order_every = 64;
/// Columns of the ordering grid over the bounds, along x and along z.
inline constexpr std::uint32_t flake_order_bins = 256;

/// World resource: the ordering's scratch, sized with the pool, so no tick
/// allocates. Derived data: neither hashed nor saved.
struct FlakeOrder {
    std::vector<std::uint32_t> counts; ///< per column, then the running offsets
    std::vector<std::uint32_t> dest;   ///< per slot: its column, then its new slot
    PoolArray<std::uint32_t> moved;    ///< one array of the pool, in its new order
    void reset(std::uint32_t capacity);
};

} // namespace snow
