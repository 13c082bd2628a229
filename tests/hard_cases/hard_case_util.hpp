/// @file hard_case_util.hpp
/// @brief Shared setup and checks for the hard-case suite (docs/hard_cases.md):
/// placing flakes by hand, the per-tick health check (exact mass, no NaN),
/// cell statistics, and the reduced counts used in sanitizer/Debug builds.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

namespace snow::hard {

/// Sanitizer (CI's ASan+UBSan Debug build) or unoptimised builds run 5-20×
/// slower: heavy cases use their reduced counts there (docs/hard_cases.md).
#if defined(__SANITIZE_ADDRESS__) || !defined(NDEBUG)
inline constexpr bool reduced_build = true;
#else
inline constexpr bool reduced_build = false;
#endif

/// `full` in optimised builds, `reduced` in sanitizer/Debug builds.
template <typename T>
[[nodiscard]] constexpr T scaled(T full, T reduced) {
    return reduced_build ? reduced : full;
}

/// Adds one airborne flake (and books its mass as spawned); returns its slot.
inline std::uint32_t place_flake(Simulation& sim, glm::vec3 p, glm::vec3 v, float k_over_m,
                                 std::uint32_t units) {
    const std::optional<std::uint32_t> slot = sim.place_flake({p, v, k_over_m, 0.01f, units});
    EXPECT_TRUE(slot.has_value()) << "test setup: flake pool full";
    return slot.value_or(0);
}

/// The invariants every hard case keeps on every tick it checks: the ledger
/// balances exactly and no flake or wind value is NaN or infinite.
[[nodiscard]] inline ::testing::AssertionResult healthy(const Simulation& sim) {
    const MassReport m = sim.mass();
    if (!m.balanced()) {
        return ::testing::AssertionFailure()
               << "tick " << sim.tick_count() << ": mass unbalanced: spawned " << m.spawned
               << " != airborne " << m.airborne << " + settled " << m.settled << " + removed "
               << m.removed;
    }
    if (const std::uint64_t bad = sim.nonfinite_count(); bad != 0) {
        return ::testing::AssertionFailure()
               << "tick " << sim.tick_count() << ": " << bad << " non-finite values";
    }
    return ::testing::AssertionSuccess();
}

/// The SnowSurface component of a surface entity.
[[nodiscard]] inline const SnowSurface& surface(const Simulation& sim, SurfaceId e) {
    return snow_surface(sim, e);
}

/// Summary of a surface's settled snow.
struct CellStats {
    std::uint32_t max = 0;
    std::uint64_t sum = 0;
    std::size_t nonzero = 0;
    std::size_t wrapped = 0; ///< cells >= 2^31: an unsigned underflow would land here
};

/// Max, sum, occupied and wrapped-looking cells of a surface.
[[nodiscard]] inline CellStats cell_stats(const SnowSurface& s) {
    CellStats st;
    for (const std::uint32_t u : s.snow) {
        st.max = std::max(st.max, u);
        st.sum += u;
        st.nonzero += u != 0 ? 1 : 0;
        st.wrapped += u >= (1u << 31) ? 1 : 0;
    }
    return st;
}

/// An unsigned count from the environment (e.g. SNOW_SOAK_TICKS), else `fallback`;
/// a value that is not a whole positive number fails the calling test.
[[nodiscard]] inline std::uint64_t env_count(const char* name, std::uint64_t fallback) {
    const char* text = std::getenv(name);
    if (text == nullptr || *text == '\0') {
        return fallback;
    }
    char* end = nullptr;
    const unsigned long long v = std::strtoull(text, &end, 10);
    if (*end != '\0' || v == 0 || text[0] == '-') {
        ADD_FAILURE() << name << " must be a whole number > 0 (got '" << text << "')";
        return fallback;
    }
    return v;
}

} // namespace snow::hard
