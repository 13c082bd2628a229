/// @file units_in.hpp
/// @brief Test support: the snow a surface holds over a world rectangle.
#pragma once

#include "systems/snowpack/snow_surface.hpp"

#include <cstdint>

namespace snow::test {

/// Units on the cells of `s` whose centres lie in [x0, x1) × [z0, z1).
inline std::uint64_t units_in(const SnowSurface& s, float x0, float z0, float x1, float z1) {
    std::uint64_t sum = 0;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const float x = s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell;
            const float z = s.z0 + (static_cast<float>(iz) + 0.5f) * s.cell;
            if (x >= x0 && x < x1 && z >= z0 && z < z1) {
                sum += s.snow[s.index(ix, iz)];
            }
        }
    }
    return sum;
}

} // namespace snow::test
