/// @file sim_counters.hpp
/// @brief What the systems did so far (landings, rolls, spills...), for run
/// reports and the HUD.
#pragma once

#include <cstdint>

namespace snow {

/// Per-run counters the systems add to (World resource; not part of the state hash).
struct SimCounters {
    std::uint64_t stiff_flake_ticks = 0; ///< flake-ticks where explicit Euler was unsafe
    std::uint64_t landed = 0;            ///< flakes that became snow
    std::uint64_t rolled = 0;            ///< of those, how many rolled ([ZCL §IV] rules 2/3)
    std::uint64_t smoothing_iterations = 0;
    std::uint64_t spilled_units = 0;
    std::uint64_t occlusion_refreshes = 0;
    std::uint64_t carved_units = 0; ///< units moved out of body footprints
};

} // namespace snow
