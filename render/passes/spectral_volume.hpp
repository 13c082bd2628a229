/// @file spectral_volume.hpp
/// @brief The far-field snow opacity volume α(x, y, t) of [LZ] (Langer &
/// Zhang): random-phase spectrum on the dispersion surface ω_t = c·ω_y/|ω|,
/// power ∝ 1/|ω| in a band, inverse 3-D FFT, rescaled to [0, 1]. Periodic in
/// x, y and t, so it tiles and loops. CPU only, deterministic, no GL.
#pragma once

#include "render/passes/fft.hpp"
#include <snow/render.hpp>

#include <cstdint>
#include <vector>

namespace snow {

/// [LZ] uses "a small range of constants c": each spatial frequency draws
/// its c from spectral_c_max · [1 − spread, 1].
inline constexpr double spectral_speed_spread = 0.25;

/// The largest c in cycles per loop: size_t / 4, so the fastest component still
/// has four frames per temporal period and stays far from temporal Nyquist.
[[nodiscard]] double spectral_c_max(const SpectralSnow& s);

/// Temporal frequency (cycles per loop) of spatial frequency (kx, ky) (cycles
/// per tile, not both 0) for constant c: round(c·ky/|k|), [LZ eq. 1] with
/// y pointing up, so every component moves down. Odd in (kx, ky).
[[nodiscard]] int spectral_temporal_frequency(int kx, int ky, double c);

/// The volume's spectrum, indexed like the volume (x fastest, negative
/// frequencies wrapped): for each (kx, ky) with band_low ≤ |k| ≤ band_high
/// (Nyquist rows excluded) one bin at kt = spectral_temporal_frequency with
/// amplitude |k|^(−1/2) (power ∝ 1/|ω|) and a random phase from `seed`, and
/// its complex conjugate at (−kx, −ky, −kt), so the inverse transform is real.
[[nodiscard]] std::vector<Complex> spectral_spectrum(const SpectralSnow& s, std::uint64_t seed);

/// α(x, y, t) in [0, 1], x fastest: size_xy × size_xy × size_t values.
struct SpectralVolume {
    std::uint32_t size_xy = 0;
    std::uint32_t size_t = 0;
    std::vector<float> alpha;
    /// Largest |imaginary part| of the inverse FFT over the largest |real part|:
    /// round-off only (the spectrum is conjugate-symmetric).
    double imaginary_ratio = 0.0;
};

/// Inverse 3-D FFT of spectral_spectrum, real part rescaled to [0, 1] [LZ].
/// A band that holds no integer frequency gives α = 0 everywhere (no snow).
/// Expects validate(s) to be empty; throws std::invalid_argument for sizes
/// that are not powers of two.
[[nodiscard]] SpectralVolume build_spectral_volume(const SpectralSnow& s, std::uint64_t seed);

/// How the volume lies on the view and on the clock.
struct SpectralMapping {
    /// Tiles per full turn of azimuth: an integer, so there is no seam behind
    /// the camera; chosen so that one texel covers about one pixel.
    int tiles_around = 1;
    /// Seconds of one period of the volume's t axis. speed 1 makes the lowest
    /// band (the nearest snow) fall at the angular speed of a particle flake
    /// falling at `fall_speed` at start_distance; higher bands are farther and
    /// slower ([LZ]: ω_t = c·ω_y/|ω|).
    double loop_seconds = 1.0;
};

/// The mapping for a view of vertical field of view `fov_y_deg` on a viewport
/// `viewport_height` pixels high.
[[nodiscard]] SpectralMapping spectral_mapping(const SpectralSnow& s, float fov_y_deg,
                                               int viewport_height, float fall_speed);

} // namespace snow
