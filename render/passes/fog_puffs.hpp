/// @file fog_puffs.hpp
/// @brief Fog puffs of [PE] (Perlin): Gaussian and Gabor density blobs
/// whose line integrals have closed forms, so the optical depth of any ray
/// costs a few erf evaluations instead of a ray march. CPU reference (double)
/// of what assets/shaders/fog_puffs.frag computes per pixel, and a probe that
/// runs that shader code on given segments (the only function here needing GL).
#pragma once

#include <snow/render.hpp>

#include <glm/vec3.hpp>

#include <complex>
#include <cstddef>
#include <span>
#include <vector>

namespace snow {

/// Puffs the shader takes (uniform arrays of this size): the pass draws the
/// first ones of Fog::puffs and reports the rest once.
inline constexpr std::size_t max_drawn_puffs = 32;

/// Density of `puff` at p, in halvings per metre (transparency is 0.5^∫density):
/// Gaussian density·e^(−|p−c|²/2σ²); with a non-zero wave vector k a Gabor
/// puff, the Gaussian times (1 + cos(k·(p − c) + phase))/2, which stays ≥ 0.
[[nodiscard]] double puff_density(const FogPuff& puff, const glm::dvec3& p);

/// ∫ puff_density along the segment a→b, in closed form: a line through a
/// Gaussian is a 1-D Gaussian (erf), through a Gabor a 1-D Gabor (complex erf)
/// [PE]. 0 for a = b or a puff with σ ≤ 0.
[[nodiscard]] double puff_optical_depth(const FogPuff& puff, const glm::dvec3& a,
                                        const glm::dvec3& b);

/// Sum of puff_optical_depth over `puffs`.
[[nodiscard]] double puffs_optical_depth(std::span<const FogPuff> puffs, const glm::dvec3& a,
                                         const glm::dvec3& b);

/// e^(−y²)·erf(x + iy) by Abramowitz & Stegun 7.1.29 (relative error ~1e-16),
/// with the e^(−y²) folded into every term so none overflows for large |y|.
[[nodiscard]] std::complex<double> scaled_complex_erf(double x, double y);

/// One straight segment for shader_puff_optical_depths.
struct PuffSegment {
    glm::vec3 a{0.0f};
    glm::vec3 b{0.0f};
};

/// The optical depth of each segment through `puffs` (at most max_drawn_puffs)
/// as the pass's GLSL computes it, one fragment per segment into a float
/// target: lets tests hold the shader to the CPU reference. Needs a current
/// context with the GL loader; leaves the framebuffer binding and viewport as
/// it found them. Throws RenderError if the float target is not renderable.
[[nodiscard]] std::vector<float> shader_puff_optical_depths(std::span<const FogPuff> puffs,
                                                            std::span<const PuffSegment> segments);

} // namespace snow
