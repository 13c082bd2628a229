/// @file type_id.hpp
/// @brief Small dense ids for component and resource types.
#pragma once

#include <cstdint>

namespace snow {

namespace detail {
inline std::uint32_t next_type_id() {
    static std::uint32_t counter = 0;
    return counter++;
}
} // namespace detail

/// A process-wide dense id per type. Only used to index storage, never hashed
/// or ordered in the simulation, so first-use order cannot change results.
template <typename T>
[[nodiscard]] std::uint32_t type_id() {
    static const std::uint32_t id = detail::next_type_id();
    return id;
}

} // namespace snow
