/// @file saltation.hpp
/// @brief The laws of blowing snow the transport is built on: the friction
/// velocity from a wind read above the snow (log law), the threshold friction
/// velocity from the snow's density [Lis07] and the saltation flux above it
/// [PG90] (docs/references.md).
#pragma once

#include <cmath>

namespace snow {

/// Von Kármán's constant of the log law.
inline constexpr double von_karman = 0.4;

/// Density of dry air (kg/m³) at sea-level pressure and `air_c` °C (ideal gas).
[[nodiscard]] inline double air_density(double air_c) {
    return 101325.0 / (287.05 * (air_c + 273.15));
}

/// u*/U(z) of the neutral log law U(z) = (u*/κ)·ln(z/z0), for z > z0.
[[nodiscard]] inline double friction_per_wind(double z, double z0) {
    return von_karman / std::log(z / z0);
}

/// The friction velocity (m/s) snow of `density` kg/m³ starts to drift at:
/// Liston et al. 2007 [Lis07], from the blowing-snow model of Pomeroy's
/// group; 0.13 m/s for fresh snow of 75 kg/m³, 0.25 m/s at 300 kg/m³ and
/// steeply more for wind-hardened snow above that.
[[nodiscard]] inline double threshold_friction_velocity(double density) {
    return density <= 300.0 ? 0.10 * std::exp(0.003 * density) : 0.005 * std::exp(0.013 * density);
}

/// Saltation mass flux (kg per metre of width per second) at friction
/// velocity `u_star` over snow that drifts from `u_star_t` on, in air of
/// `air_kg_m3` (Pomeroy & Gray 1990 [PG90]); 0 at or below the threshold.
[[nodiscard]] inline double saltation_flux(double u_star, double u_star_t, double air_kg_m3,
                                           double g) {
    if (!(u_star > u_star_t)) {
        return 0.0;
    }
    return 0.68 * air_kg_m3 * u_star_t * (u_star * u_star - u_star_t * u_star_t) / (g * u_star);
}

} // namespace snow
