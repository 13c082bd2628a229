/// @file flake_pool.hpp
/// @brief All snowflakes as one structure-of-arrays pool with a free-index
/// stack (seed 003 §III.B): up to millions of flakes, not one entity each.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace snow {

/// World resource. Hot arrays (position, velocity, k/m) are read every tick;
/// cold ones (size, mass) only on spawn, landing and rendering.
/// A slot is alive iff mass_units[slot] != 0.
struct FlakePool {
    // hot
    std::vector<float> px, py, pz;
    std::vector<float> vx, vy, vz;
    std::vector<float> k_over_m; ///< linear drag coefficient over mass (1/s)
    // cold
    std::vector<std::uint32_t> mass_units; ///< 0 = free slot
    std::vector<float> size;               ///< diameter (m), for rendering
    std::vector<std::uint32_t> free_stack; ///< free slots; top = back()
    std::uint32_t alive = 0;
    std::uint32_t max_alive = 0; ///< high-water mark of `alive`

    /// Allocates all storage once; no allocation happens in a tick afterwards.
    void reset(std::uint32_t capacity);
    [[nodiscard]] std::uint32_t capacity() const {
        return static_cast<std::uint32_t>(mass_units.size());
    }
    [[nodiscard]] bool is_alive(std::uint32_t slot) const { return mass_units[slot] != 0; }
    /// Takes a free slot (lowest first for a fresh pool); returns false when full.
    [[nodiscard]] bool acquire(std::uint32_t& slot);
    /// Frees a slot; its mass must already be accounted for by the caller.
    void release(std::uint32_t slot);
    /// Sum of mass units of alive flakes (airborne snow).
    [[nodiscard]] std::uint64_t airborne_units() const;
};

} // namespace snow
