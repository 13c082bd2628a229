// The project's radix-2 FFT (render/passes/fft.hpp), used for the spectral snow
// volume of [LZ]: against a naive DFT, round trips, 3-D composition.
#include "ecs/rng.hpp"
#include "render/passes/fft.hpp"
#include "systems/core/random_streams.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace snow {
namespace {

std::vector<Complex> random_signal(std::size_t n, std::uint64_t seed) {
    std::vector<Complex> x(n);
    for (std::size_t i = 0; i < n; ++i) {
        const RngKey key{seed, 0, static_cast<std::uint32_t>(i), random_stream::test};
        x[i] = {rng_range(key, 0, -1.0f, 1.0f), rng_range(key, 1, -1.0f, 1.0f)};
    }
    return x;
}

std::vector<Complex> naive_dft(const std::vector<Complex>& x, double sign) {
    const std::size_t n = x.size();
    std::vector<Complex> out(n);
    for (std::size_t k = 0; k < n; ++k) {
        for (std::size_t j = 0; j < n; ++j) {
            const double angle = sign * 2.0 * std::numbers::pi * static_cast<double>(k * j % n) /
                                 static_cast<double>(n);
            out[k] += x[j] * std::polar(1.0, angle);
        }
    }
    return out;
}

double max_error(const std::vector<Complex>& a, const std::vector<Complex>& b) {
    double e = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        e = std::max(e, std::abs(a[i] - b[i]));
    }
    return e;
}

TEST(Fft, ForwardAndInverseMatchTheNaiveDft) {
    for (const std::size_t n : {1u, 2u, 4u, 8u, 32u, 128u}) {
        const std::vector<Complex> x = random_signal(n, n);
        const FftPlan plan(n);
        std::vector<Complex> f = x;
        plan.transform(f, FftDirection::forward);
        EXPECT_LT(max_error(f, naive_dft(x, -1.0)), 1e-12 * static_cast<double>(n)) << n;
        std::vector<Complex> g = x;
        plan.transform(g, FftDirection::inverse);
        std::vector<Complex> expected = naive_dft(x, 1.0);
        for (Complex& c : expected) {
            c /= static_cast<double>(n);
        }
        EXPECT_LT(max_error(g, expected), 1e-13 * static_cast<double>(n)) << n;
    }
}

TEST(Fft, InverseOfForwardReturnsTheInput) {
    const std::vector<Complex> x = random_signal(4096, 7);
    const FftPlan plan(x.size());
    std::vector<Complex> y = x;
    plan.transform(y, FftDirection::forward);
    plan.transform(y, FftDirection::inverse);
    EXPECT_LT(max_error(x, y), 1e-14);
}

TEST(Fft, DeltaAndPureToneHaveTheirTextbookSpectra) {
    const std::size_t n = 64;
    const FftPlan plan(n);
    std::vector<Complex> delta(n);
    delta[0] = 1.0;
    plan.transform(delta, FftDirection::forward);
    for (const Complex& c : delta) {
        EXPECT_NEAR(std::abs(c - Complex(1.0, 0.0)), 0.0, 1e-15);
    }
    // cos(2π·5j/n) → n/2 at bins 5 and n − 5, zero elsewhere.
    std::vector<Complex> tone(n);
    for (std::size_t j = 0; j < n; ++j) {
        tone[j] = std::cos(2.0 * std::numbers::pi * 5.0 * static_cast<double>(j) / n);
    }
    plan.transform(tone, FftDirection::forward);
    for (std::size_t k = 0; k < n; ++k) {
        const double expected = (k == 5 || k == n - 5) ? n / 2.0 : 0.0;
        EXPECT_NEAR(std::abs(tone[k]), expected, 1e-12) << k;
    }
}

TEST(Fft, ParsevalHolds) {
    const std::vector<Complex> x = random_signal(512, 3);
    std::vector<Complex> f = x;
    FftPlan(x.size()).transform(f, FftDirection::forward);
    double ex = 0.0, ef = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        ex += std::norm(x[i]);
        ef += std::norm(f[i]);
    }
    EXPECT_NEAR(ef / static_cast<double>(x.size()), ex, 1e-10 * ex);
}

TEST(Fft, RejectsLengthsThatAreNotPowersOfTwoNamingThem) {
    for (const std::size_t n : {0u, 3u, 12u, 100u}) {
        try {
            const FftPlan plan(n);
            ADD_FAILURE() << "no error for n = " << n;
        } catch (const std::invalid_argument& e) {
            EXPECT_NE(std::string(e.what()).find("n = " + std::to_string(n)), std::string::npos)
                << e.what();
        }
    }
    const FftPlan plan(8);
    std::vector<Complex> wrong(4);
    EXPECT_THROW(plan.transform(wrong, FftDirection::forward), std::invalid_argument);
    std::vector<Complex> volume(4 * 4 * 4);
    EXPECT_THROW(fft_3d(volume, 4, 4, 3, FftDirection::forward), std::invalid_argument);
    EXPECT_THROW(fft_3d(volume, 4, 4, 8, FftDirection::forward), std::invalid_argument);
}

TEST(Fft3d, PlaneWaveGoesToOneBinAndBack) {
    const std::size_t nx = 8, ny = 4, nz = 16;
    const int a = 3, b = 1, c = 13;
    std::vector<Complex> v(nx * ny * nz);
    for (std::size_t z = 0; z < nz; ++z) {
        for (std::size_t y = 0; y < ny; ++y) {
            for (std::size_t x = 0; x < nx; ++x) {
                const double phase =
                    2.0 * std::numbers::pi *
                    (static_cast<double>(a * x) / nx + static_cast<double>(b * y) / ny +
                     static_cast<double>(c * z) / nz);
                v[x + nx * (y + ny * z)] = std::polar(1.0, phase);
            }
        }
    }
    const std::vector<Complex> original = v;
    fft_3d(v, nx, ny, nz, FftDirection::forward);
    const std::size_t peak = a + nx * (b + ny * c);
    for (std::size_t i = 0; i < v.size(); ++i) {
        EXPECT_NEAR(std::abs(v[i]), i == peak ? static_cast<double>(v.size()) : 0.0, 1e-10) << i;
    }
    fft_3d(v, nx, ny, nz, FftDirection::inverse);
    EXPECT_LT(max_error(v, original), 1e-14);
}

TEST(Fft3d, InverseOfForwardReturnsARandomVolume) {
    const std::size_t nx = 16, ny = 32, nz = 8;
    const std::vector<Complex> x = random_signal(nx * ny * nz, 11);
    std::vector<Complex> y = x;
    fft_3d(y, nx, ny, nz, FftDirection::forward);
    fft_3d(y, nx, ny, nz, FftDirection::inverse);
    EXPECT_LT(max_error(x, y), 1e-14);
}

} // namespace
} // namespace snow
