/// @file drifting_snow.hpp
/// @brief Snow blowing over a flat snow field: the saltation flux the
/// transport carries across a line, measured from the snow itself. What the
/// tests and snow_validate hold to: the flux is the same at any cell size,
/// depth, step and field resolution, and within the band of Pomeroy & Gray's
/// saltation law [PG90] (docs/references.md, docs/wind_field.md "Transport").
#pragma once

#include <cstdint>

namespace snow {

/// One run: a 10 m × 1 m strip of snow on a ground that never spills, in a
/// steady wind along +x through a wind field over a 12 m × 4 m × 2 m box.
struct DriftingSnow {
    float wind = 12.0f;       ///< the free wind (m/s)
    float cell = 0.05f;       ///< the snow's cell edge (m)
    float depth = 0.03f;      ///< fresh snow on every cell at the start (m)
    float dt = 1.0f / 60.0f;  ///< the tick (s)
    float field_cell = 0.25f; ///< the field's horizontal cell edge (m); 4 layers in y
    float seconds = 3.0f;     ///< how long the flux is measured
    /// WindTransportDef::adjustment_length: short, so the flux across the
    /// strip's middle is the saturated one [PG90] measured.
    float adjustment_length = 0.1f;
};

/// What a run gives.
struct DriftFlux {
    /// Mass that crossed the strip's middle (kg per metre of width per
    /// second): what the upwind half lost, over the time and the width.
    double flux = 0.0;
    /// The friction velocity the log law gives for the free wind at 10 m
    /// over the transport's roughness, and the threshold of the fresh snow
    /// (m/s): what Pomeroy & Gray's law is evaluated at for comparison.
    double u_star_10m = 0.0;
    double u_star_t = 0.0;
    /// Pomeroy & Gray's saltation flux at those (kg/(m·s)).
    double published = 0.0;
    /// Density (kg/m³) of the snow the downwind half gained: its units over
    /// the volume they added.
    double laid_density = 0.0;
    bool balanced = true; ///< the ledger held every tick
};

[[nodiscard]] DriftFlux drifting_snow(const DriftingSnow& run);

} // namespace snow
