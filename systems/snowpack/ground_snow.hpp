/// @file ground_snow.hpp
/// @brief How much snow lies on the ground (surfaces that lie on no solid)
/// in a rectangle: what tests and the accuracy study measure in the lee of
/// a building.
#pragma once

#include "ecs/world.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <cstdint>

namespace snow {

/// A rectangle of the ground plane (m): x in (x0, x1), z in (z0, z1).
struct GroundRect {
    float x0, z0, x1, z1;
};

/// Settled units in the cells of the ground surfaces whose centres lie in `r`.
[[nodiscard]] inline std::uint64_t ground_units_in(const World& w, const GroundRect& r) {
    std::uint64_t units = 0;
    w.each<SnowSurface, SurfaceOf>([&](Entity, const SnowSurface& s, const SurfaceOf& of) {
        if (!of.owner.is_null()) {
            return;
        }
        for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
            const float z = s.z0 + (static_cast<float>(iz) + 0.5f) * s.cell;
            for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
                const float x = s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell;
                if (x > r.x0 && x < r.x1 && z > r.z0 && z < r.z1) {
                    units += s.snow[s.index(ix, iz)];
                }
            }
        }
    });
    return units;
}

} // namespace snow
