/// @file ground_wind.hpp
/// @brief The wind field over a ground surface: a closed 2 m cube standing
/// on a ground whose top lies half a metre above the bounds floor (as the
/// village's does), in a steady 2 m/s wind. What the tests and snow_validate
/// hold to: no air inside a closed building, and the reattachment behind a
/// surface-mounted cube [MT93] (docs/references.md, docs/wind_field.md).
#pragma once

namespace snow {

/// The cube as a box collider, or as a closed shell of 12 triangles.
enum class CubeShape { box, mesh };

/// Time means of the developed flow (after `spin_up_s`, over `mean_s`).
struct GroundCubeWake {
    /// Mean horizontal speed over the cube's footprint (the centres of the
    /// field cells inside it) at 0.1 and 0.25 m above the ground, over the
    /// free stream.
    double inside_over_free = 0.0;
    /// Along the centreline 0.25 m above the ground (the lowest air layer),
    /// behind the lee face, in cube heights h: where the mean air first
    /// turns back and where it flows forward again. Negative: not found.
    double reversal_over_h = -1.0;
    double reattachment_over_h = -1.0;
};

[[nodiscard]] GroundCubeWake ground_cube_wake(CubeShape shape, double spin_up_s = 20.0,
                                              double mean_s = 8.0);

} // namespace snow
