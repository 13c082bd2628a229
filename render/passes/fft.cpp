#include "render/passes/fft.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace snow {

namespace {

/// (a·b) written out: no FMA contraction, no library call on the NaN path.
Complex multiply(const Complex& a, const Complex& b) {
    return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}

/// Transforms every line of `volume` along one axis: `count` lines of `n`
/// elements `stride` apart, line i starting at offset(i).
template <typename Offset>
void transform_lines(std::span<Complex> volume, const FftPlan& plan, std::size_t stride,
                     std::size_t count, Offset offset, FftDirection direction,
                     std::vector<Complex>& line) {
    const std::size_t n = plan.size();
    for (std::size_t i = 0; i < count; ++i) {
        const std::size_t base = offset(i);
        if (stride == 1) {
            plan.transform(volume.subspan(base, n), direction);
            continue;
        }
        for (std::size_t k = 0; k < n; ++k) {
            line[k] = volume[base + k * stride];
        }
        plan.transform(std::span<Complex>(line).first(n), direction);
        for (std::size_t k = 0; k < n; ++k) {
            volume[base + k * stride] = line[k];
        }
    }
}

} // namespace

FftPlan::FftPlan(std::size_t n) : n_(n) {
    if (!is_power_of_two(n) || n > (std::size_t{1} << 30)) {
        throw std::invalid_argument("fft: length n = " + std::to_string(n) +
                                    " is not a power of two in [1, 2^30]");
    }
    twiddle_.resize(n / 2);
    for (std::size_t k = 0; k < n / 2; ++k) {
        const double angle =
            -2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
        twiddle_[k] = {std::cos(angle), std::sin(angle)};
    }
    int bits = 0;
    while ((std::size_t{1} << bits) < n) {
        ++bits;
    }
    reverse_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        std::uint32_t r = 0;
        for (int b = 0; b < bits; ++b) {
            r |= static_cast<std::uint32_t>((i >> b) & 1u) << (bits - 1 - b);
        }
        reverse_[i] = r;
    }
}

void FftPlan::transform(std::span<Complex> data, FftDirection direction) const {
    if (data.size() != n_) {
        throw std::invalid_argument("fft: data has " + std::to_string(data.size()) +
                                    " elements, the plan is for " + std::to_string(n_));
    }
    for (std::size_t i = 0; i < n_; ++i) {
        if (i < reverse_[i]) {
            std::swap(data[i], data[reverse_[i]]);
        }
    }
    const bool inverse = direction == FftDirection::inverse;
    // Iterative decimation in time: butterflies of growing span.
    for (std::size_t len = 2; len <= n_; len <<= 1) {
        const std::size_t half = len / 2;
        const std::size_t step = n_ / len;
        for (std::size_t start = 0; start < n_; start += len) {
            for (std::size_t j = 0; j < half; ++j) {
                const Complex& t = twiddle_[j * step];
                const Complex w = inverse ? std::conj(t) : t;
                const Complex u = data[start + j];
                const Complex v = multiply(data[start + j + half], w);
                data[start + j] = u + v;
                data[start + j + half] = u - v;
            }
        }
    }
    if (inverse) {
        const double scale = 1.0 / static_cast<double>(n_);
        for (Complex& c : data) {
            c *= scale;
        }
    }
}

void fft_3d(std::span<Complex> volume, std::size_t nx, std::size_t ny, std::size_t nz,
            FftDirection direction) {
    const FftPlan px(nx), py(ny), pz(nz); // each throws for a bad size
    if (volume.size() != nx * ny * nz) {
        throw std::invalid_argument(
            "fft_3d: volume has " + std::to_string(volume.size()) +
            " elements, expected nx·ny·nz = " + std::to_string(nx * ny * nz));
    }
    std::vector<Complex> line(std::max({nx, ny, nz}));
    // A 3-D DFT is the 1-D DFT along each axis in turn (separable kernel).
    transform_lines(
        volume, px, 1, ny * nz, [&](std::size_t i) { return i * nx; }, direction, line);
    transform_lines(
        volume, py, nx, nx * nz, [&](std::size_t i) { return (i / nx) * nx * ny + i % nx; },
        direction, line);
    transform_lines(
        volume, pz, nx * ny, nx * ny, [](std::size_t i) { return i; }, direction, line);
}

} // namespace snow
