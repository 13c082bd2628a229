/// @file rect_surface.hpp
/// @brief Test support: a declared rectangle of snow surface with 10 cm cells.
#pragma once

#include "systems/snowpack/snow_surface.hpp"

namespace snow::test {

/// A flat surface over [x0, x0 + sx] × [z0, z0 + sz] with its bare top at
/// height y and 10 cm cells; `spills` as SurfaceDef::spills.
inline SurfaceDef rect_surface(float x0, float z0, float sx, float sz, float y,
                               bool spills = true) {
    SurfaceDef d;
    d.x0 = x0;
    d.z0 = z0;
    d.size_x = sx;
    d.size_z = sz;
    d.cell = 0.1f;
    d.base_y = y;
    d.spills = spills;
    return d;
}

} // namespace snow::test
