/// @file sun_cascades.hpp
/// @brief Cascaded shadow maps for the sun [CSM]: the view frustum up to the
/// shadow distance split in three slices [PSSM], each covered by an
/// orthographic view from the sun, fitted and texel-snapped so that the
/// shadows hold still while the camera moves [MSDN-SM]. CPU only.
#pragma once

#include <snow/render.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace snow {

/// Cascades per frame; the atlas holds them side by side.
inline constexpr int sun_cascade_count = 3;

struct SunCascades {
    /// World → clip space of each cascade's view from the sun (what casters are drawn with).
    std::array<glm::mat4, sun_cascade_count> light_clip{};
    /// World → (u, v, depth) in [0, 1] of the atlas, cascade i in its i-th third.
    std::array<glm::mat4, sun_cascade_count> to_atlas{};
    std::array<float, sun_cascade_count> far{};   ///< view depth (m) where each cascade ends
    std::array<float, sun_cascade_count> texel{}; ///< metres one shadow texel spans
};

/// Casters this far (m) beyond a cascade's slice towards the sun still shade it.
inline constexpr float sun_caster_reach = 60.0f;

/// The cascades covering `camera`'s view from its near plane to `distance`
/// (capped at its far plane), `resolution` texels square each, lit from the
/// direction `to_sun` (normalised here).
[[nodiscard]] SunCascades fit_sun_cascades(const ViewCamera& camera, float aspect,
                                           const glm::vec3& to_sun, float distance, int resolution);

} // namespace snow
