/// @file flake_pool.hpp
/// @brief All snowflakes as one structure-of-arrays pool with a free-index
/// stack [ZCL §III.B]: up to millions of flakes, not one entity each.
#pragma once

#include "ecs/host_memory.hpp"
#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include <snow/defs.hpp>

namespace snow {

/// Storage for CacheAligned, from the host's allocator: `bytes` on a cache
/// line, or on whole 2 MiB pages offered to the kernel as huge pages from
/// 2 MiB on (flake_pool.cpp).
[[nodiscard]] void* allocate_pool_array(std::size_t bytes);
void free_pool_array(void* p, std::size_t bytes) noexcept;

/// Allocator for the pool's arrays: storage starts on a cache line, so the
/// SIMD loops of the per-flake systems load whole lines and chunks of
/// flake_grain slots never share a line with their neighbours. An array of
/// 2 MiB or more is laid on whole 2 MiB pages and offered to the kernel as
/// huge pages (Linux; a hint): a pass streams a dozen such arrays at once,
/// and on 4 KiB pages every 4 KiB of each costs a TLB miss.
template <typename T>
struct CacheAligned {
    using value_type = T;

    CacheAligned() = default;
    template <typename U>
    CacheAligned(const CacheAligned<U>&) noexcept {}

    [[nodiscard]] T* allocate(std::size_t n) {
        return static_cast<T*>(allocate_pool_array(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept { free_pool_array(p, n * sizeof(T)); }
    template <typename U>
    bool operator==(const CacheAligned<U>&) const noexcept {
        return true;
    }
};

/// One per-slot array of the pool.
template <typename T>
using PoolArray = std::vector<T, CacheAligned<T>>;

/// World resource. Hot arrays (position, velocity, k/m) are read every tick;
/// cold ones (size, mass) only on spawn, landing and rendering.
/// A slot is alive iff mass_units[slot] != 0. A free slot's py is parked_y,
/// so a per-flake prefilter that tests heights against surface tops passes
/// over free slots without reading their mass (landed flakes would otherwise
/// lie on the tops they landed on).
struct FlakePool {
    static constexpr float parked_y = std::numeric_limits<float>::infinity();

    // hot
    PoolArray<float> px, py, pz;
    PoolArray<float> vx, vy, vz;
    PoolArray<float> k_over_m; ///< linear drag coefficient over mass (1/s)
    // cold
    PoolArray<std::uint32_t> mass_units; ///< 0 = free slot
    PoolArray<float> size;               ///< diameter (m), for rendering
    /// The flake's own number, kept when the pool is reordered: its random
    /// draws are keyed by it, not by the slot it happens to be in.
    PoolArray<std::uint32_t> id;
    /// The wind field's wind each flake drags towards, held between samples
    /// (systems/flakes/held_wind.hpp): one array per axis, empty without a field.
    PoolArray<std::int16_t> held_wind[3];
    Vector<std::uint32_t> free_stack; ///< free slots; top = back()
    std::uint32_t alive = 0;
    std::uint32_t max_alive = 0; ///< high-water mark of `alive`
    /// One past the highest slot ever handed out: every alive slot is below it,
    /// so per-flake passes stop there instead of at capacity().
    std::uint32_t slot_end = 0;
    std::uint32_t next_id = 0; ///< id of the next flake acquire() hands out (wraps at 2^32)

    /// Allocates all storage once; no allocation happens in a tick afterwards.
    void reset(std::uint32_t capacity);
    [[nodiscard]] std::uint32_t capacity() const {
        return static_cast<std::uint32_t>(mass_units.size());
    }
    [[nodiscard]] bool is_alive(std::uint32_t slot) const { return mass_units[slot] != 0; }
    /// With `on`, every slot's held wind is unset (each alive flake samples the
    /// field on its next tick); without, the held winds are dropped.
    void hold_wind(bool on);
    [[nodiscard]] bool holds_wind() const { return !held_wind[0].empty(); }
    /// Takes a free slot (lowest first for a fresh pool) and gives it the next
    /// id (and an unset held wind); returns false when full.
    [[nodiscard]] bool acquire(std::uint32_t& slot);
    /// Frees a slot; its mass must already be accounted for by the caller.
    void release(std::uint32_t slot) {
        park(slot);
        free_parked(slot);
    }
    /// The slot's half of release(): its fields as a free slot holds them. A
    /// pass's block parks the flakes it removes while their slots are in
    /// cache; the pass's end frees them in slot order.
    void park(std::uint32_t slot) {
        mass_units[slot] = 0;
        vx[slot] = vy[slot] = vz[slot] = 0.0f;
        py[slot] = parked_y;
    }
    /// The pool's half of release() for a parked slot: onto the free stack
    /// (whose order is state: callers go in slot order), one fewer alive.
    void free_parked(std::uint32_t slot) {
        free_stack.push_back(slot); // capacity was reserved in reset(): no allocation
        --alive;
    }
    /// Sum of mass units of alive flakes (airborne snow).
    [[nodiscard]] std::uint64_t airborne_units() const;
};

class ByteWriter;
class ByteReader;
/// The pool's snapshot record: the slots below slot_end and the free stack.
void save_state(ByteWriter& out, const FlakePool& f);
/// Reads a record of save_state into `f`, a pool of the capacity it was
/// saved with (throws SimulationError naming what is wrong otherwise).
void load_state(ByteReader& in, FlakePool& f);
class StateHasher;
/// The alive slots and the free stack; the path starts are rewritten by the
/// next integrate before anything reads them, so they are not state.
void hash_state(StateHasher& h, const FlakePool& f);

/// `flake.*`: one flake placed by hand.
inline constexpr FieldRule<FlakeSpec> flake_fields[] = {
    {"position", &FlakeSpec::position},
    {"velocity", &FlakeSpec::velocity},
    {"k_over_m", &FlakeSpec::k_over_m, positive},
    {"size", &FlakeSpec::size, non_negative},
    {"mass_units", &FlakeSpec::mass_units, between(1, max_flake_units)},
};

[[nodiscard]] Invalid validate(const FlakeSpec& f);

} // namespace snow
