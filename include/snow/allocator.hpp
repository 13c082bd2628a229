/// @file allocator.hpp
/// @brief The host's memory: every allocation of the simulation library
/// (snow::sim and the ECS under it) goes through one Allocator, the host's
/// or the default (aligned ::operator new and delete), and a tick makes none:
/// the Simulation sizes what its ticks need when the scene is built or
/// changed (Box2D's b2SetAllocator, Jolt's Allocate/Free hooks).
/// Not through it: what the host owns (the bytes save_bytes returns), the
/// messages of errors snow throws, and the start-up state std::thread
/// allocates for each thread of the built-in pool (none with the host's own
/// TaskSystem). Self-contained: the standard library only.
#pragma once

#include <cstddef>

namespace snow {

/// The host's allocation functions. Both may be called from several threads
/// at once (two Simulations built or changed on two threads), so they must
/// be thread-safe.
struct Allocator {
    /// `size` bytes (> 0) aligned to `alignment` (a power of two, up to the
    /// 2 MiB of the flake pool's large arrays); null when the host has
    /// none, and snow throws std::bad_alloc.
    void* (*allocate)(std::size_t size, std::size_t alignment, void* user) = nullptr;
    /// Gives back a block of allocate(), with the size and alignment it was asked for.
    void (*free)(void* p, std::size_t size, std::size_t alignment, void* user) = nullptr;
    /// Passed to both as it is.
    void* user = nullptr;
};

/// Routes the library's allocations through `allocator` from now on. Throws
/// SimulationError (<snow/error.hpp>) when a function is null, or while the
/// library holds memory (live_allocations() > 0: destroy every Simulation
/// first), since a block must go back to the allocator that gave it. Not
/// to be called while another thread is inside snow.
void set_allocator(const Allocator& allocator);
/// Back to the default, aligned ::operator new and delete; refused as set_allocator is.
void reset_allocator();

/// Bytes the library holds now (as asked for, without the allocator's own overhead).
[[nodiscard]] std::size_t allocated_bytes();
/// Blocks the library holds now.
[[nodiscard]] std::size_t live_allocations();

} // namespace snow
