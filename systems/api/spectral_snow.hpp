/// @file spectral_snow.hpp
/// @brief Settings of the far-field spectral snow layer [LZ].
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <cstdint>

namespace snow {

/// World resource. Absent means no FFT volume is built and no pass runs.
struct SpectralSnow {
    std::uint32_t size_xy = 128;  ///< volume size in x and y (power of two)
    std::uint32_t size_t = 64;    ///< frames in the loop (power of two)
    float speed = 1.0f;           ///< c in ω_t = c·ω_y/|ω|
    float band_low = 4.0f;        ///< lowest spatial frequency (cycles per tile)
    float band_high = 32.0f;      ///< highest
    float opacity = 0.6f;         ///< scales α
    float start_distance = 25.0f; ///< where the particle LOD ends
};

/// `spectral.*` [LZ]; sizes must also be powers of two, and the band ordered
/// and below the volume's Nyquist frequency (checked by validate()).
inline constexpr FieldRule<SpectralSnow> spectral_fields[] = {
    {"size_xy", &SpectralSnow::size_xy, between(min_spectral_size_xy, max_spectral_size_xy)},
    {"size_t", &SpectralSnow::size_t, between(min_spectral_size_t, max_spectral_size_t)},
    {"speed", &SpectralSnow::speed, positive},
    {"band_low", &SpectralSnow::band_low, positive},
    {"band_high", &SpectralSnow::band_high, positive},
    {"opacity", &SpectralSnow::opacity, between(0, 1)},
    {"start_distance", &SpectralSnow::start_distance, non_negative},
};

[[nodiscard]] Invalid validate(const SpectralSnow& s);

} // namespace snow
