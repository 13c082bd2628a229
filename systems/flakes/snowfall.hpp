/// @file snowfall.hpp
/// @brief What an emitter's snow is made of: the exponential size spectrum
/// of snowfall [GM58], mass and still-air fall speed by size [LH74], and how
/// many real flakes each simulated parcel stands for.
#pragma once

#include <snow/defs.hpp>

namespace snow {

/// One real flake of maximum dimension `size` (m): its still-air fall speed
/// (m/s) and its mass (mg), by its crystal type's power laws [LH74].
[[nodiscard]] float fall_speed(CrystalType crystal, float size);
[[nodiscard]] double flake_mass_mg(CrystalType crystal, float size);

/// The size (m) at quantile `u` in [0, 1) of the emitter's spectrum
/// N0·e^(−D/size_mean) clipped to [size_min, size_max].
[[nodiscard]] float size_at(const Emitter& e, float u);

/// Averages over the emitter's spectrum, flake by flake.
struct SpectrumMeans {
    double mass_mg = 0.0;
    double fall_speed = 0.0; ///< m/s
};
[[nodiscard]] SpectrumMeans spectrum_means(const Emitter& e);

/// Real flakes per parcel: the declared snowfall over `ground_area` m²,
/// shared among `rate` parcels a second (0 when the emitter makes none).
[[nodiscard]] double parcel_multiplicity(const Emitter& e, double ground_area);
/// The same with the spectrum's means already at hand (spawn needs both).
[[nodiscard]] double parcel_multiplicity(const Emitter& e, double ground_area,
                                         const SpectrumMeans& means);

/// The fewest parcels a second that carry the snowfall over `ground_area` m²
/// with no parcel (the largest size's) above max_flake_units.
[[nodiscard]] double min_parcel_rate(const Emitter& e, double ground_area);

/// `e` with `snowfall_kg_m2_h` and its rate raised, where needed, to the
/// fewest parcels a second that carry it over `ground_area` m².
[[nodiscard]] Emitter with_snowfall(const Emitter& e, float snowfall_kg_m2_h, double ground_area);

/// The heaviest snowfall (kg/m²/h) `e.rate` parcels a second carry over
/// `ground_area` m² (a hair under, so that the float passes validation).
[[nodiscard]] float heaviest_snowfall_kg_m2_h(const Emitter& e, double ground_area);

/// A parcel's expected mass in units (a real number; spawn rounds it
/// stochastically, so the snowfall is exact on average).
[[nodiscard]] double parcel_units(const Emitter& e, double multiplicity, float size);

} // namespace snow
