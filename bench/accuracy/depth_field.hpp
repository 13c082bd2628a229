/// @file depth_field.hpp
/// @brief Settled snow of a run as depth (m) per cell of every surface, and
/// its error against a reference field that may use other cell sizes.
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <cstdint>
#include <vector>

namespace snow::accuracy {

/// One surface's grid and its snow depth (m) per cell, row-major, x fastest.
struct SurfaceDepth {
    float x0 = 0.0f, z0 = 0.0f, cell = 0.0f;
    std::uint32_t nx = 0, nz = 0;
    std::vector<double> depth;

    /// Depth at world (x, z): the cell containing it, the nearest edge cell
    /// when (x, z) lies just outside the grid (grids of different cell sizes
    /// over one top differ in extent by less than a cell).
    [[nodiscard]] double sample(double x, double z) const;
    /// Snow volume (m^3): depth times cell area, summed.
    [[nodiscard]] double volume() const;
};

/// Every surface of a run, in creation order (the scene's node order).
struct DepthField {
    std::vector<SurfaceDepth> surfaces;
};

/// Depth fields of the surfaces of `sim` now.
[[nodiscard]] DepthField capture_depth(const Simulation& sim);

/// Cell-wise mean of fields with identical grids (an ensemble reference).
[[nodiscard]] DepthField mean_field(const std::vector<DepthField>& fields);

struct DepthError {
    double l1 = 0.0;     ///< area-weighted mean |depth error| over all surfaces (m)
    double linf = 0.0;   ///< largest |depth error| of one block (m)
    double rel_l1 = 0.0; ///< Σ|volume error| / reference volume, over blocks
    double centroid_shift =
        0.0; ///< reference-volume-weighted mean shift of each surface's centroid (m)
    double volume_ratio = 0.0; ///< settled volume of the run / of the reference
};

/// Error of `run` against `ref`. Both are sampled at the reference's cell
/// centres (the run's cell containing each centre, so a coarse run counts
/// as piecewise constant), then averaged over square blocks of about `block`
/// metres (whole reference cells, at least one) before differencing.
/// Surfaces pair up by index; throws std::invalid_argument if counts differ.
[[nodiscard]] DepthError compare_depth(const DepthField& run, const DepthField& ref, float block);

} // namespace snow::accuracy
