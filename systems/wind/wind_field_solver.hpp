/// @file wind_field_solver.hpp
/// @brief Internals of the wind field (wind_field.cpp, wind_field_obstacles.cpp,
/// wind_field_system.cpp): the obstacle cells and the solver's scratch.
#pragma once

#include "ecs/host_memory.hpp"
#include "ecs/world.hpp"
#include "systems/wind/wind_field.hpp"

#include <cstdint>

namespace snow {

/// Which sides of the box take the global wind in (bit set: inflow), and
/// whether the z sides are walls (WindFieldDef::tunnel). The floor is a wall
/// and the top is always open; the rest are open outflow.
enum FieldSide : std::uint8_t {
    inflow_x_min = 1,
    inflow_x_max = 2,
    inflow_z_min = 4,
    inflow_z_max = 8,
    walls_z = 16,
};

/// The sides a wind blows in through (those it points away from), or for a
/// tunnel the x sides it blows in through and the z walls.
[[nodiscard]] std::uint8_t field_sides(const glm::vec3& wind, bool tunnel);

/// The pressure sweeps' arrays with each colour (i + j + k) & 1 of the
/// centre lattice dense (layout in wind_field.cpp, odd_up): the pressure
/// while the sweeps run, their right-hand side and the inverse diagonal.
struct ColourSplit {
    std::int32_t px = 0;    ///< row length: the lattice's x dim, rounded up to odd
    std::int32_t plane = 0; ///< px · the lattice's y dim rounded up to odd
    Vector<float> pressure[2], rhs[2], inv_diag[2];
};

/// World resource beside a WindField: what the geometry makes of the grid
/// (rebuilt when SourceVersions::solids changes) and buffers reused every step.
/// Everything here follows from the geometry and the field's state.
struct WindFieldSolver {
    bool built = false;
    std::uint64_t built_from_solids = 0;   ///< SourceVersions::solids it was built from
    std::uint64_t built_from_surfaces = 0; ///< SourceVersions::surfaces it was built from
    Vector<std::uint8_t> solid;            ///< per cell of the centre lattice (ghosts 0)
    /// Per cell of the centre lattice: the pressure-loss coefficient of the
    /// porous box filling it (fence_pressure_loss), 0 for open air.
    Vector<float> resistance;
    /// Per horizontal component (0: u, 2: w; 1 stays empty): the faces beside
    /// a porous cell and their drag, (k_lo + k_hi) / (4·cell) per metre of
    /// air passed: the fence's loss spread over the cell it fills [Wil85].
    Vector<std::int32_t> porous_faces[3];
    Vector<float> porous_drag[3];
    /// Per column (x fastest): how many cells from the bottom the ground
    /// fills (0: none); the top one reads as the air above it.
    Vector<std::int32_t> ground_cells;
    Vector<std::int32_t> ground_now; ///< ground_moved()'s columns, as the snow stands now
    Vector<std::int32_t> reach;      ///< the enclosed-air search's stack
    Vector<std::int32_t> closed[3];  ///< per component: faces touching a solid cell
    Vector<float> inv_diag;          ///< per cell: 1 / Σ coefficients of its open neighbours
    std::uint8_t diag_sides = 0xff;  ///< field_sides inv_diag was built for
    ColourSplit split;               ///< the sweeps' arrays, by colour
    Vector<float> advected[3];       ///< semi-Lagrangian output, swapped with the velocity
    Vector<float> divergence;
};

/// Marks the cells of the centre lattice that are not air (into s.solid,
/// s.ground_cells; wind_field_obstacles.cpp): what colliders fill (boxes,
/// spheres, triangle meshes), the cells at or below the ground surfaces and
/// air no open side reaches (inside a closed building).
void mark_obstacles(const World& w, const WindField& f, WindFieldSolver& s);

/// Per column of the field (x fastest), into `filled`: how many cells from
/// the bottom the ground fills, up to the last cell whose centre is at or
/// below the snow top of a ground surface (one lying on no solid) there: the
/// top rounded to the nearest cell face, as a box's faces are. The air then
/// flows over the terrain and its drifts, not over the bounds floor under
/// them, and never under a building standing on the ground.
void ground_columns(const World& w, const WindField& f, Vector<std::int32_t>& filled);

/// Whether the snow has moved the ground's columns since the obstacles were
/// marked (then they are marked again).
[[nodiscard]] bool ground_moved(const World& w, const WindField& f, WindFieldSolver& s);

/// Gives `s` room for everything the field's obstacle rebuilds and steps
/// write (prepare_wind_field): then neither allocates.
void reserve_solver(const WindField& f, WindFieldSolver& s);

/// Takes a new obstacle mask: rebuilds the face masks and stops the air in
/// newly solid faces (the field's state changes, deterministically).
void apply_obstacles(WindField& f, WindFieldSolver& s);

/// One solver step of dt seconds with `wind` (m/s) on the upwind sides (a
/// tunnel takes its x and y parts); the first step fills the field with the
/// inflow and projects it [STAM §3].
void step_wind_field(WindField& f, WindFieldSolver& s, const glm::vec3& wind, float dt);

/// Mean |∇·u| over the open cells (1/s): how far the last projection is
/// from incompressible (for tests).
[[nodiscard]] double wind_field_divergence(const WindField& f, const WindFieldSolver& s);

} // namespace snow
