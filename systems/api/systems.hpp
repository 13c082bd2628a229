/// @file systems.hpp
/// @brief The simulation systems, one free function each, in tick order
/// (docs/design.md "One tick"). Each lives in its own .cpp file.
#pragma once

#include "ecs/world.hpp"
#include <snow/views.hpp>

namespace snow {

void cover_system(World& w);       ///< snow_cover.cpp: covers follow the geometry under them
void body_system(World& w);        ///< body_system.cpp: moving bodies take this tick's pose
void flake_order_system(World& w); ///< flake_order.cpp: alive flakes sorted by column, packed
void spawn_system(World& w);       ///< spawn_system.cpp: inactive flakes activate [WF §4]
void wind_system(World& w);        ///< wind_system.cpp: bounded random walk + gusts
void wind_field_system(World& w);  ///< wind_field_system.cpp: stable fluids around obstacles
/// flake_pass_system.cpp: the three stages below on each block of flakes in turn
/// (what a tick runs; flake_stages.hpp)
void flake_pass_system(World& w);
void integrate_system(World& w); ///< integrate.cpp: gravity + drag to wind (alone: tests)
void collide_system(World& w);   ///< collide.cpp: boxes, spheres, meshes, bounds (alone)
void deposit_system(World& w);   ///< deposit.cpp: landing + rolling rules [ZCL §IV] (alone)
void carve_system(
    World& w); ///< carve_system.cpp: bodies push snow to trail rims, snowballs take it
void wind_transport_system(World& w); ///< wind_transport_system.cpp: the field's wind moves snow
/// True when a wind field with transport is declared (wind_transport_system's need).
[[nodiscard]] bool wind_transport_declared(const World& w);
void settle_system(World& w);       ///< settle_system.cpp: snow settles under its weight [And76]
void redistribute_system(World& w); ///< redistribute_system.cpp: Laplacian cap [WF §3]
void spill_system(World& w);        ///< spill_system.cpp: edge overflow to lower surfaces
void occlusion_system(World& w);    ///< occlusion.cpp: sky depth map [SKY]

// Each prepare makes what its system's ticks need for the scene as it stands:
// caches of the sources built, buffers with room for the most a tick can
// write, so that no tick allocates (<snow/allocator.hpp>). The Simulation
// calls them after each call that changes the scene; each system calls its
// own first (a no-op then, but a world changed behind the facade still runs).
void prepare_cover(World& w);          ///< snow_cover.cpp: a rebuild's buffers
void prepare_flake_order(World& w);    ///< flake_order.cpp: the held winds' spare buffer
void prepare_wind_field(World& w);     ///< wind_field_system.cpp: the solver's arrays
void prepare_flake_pass(World& w);     ///< flake_pass_system.cpp: the three stages' buffers
void prepare_carve(World& w);          ///< carve_system.cpp: a footprint on the largest surface
void prepare_wind_transport(World& w); ///< wind_transport_system.cpp: moves, windy columns
void prepare_redistribute(World& w);   ///< redistribute_system.cpp: the largest surface's steps
void prepare_occlusion(World& w);      ///< occlusion.cpp: the map's texels

} // namespace snow
