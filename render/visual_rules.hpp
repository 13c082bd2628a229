/// @file visual_rules.hpp
/// @brief The field tables and checks of the render-only settings a scene
/// declares (SceneVisuals::fog [PE], [SKY], ::spectral [LZ] and ::sun): the scene
/// loader reports bad values by field, the renderer refuses a spectral layer
/// it cannot build. Inline: the scene library has no GL and links no renderer.
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <bit>
#include <cmath>
#include <string>
#include <utility>

#include <snow/render.hpp>

namespace snow {

/// `fog.*` (the mode is a choice; puffs have their own table; layer_bottom
/// <= layer_top is checked by validate()).
inline constexpr FieldRule<Fog> fog_fields[] = {
    {"color", &Fog::color},
    {"density", &Fog::density, non_negative},
    {"half_distance", &Fog::half_distance, positive},
    {"layer_bottom", &Fog::layer_bottom},
    {"layer_top", &Fog::layer_top},
    {"layer_density", &Fog::layer_density, non_negative},
};
/// `fog.puffs[i].*`.
inline constexpr FieldRule<FogPuff> fog_puff_fields[] = {
    {"center", &FogPuff::center},
    {"sigma", &FogPuff::sigma, positive},
    {"density", &FogPuff::density, non_negative},
    {"frequency", &FogPuff::frequency},
    {"phase", &FogPuff::phase},
};

/// `spectral.*` [LZ]; sizes must also be powers of two, and the band ordered
/// and below the volume's Nyquist frequency (checked by validate()).
inline constexpr FieldRule<SpectralSnow> spectral_fields[] = {
    {"size_xy", &SpectralSnow::size_xy, between(min_spectral_size_xy, max_spectral_size_xy)},
    {"size_t", &SpectralSnow::size_t, between(min_spectral_size_t, max_spectral_size_t)},
    {"speed", &SpectralSnow::speed, positive},
    {"band_low", &SpectralSnow::band_low, positive},
    {"band_high", &SpectralSnow::band_high, positive},
    {"opacity", &SpectralSnow::opacity, between(0, 1)},
    {"start_distance", &SpectralSnow::start_distance, non_negative},
};

/// `sun.*`; the direction must also have a length (checked by validate()).
inline constexpr FieldRule<Sun> sun_fields[] = {
    {"direction", &Sun::direction},
    {"color", &Sun::color, non_negative},
    {"intensity", &Sun::intensity, non_negative},
};

[[nodiscard]] inline Invalid validate(const Sun& s) {
    Invalid e = check_fields("sun", sun_fields, s);
    const glm::vec3 d = s.direction;
    const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(length > 0.0)) {
        check::fail(e, "sun.direction", "of length > 0", length);
    }
    return e;
}

[[nodiscard]] inline Invalid validate(const Fog& f) {
    Invalid e = check_fields("fog", fog_fields, f);
    check::ordered(e, "fog", "layer_bottom", f.layer_bottom, "layer_top", f.layer_top);
    for (std::size_t i = 0; i < f.puffs.size() && e.empty(); ++i) {
        check_fields(e, "fog.puffs[" + std::to_string(i) + "]", fog_puff_fields, f.puffs[i]);
    }
    return e;
}

[[nodiscard]] inline Invalid validate(const SpectralSnow& s) {
    Invalid e = check_fields("spectral", spectral_fields, s);
    for (const auto& [field, size] :
         {std::pair{"spectral.size_xy", s.size_xy}, std::pair{"spectral.size_t", s.size_t}}) {
        if (!std::has_single_bit(size)) {
            check::fail(e, field, "a power of two", size);
        }
    }
    check::ordered(e, "spectral", "band_low", s.band_low, "band_high", s.band_high);
    // The band must fit the volume: at most its Nyquist frequency [LZ].
    check::number(e, "spectral.band_high", up_to(s.size_xy / 2.0), s.band_high);
    return e;
}

} // namespace snow
