#include "render/passes/far_field.hpp"

#include "systems/api/spectral_snow.hpp"

#include <algorithm>

namespace snow {

std::optional<float> far_field_handover(const World& world, const RenderSettings& settings) {
    const SpectralSnow* s = world.try_resource<SpectralSnow>();
    if (s == nullptr || !(s->start_distance > 0.0f)) { // set_spectral_snow validated it
        return std::nullopt;
    }
    return settings.lod_distance > 0.0f ? std::min(s->start_distance, settings.lod_distance)
                                        : s->start_distance;
}

} // namespace snow
