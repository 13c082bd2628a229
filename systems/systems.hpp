/// @file systems.hpp
/// @brief The simulation systems, one free function each, in tick order
/// (DESIGN.md "Data flow of one tick"). Each lives in its own .cpp file.
#pragma once

#include "ecs/world.hpp"
#include "systems/sim_counters.hpp"

namespace snow {

void spawn_system(World& w);        ///< spawn.cpp: inactive flakes activate (seed 002 §4)
void wind_system(World& w);         ///< wind_system.cpp: bounded random walk + gusts
void integrate_system(World& w);    ///< integrate.cpp: gravity + drag to wind
void collide_system(World& w);      ///< collide.cpp: boxes, spheres, meshes, bounds
void deposit_system(World& w);      ///< deposit.cpp: landing + rolling rules (seed 003 §IV)
void redistribute_system(World& w); ///< redistribute.cpp: Laplacian cap (seed 002 §3)
void spill_system(World& w);        ///< spill.cpp: edge overflow to lower surfaces
void occlusion_system(World& w);    ///< occlusion.cpp: sky depth map (seed 004)

} // namespace snow
