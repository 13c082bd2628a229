/// @file shed.hpp
/// @brief Settled snow leaving a cell as flakes (clumps): spill over an edge
/// [WF §3] and snow whose base moved away under it.
#pragma once

#include "ecs/world.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <glm/vec3.hpp>

#include <cstdint>

namespace snow {

/// Where clumps appear and how they fall.
struct ClumpStart {
    glm::vec3 at{0.0f};
    float k_over_m = 1.0f;
};

/// Where clumps leaving cell (ix, iz) of `s` across an edge start: the
/// cell's centre moved one cell by (ox, oz), i.e. half a cell beyond the edge
/// it crosses, at the cell's snow top.
[[nodiscard]] ClumpStart clump_beyond(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz,
                                      double ox, double oz, float k_over_m);

/// Turns up to `units` settled units into resting flakes of at most
/// max_flake_units each at `start`. Returns the units turned (fewer when the
/// pool is full); the caller takes them off its cell, so the ledger total holds.
std::uint32_t shed_units(FlakePool& pool, std::uint32_t units, const ClumpStart& start);

/// Drag of clumps: their terminal speed is the first emitter's mean fall
/// speed (1 m/s without an emitter).
[[nodiscard]] float clump_drag(const World& w);

} // namespace snow
