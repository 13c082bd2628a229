/// @file systems.hpp
/// @brief The simulation systems, one free function each, in tick order
/// (docs/design.md "One tick"). Each lives in its own .cpp file.
#pragma once

#include "ecs/world.hpp"

#include <cstdint>

namespace snow {

void cover_system(World& w);        ///< snow_cover.cpp: covers follow the geometry under them
void body_system(World& w);         ///< body_motion.cpp: moving bodies take this tick's pose
void spawn_system(World& w);        ///< spawn.cpp: inactive flakes activate [WF §4]
void wind_system(World& w);         ///< wind_system.cpp: bounded random walk + gusts
void integrate_system(World& w);    ///< integrate.cpp: gravity + drag to wind
void collide_system(World& w);      ///< collide.cpp: boxes, spheres, meshes, bounds
void deposit_system(World& w);      ///< deposit.cpp: landing + rolling rules [ZCL §IV]
void carve_system(World& w);        ///< carve.cpp: bodies push snow to trail rims, snowballs take it
void redistribute_system(World& w); ///< redistribute.cpp: Laplacian cap [WF §3]
void spill_system(World& w);        ///< spill.cpp: edge overflow to lower surfaces
void occlusion_system(World& w);    ///< occlusion.cpp: sky depth map [SKY]

/// Per-run counters the systems add to (World resource; tick state, so saved and hashed).
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
