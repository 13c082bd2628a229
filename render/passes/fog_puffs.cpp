#include "render/passes/fog_puffs.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace snow {

namespace {

constexpr double pi = std::numbers::pi;

/// sin(u)/u, 1 at u = 0.
double sinc(double u) {
    return std::abs(u) < 1e-4 ? 1.0 - u * u / 6.0 : std::sin(u) / u;
}

bool is_gabor(const FogPuff& puff) {
    return puff.frequency != glm::vec3(0.0f);
}

} // namespace

double puff_density(const FogPuff& puff, const glm::dvec3& p) {
    const glm::dvec3 r = p - glm::dvec3(puff.center);
    const double sigma = puff.sigma;
    const double gauss = puff.density * std::exp(-glm::dot(r, r) / (2.0 * sigma * sigma));
    if (!is_gabor(puff)) {
        return gauss;
    }
    return gauss * 0.5 * (1.0 + std::cos(glm::dot(glm::dvec3(puff.frequency), r) + puff.phase));
}

std::complex<double> scaled_complex_erf(double x, double y) {
    const double ey = std::exp(-y * y);
    const double ex = std::exp(-x * x);
    const double u = x * y;
    // (1 − cos 2xy)/(2πx) and sin(2xy)/(2πx), written to stay finite at x = 0.
    double re = std::erf(x) * ey + ex * ey * y * std::sin(u) * sinc(u) / pi;
    double im = ex * ey * y * sinc(2.0 * u) / pi;
    if (ex == 0.0) {
        return {re, im};
    }
    const double c2 = std::cos(2.0 * u);
    const double s2 = std::sin(2.0 * u);
    // e^(−y²)·e^(−n²/4)·cosh(ny) = (e^(−(n/2−y)²) + e^(−(n/2+y)²))/2 (sinh: −); terms
    // beyond n ≈ 2|y| + 12 are below 1e-16 of the largest.
    const int terms = static_cast<int>(std::ceil(2.0 * std::abs(y))) + 12;
    double sum_re = 0.0;
    double sum_im = 0.0;
    for (int n = 1; n <= terms; ++n) {
        const double h = 0.5 * n;
        const double e = std::exp(-y * y - h * h);
        const double plus = std::exp(-(h - y) * (h - y));
        const double minus = std::exp(-(h + y) * (h + y));
        const double ch = 0.5 * (plus + minus);
        const double sh = 0.5 * (plus - minus);
        const double denom = static_cast<double>(n) * n + 4.0 * x * x;
        sum_re += (2.0 * x * e - 2.0 * x * ch * c2 + n * sh * s2) / denom;
        sum_im += (2.0 * x * ch * s2 + n * sh * c2) / denom;
    }
    re += 2.0 / pi * ex * sum_re;
    im += 2.0 / pi * ex * sum_im;
    return {re, im};
}

double puff_optical_depth(const FogPuff& puff, const glm::dvec3& a, const glm::dvec3& b) {
    const glm::dvec3 ab = b - a;
    const double length = glm::length(ab);
    const double sigma = puff.sigma;
    if (!(length > 0.0) || !(sigma > 0.0)) {
        return 0.0;
    }
    const glm::dvec3 dir = ab / length;
    // Along the ray, |p − c|² = (s + b)² + h²: a 1-D Gaussian in s around −b.
    const glm::dvec3 q = a - glm::dvec3(puff.center);
    const double along = glm::dot(q, dir);
    const glm::dvec3 perp = q - along * dir;
    const double inv = 1.0 / (sigma * std::sqrt(2.0)); // x = s + b → t = x·inv
    const double t0 = along * inv;
    const double t1 = (along + length) * inv;
    // ∫ e^(−x²/2σ²) dx from x0 to x1 = (√π/2)/inv · (erf(t1) − erf(t0)).
    const double scale =
        puff.density * std::exp(-glm::dot(perp, perp) * inv * inv) * (std::sqrt(pi) / 2.0) / inv;
    const double gauss = std::erf(t1) - std::erf(t0);
    if (!is_gabor(puff)) {
        return scale * gauss;
    }
    // cos(k·(p − c) + phase) = cos(κx + θ) along the ray; ∫ e^(−t²) e^(2iβt) dt =
    // e^(−β²)(√π/2)[erf(t − iβ)], β = κσ/√2: the complex error function.
    const glm::dvec3 k(puff.frequency);
    const double beta = glm::dot(k, dir) * sigma / std::sqrt(2.0);
    const double theta = glm::dot(k, perp) + puff.phase;
    const std::complex<double> delta =
        scaled_complex_erf(t1, -beta) - scaled_complex_erf(t0, -beta);
    const double wave = (std::polar(1.0, theta) * delta).real();
    return scale * 0.5 * (gauss + wave);
}

double puffs_optical_depth(std::span<const FogPuff> puffs, const glm::dvec3& a,
                           const glm::dvec3& b) {
    double sum = 0.0;
    for (const FogPuff& puff : puffs) {
        sum += puff_optical_depth(puff, a, b);
    }
    return sum;
}

} // namespace snow
