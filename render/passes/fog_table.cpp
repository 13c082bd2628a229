#include "render/passes/fog_table.hpp"

#include <cmath>

namespace snow {

float layered_fog_density(const Fog& fog, float y) {
    const float h = fog.layer_top - fog.layer_bottom;
    if (!(h > 0.0f) || y < fog.layer_bottom || y > fog.layer_top) {
        return 0.0f;
    }
    const float t = (y - fog.layer_bottom) / h;
    return fog.layer_density * (1.0f - t * t * (3.0f - 2.0f * t)); // mist lies low
}

std::vector<glm::vec2> layered_fog_table(const Fog& fog, std::size_t samples) {
    const double h = static_cast<double>(fog.layer_top) - fog.layer_bottom;
    if (!(h > 0.0) || !std::isfinite(h) || !std::isfinite(fog.layer_density) || samples < 2) {
        return {}; // no layer, or numbers a scene validator should have rejected
    }
    // Composite Simpson on each table interval: exact for the cubic profile.
    constexpr int sub = 8; // even number of Simpson sub-intervals per table step
    const double step = h / static_cast<double>(samples - 1);
    const double hs = step / sub;
    std::vector<glm::vec2> table(samples);
    double integral = 0.0;
    for (std::size_t i = 0; i < samples; ++i) {
        const double y0 = fog.layer_bottom + step * static_cast<double>(i);
        if (i > 0) {
            const double a = y0 - step;
            double sum = 0.0;
            for (int k = 0; k <= sub; ++k) {
                const double w = (k == 0 || k == sub) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
                sum += w * layered_fog_density(fog, static_cast<float>(a + hs * k));
            }
            integral += sum * hs / 3.0;
        }
        table[i] = {static_cast<float>(integral), layered_fog_density(fog, static_cast<float>(y0))};
    }
    return table;
}

} // namespace snow
