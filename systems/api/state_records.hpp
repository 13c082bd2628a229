/// @file state_records.hpp
/// @brief Records written for every item of a kind, shared by the state hash
/// and the byte snapshot (the hash feeds a ByteWriter into its hasher, so a
/// type whose hash is its record has one field list for both).
#pragma once

#include "ecs/world.hpp"
#include "systems/core/state_bytes.hpp"

#include <cstdint>

namespace snow {

/// The count, then entity and record for every T in the world.
template <typename T>
void write_each(ByteWriter& out, const World& world) {
    out(static_cast<std::uint64_t>(world.count<T>()));
    world.each<T>([&](Entity e, const T& item) {
        out(e.bits);
        save_state(out, item);
    });
}

/// A resource that may be absent: a flag, then its record.
template <typename T>
void write_optional(ByteWriter& out, const T* item) {
    out(item != nullptr);
    if (item != nullptr) {
        save_state(out, *item);
    }
}

} // namespace snow
