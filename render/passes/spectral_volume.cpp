#include "render/passes/spectral_volume.hpp"

#include "ecs/rng.hpp"
#include "systems/core/random_streams.hpp"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace snow {

namespace {

/// Position of frequency k (possibly negative) along an axis of n samples.
std::size_t wrap(int k, std::uint32_t n) {
    const int m = static_cast<int>(n);
    return static_cast<std::size_t>(((k % m) + m) % m);
}

} // namespace

double spectral_c_max(const SpectralSnow& s) {
    return static_cast<double>(s.size_t) / 4.0;
}

int spectral_temporal_frequency(int kx, int ky, double c) {
    const double k = std::hypot(static_cast<double>(kx), static_cast<double>(ky));
    // lround rounds halves away from zero, so the result is odd in (kx, ky)
    // and a bin and its conjugate stay on the same surface.
    return static_cast<int>(std::lround(c * static_cast<double>(ky) / k));
}

std::vector<Complex> spectral_spectrum(const SpectralSnow& s, std::uint64_t seed) {
    const std::uint32_t n = s.size_xy;
    const std::uint32_t nt = s.size_t;
    std::vector<Complex> spectrum(static_cast<std::size_t>(n) * n * nt);
    const auto at = [&](int kx, int ky, int kt) -> Complex& {
        return spectrum[wrap(kx, n) + n * (wrap(ky, n) + n * wrap(kt, nt))];
    };
    const double c_max = spectral_c_max(s);
    // |kx|, |ky| < n/2: the Nyquist rows are their own conjugates and are left out.
    const int half = static_cast<int>(n / 2);
    for (int ky = 0; ky < half; ++ky) {
        for (int kx = -half + 1; kx < half; ++kx) {
            if (ky == 0 && kx <= 0) {
                continue; // one of each conjugate pair; (0, 0) is outside any band
            }
            const double k = std::hypot(static_cast<double>(kx), static_cast<double>(ky));
            if (k < s.band_low || k > s.band_high) {
                continue; // [LZ]: small flakes only, far from the Nyquist limit
            }
            const RngKey key{
                seed, 0,
                static_cast<std::uint32_t>((ky + half) * static_cast<int>(n) + (kx + half)),
                random_stream::spectral_volume};
            const double phase = 2.0 * std::numbers::pi * rng_uniform(key, 0);
            const double c = c_max * (1.0 - spectral_speed_spread * rng_uniform(key, 1));
            const int kt = spectral_temporal_frequency(kx, ky, c);
            // Power ∝ 1/|ω|: equal power per octave ([LZ], after Field 1987).
            const Complex value = std::polar(1.0 / std::sqrt(k), phase);
            at(kx, ky, kt) = value;
            at(-kx, -ky, -kt) = std::conj(value); // Bracewell's conjugacy: a real volume
        }
    }
    return spectrum;
}

SpectralVolume build_spectral_volume(const SpectralSnow& s, std::uint64_t seed) {
    SpectralVolume v;
    v.size_xy = s.size_xy;
    v.size_t = s.size_t;
    std::vector<Complex> data = spectral_spectrum(s, seed);
    fft_3d(data, s.size_xy, s.size_xy, s.size_t, FftDirection::inverse);
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    double max_real = 0.0;
    double max_imag = 0.0;
    for (const Complex& c : data) {
        lo = std::min(lo, c.real());
        hi = std::max(hi, c.real());
        max_real = std::max(max_real, std::abs(c.real()));
        max_imag = std::max(max_imag, std::abs(c.imag()));
    }
    v.imaginary_ratio = max_real > 0.0 ? max_imag / max_real : 0.0;
    v.alpha.resize(data.size());
    // [LZ]: rescale I(x, y, t) to [0, 1] and use it as the opacity α.
    const double range = hi - lo;
    for (std::size_t i = 0; i < data.size(); ++i) {
        v.alpha[i] = range > 0.0 ? static_cast<float>((data[i].real() - lo) / range) : 0.0f;
    }
    return v;
}

SpectralMapping spectral_mapping(const SpectralSnow& s, float fov_y_deg, int viewport_height,
                                 float fall_speed) {
    SpectralMapping m;
    const double pixels_per_radian =
        static_cast<double>(std::max(viewport_height, 1)) /
        (2.0 * std::tan(glm::radians(static_cast<double>(fov_y_deg)) * 0.5));
    const double around =
        2.0 * std::numbers::pi * pixels_per_radian / static_cast<double>(std::max(s.size_xy, 1u));
    m.tiles_around = std::max(1, static_cast<int>(std::lround(around)));
    // The lowest band moves spectral_c_max / band_low tiles per loop; match that to
    // speed × fall_speed / start_distance radians per second.
    const double tile_radians = 2.0 * std::numbers::pi / m.tiles_around;
    const double reference_distance = std::max(static_cast<double>(s.start_distance), 1.0);
    const double rate = std::max(static_cast<double>(s.speed) * fall_speed, 1e-6);
    m.loop_seconds = spectral_c_max(s) * tile_radians * reference_distance /
                     (std::max(static_cast<double>(s.band_low), 1e-6) * rate);
    return m;
}

} // namespace snow
