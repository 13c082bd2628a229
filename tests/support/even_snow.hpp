/// @file even_snow.hpp
/// @brief Test support: the same settled snow in every cell of a surface.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <cstdint>

namespace snow::test {

/// Adds `units` of settled snow to every cell of surface `e`.
inline void snow_every_cell(Simulation& sim, SurfaceId e, std::uint32_t units) {
    const std::uint32_t nx = snow_surface(sim, e).nx, nz = snow_surface(sim, e).nz;
    for (std::uint32_t iz = 0; iz < nz; ++iz) {
        for (std::uint32_t ix = 0; ix < nx; ++ix) {
            sim.add_settled_snow(e, ix, iz, units);
        }
    }
}

} // namespace snow::test
