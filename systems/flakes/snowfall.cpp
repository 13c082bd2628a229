#include "systems/flakes/snowfall.hpp"

#include "systems/core/units.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// v = a·D^b m/s and m = c·D^d mg, D in mm [LH74].
struct PowerLaws {
    double speed_coeff, speed_exponent, mass_coeff, mass_exponent;
};

PowerLaws laws(CrystalType crystal) {
    switch (crystal) {
    case CrystalType::rimed_aggregate:
        return {0.79, 0.27, 0.037, 1.9};
    case CrystalType::dendrite_aggregate:
        break;
    }
    return {0.8, 0.16, 0.073, 1.4};
}

double millimetres(float size) {
    return static_cast<double>(size) * 1000.0;
}

/// Quantiles at which spectrum_means samples the spectrum (midpoints).
constexpr int spectrum_samples = 256;

} // namespace

float fall_speed(CrystalType crystal, float size) {
    const PowerLaws l = laws(crystal);
    return static_cast<float>(l.speed_coeff * std::pow(millimetres(size), l.speed_exponent));
}

double flake_mass_mg(CrystalType crystal, float size) {
    const PowerLaws l = laws(crystal);
    return l.mass_coeff * std::pow(millimetres(size), l.mass_exponent);
}

float size_at(const Emitter& e, float u) {
    // Inverse of the clipped exponential's distribution function.
    const double lo = e.size_min, hi = e.size_max, mean = e.size_mean;
    const double span = 1.0 - std::exp(-(hi - lo) / mean);
    const double d = lo - mean * std::log1p(-static_cast<double>(u) * span);
    return static_cast<float>(std::fmin(d, hi));
}

SpectrumMeans spectrum_means(const Emitter& e) {
    SpectrumMeans m;
    for (int i = 0; i < spectrum_samples; ++i) {
        const float size = size_at(e, static_cast<float>((i + 0.5) / spectrum_samples));
        m.mass_mg += flake_mass_mg(e.crystal, size);
        m.fall_speed += fall_speed(e.crystal, size);
    }
    m.mass_mg /= spectrum_samples;
    m.fall_speed /= spectrum_samples;
    return m;
}

double parcel_multiplicity(const Emitter& e, double ground_area) {
    return parcel_multiplicity(e, ground_area, spectrum_means(e));
}

double parcel_multiplicity(const Emitter& e, double ground_area, const SpectrumMeans& means) {
    if (e.rate <= 0.0f) {
        return 0.0;
    }
    const double kg_per_s = static_cast<double>(e.snowfall_kg_m2_h) * ground_area / 3600.0;
    return kg_per_s / (static_cast<double>(e.rate) * means.mass_mg * 1.0e-6);
}

double min_parcel_rate(const Emitter& e, double ground_area) {
    Emitter one_per_second = e;
    one_per_second.rate = 1.0f;
    const double heaviest =
        parcel_units(e, parcel_multiplicity(one_per_second, ground_area), e.size_max);
    return heaviest / max_flake_units; // a parcel's mass scales as 1/rate
}

Emitter with_snowfall(const Emitter& e, float snowfall_kg_m2_h, double ground_area) {
    Emitter out = e;
    out.snowfall_kg_m2_h = snowfall_kg_m2_h;
    out.rate = std::max(out.rate, static_cast<float>(std::ceil(min_parcel_rate(out, ground_area))));
    return out;
}

float heaviest_snowfall_kg_m2_h(const Emitter& e, double ground_area) {
    // min_parcel_rate is proportional to the snowfall.
    const double limit = e.snowfall_kg_m2_h * (e.rate / min_parcel_rate(e, ground_area));
    return static_cast<float>(limit * (1.0 - 1e-6));
}

double parcel_units(const Emitter& e, double multiplicity, float size) {
    return multiplicity * flake_mass_mg(e.crystal, size) * 1.0e-6 / unit_kg;
}

} // namespace snow
