#include "render/passes/far_field.hpp"

#include <algorithm>

namespace snow {

std::optional<float> far_field_handover(const SceneVisuals& visuals,
                                        const RenderSettings& settings) {
    const std::optional<SpectralSnow>& s = visuals.spectral;
    if (!s || !(s->start_distance > 0.0f)) { // the scene loader validated it
        return std::nullopt;
    }
    return settings.lod_distance > 0.0f ? std::min(s->start_distance, settings.lod_distance)
                                        : s->start_distance;
}

} // namespace snow
