/// @file find_flake.hpp
/// @brief Test support: where a flake is now. The pool's spatial order moves
/// flakes between slots every few ticks, so a test that follows one flake
/// follows its id.
#pragma once

#include "systems/flakes/flake_pool.hpp"

#include <cstdint>
#include <optional>

namespace snow::test {

/// The slot of the alive flake with id `id`; nullopt if it has gone.
inline std::optional<std::uint32_t> slot_of(const FlakePool& f, std::uint32_t id) {
    for (std::uint32_t s = 0; s < f.slot_end; ++s) {
        if (f.is_alive(s) && f.id[s] == id) {
            return s;
        }
    }
    return std::nullopt;
}

} // namespace snow::test
