/// @file spectral_snow.hpp
/// @brief Settings of the far-field spectral snow layer [LZ].
#pragma once

#include <cstdint>
#include <string>

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

[[nodiscard]] std::string validate(const SpectralSnow& s);

} // namespace snow
