/// @file fog_table.hpp
/// @brief Layered fog [PE]: density varies with height only, so the
/// optical depth of any ray is (E(yB) − E(yA)) / cos θ with E a precomputed
/// 1-D table of the density's integral.
#pragma once

#include <snow/render.hpp>

#include <glm/vec2.hpp>

#include <cstddef>
#include <vector>

namespace snow {

/// Texels of the E(y) table the renderer uploads.
inline constexpr std::size_t fog_table_size = 256;

/// Density (halvings per metre: transparency is 0.5^∫density) at height y:
/// layer_density at layer_bottom, fading smoothly to 0 at layer_top, 0 outside.
[[nodiscard]] float layered_fog_density(const Fog& fog, float y);

/// `samples` (≥ 2) evenly spaced heights from layer_bottom to layer_top; entry i
/// holds (E(y_i), density(y_i)) with E(y) = ∫ density from −∞ to y, integrated
/// numerically so any density profile works. Empty for an empty layer or
/// non-finite settings.
[[nodiscard]] std::vector<glm::vec2> layered_fog_table(const Fog& fog, std::size_t samples);

} // namespace snow
