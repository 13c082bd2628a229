#include "systems/snowpack/shed.hpp"

#include "systems/core/sim_config.hpp"
#include "systems/core/units.hpp"
#include "systems/flakes/emitter.hpp"
#include "systems/flakes/snowfall.hpp"

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// Diameter (m) of a clump, for rendering.
constexpr float clump_size = 0.01f;

} // namespace

ClumpStart clump_beyond(const SnowSurface& s, std::uint32_t ix, std::uint32_t iz, double ox,
                        double oz, float k_over_m) {
    const double cell = s.cell;
    return {{static_cast<float>(s.x0 + (ix + 0.5 + ox) * cell), s.top_y(s.index(ix, iz)),
             static_cast<float>(s.z0 + (iz + 0.5 + oz) * cell)},
            k_over_m};
}

std::uint32_t shed_units(FlakePool& pool, std::uint32_t units, const ClumpStart& start) {
    std::uint32_t left = units;
    while (left > 0) {
        std::uint32_t slot = 0;
        if (!pool.acquire(slot)) {
            break;
        }
        const std::uint32_t m = std::min(left, max_flake_units);
        pool.px[slot] = start.at.x;
        pool.py[slot] = start.at.y;
        pool.pz[slot] = start.at.z;
        pool.vx[slot] = pool.vy[slot] = pool.vz[slot] = 0.0f;
        pool.k_over_m[slot] = start.k_over_m;
        pool.size[slot] = clump_size;
        pool.mass_units[slot] = m; // settled -> airborne: the ledger total is unchanged
        left -= m;
    }
    return units - left;
}

float clump_drag(const World& w) {
    const float g = std::abs(w.resource<SimConfig>().gravity.y);
    float fall = 1.0f;
    if (const auto* emitters = w.find_pool<Emitter>(); emitters && emitters->size() > 0) {
        const Emitter& e = emitters->components().front();
        fall = static_cast<float>(spectrum_means(e).fall_speed);
    }
    return g / fall;
}

} // namespace snow
