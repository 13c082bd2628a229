/// @file entity.hpp
/// @brief 32-bit entity handles: index + generation, 0 is the null handle.
#pragma once

#include <cstdint>

namespace snow {

/// An entity handle. Low 20 bits: slot index + 1 (so 0 stays null);
/// high 12 bits: generation, bumped on destroy so stale handles are detected.
struct Entity {
    std::uint32_t bits = 0;

    static constexpr std::uint32_t index_bits = 20;
    static constexpr std::uint32_t index_mask = (1u << index_bits) - 1u;
    static constexpr std::uint32_t max_entities = index_mask; // slots 0..max-1
    static constexpr std::uint32_t generation_mask = (1u << (32 - index_bits)) - 1u;

    [[nodiscard]] constexpr bool is_null() const { return bits == 0; }
    [[nodiscard]] constexpr std::uint32_t index() const { return (bits & index_mask) - 1u; }
    [[nodiscard]] constexpr std::uint32_t generation() const { return bits >> index_bits; }

    [[nodiscard]] static constexpr Entity make(std::uint32_t index, std::uint32_t generation) {
        return Entity{((generation & generation_mask) << index_bits) | (index + 1u)};
    }
    friend constexpr bool operator==(Entity, Entity) = default;
};

inline constexpr Entity null_entity{};

} // namespace snow
