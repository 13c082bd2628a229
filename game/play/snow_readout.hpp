/// @file snow_readout.hpp
/// @brief What snow_game reads off the simulation's surfaces (read only):
/// the snow column under a point, the ground, and how deep the ground's snow is.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <snow/snow.hpp>

#include <limits>
#include <optional>

namespace snow {

/// The snow of one column: the highest bare top of any surface or cover cell
/// there, at or below some height, and the snow lying on that cell.
struct SnowColumn {
    float base = 0.0f;  ///< bare top (m)
    float depth = 0.0f; ///< snow on it (m)
    [[nodiscard]] float top() const { return base + depth; }
};

/// The column under world (x, z) whose bare top is the highest at or below
/// `below` (by default the topmost: what an on_ground body stands on; a
/// walker's feet plus a step: the ground under a roof), or nothing where no
/// surface cell is.
[[nodiscard]] std::optional<SnowColumn>
snow_column(const World& world, float x, float z,
            float below = std::numeric_limits<float>::infinity());

/// The ground: the largest cover or surface that lies on no solid; null if none.
[[nodiscard]] const SnowSurface* ground_surface(const World& world);

/// Mean snow depth (m) over the cells of `s` that can hold snow.
[[nodiscard]] double mean_depth(const SnowSurface& s);

} // namespace snow
