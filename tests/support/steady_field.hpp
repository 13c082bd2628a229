/// @file steady_field.hpp
/// @brief Test support: a steady wind along +x (no random walk, no gusts)
/// blowing through a declared wind field, so the field's flow depends on the
/// obstacles alone and runs can be compared tick for tick.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <cstdint>

namespace snow::test {

/// Grid and step interval of a test field.
struct FieldGrid {
    std::uint32_t x = 64, y = 16, z = 64;
    std::uint32_t update_every = 4;
    bool tunnel = false; ///< WindFieldDef::tunnel
};

/// Sets the global wind to `speed` m/s along +x, steady, and declares a field
/// of `grid` with the other settings at their defaults.
inline void blow_steadily_through_field(Simulation& sim, float speed, const FieldGrid& grid) {
    Wind wind;
    wind.base = wind.current = {speed, 0.0f, 0.0f};
    wind.walk = 0.0f;
    wind.max_deviation = 0.0f;
    sim.set_wind(wind);
    WindFieldDef def;
    def.cells_x = grid.x;
    def.cells_y = grid.y;
    def.cells_z = grid.z;
    def.update_every = grid.update_every;
    def.tunnel = grid.tunnel;
    sim.set_wind_field(def);
}

} // namespace snow::test
