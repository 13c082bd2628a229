/// @file far_field.hpp
/// @brief Where the particle flakes hand the falling snow over to the
/// spectral far-field layer [LZ], so that one cannot tell where one
/// becomes the other. Beyond the hand-over distance h a flake at distance d is
/// drawn with probability (h/d)² (the flakes' level of detail,
/// flake_selection.hpp: their on-screen density stays what it is at h), and
/// the layer over a surface D away has the weight 1 − (h/D)²: the share of
/// the snow in front of that surface the particles no longer draw. Both are
/// continuous in distance, so neither a row of the ground nor the horizon
/// (where the ground ends and the sky begins) shows a seam.
#pragma once

#include "ecs/world.hpp"
#include <snow/render.hpp>

#include <optional>

namespace snow {

/// The hand-over distance (m) of visuals with a spectral layer: its
/// start_distance, or the flakes' lod_distance where that is nearer. The same
/// on every GL, level of detail on or off, so a scene looks alike everywhere.
/// Empty without the layer, or for a start of 0 (the layer everywhere:
/// nothing to hand over).
[[nodiscard]] std::optional<float> far_field_handover(const SceneVisuals& visuals,
                                                      const RenderSettings& settings);

} // namespace snow
