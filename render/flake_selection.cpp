#include "render/flake_selection.hpp"

namespace snow {

namespace {

/// A fixed per-slot number in [0, 1) (integer hash), for stable thinning.
float slot_fraction(std::uint32_t slot) {
    std::uint32_t h = slot * 0x9E3779B1u;
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

} // namespace

std::uint32_t select_flakes(const FlakePool& pool, const FlakeSelection& sel,
                            std::vector<float>& out) {
    const std::uint32_t n = pool.capacity();
    const glm::mat4& m = sel.view_proj;
    const float lod2 = sel.lod_distance * sel.lod_distance;
    std::uint32_t count = 0;
    float* dst = out.data();
    for (std::uint32_t i = 0; i < n; ++i) {
        if (pool.mass_units[i] == 0) {
            continue;
        }
        const float x = pool.px[i], y = pool.py[i], z = pool.pz[i];
        // Clip-space frustum test; the 10% margin keeps sprites that straddle an edge.
        const float cw = m[0][3] * x + m[1][3] * y + m[2][3] * z + m[3][3];
        const float cx = m[0][0] * x + m[1][0] * y + m[2][0] * z + m[3][0];
        const float cy = m[0][1] * x + m[1][1] * y + m[2][1] * z + m[3][1];
        const float cz = m[0][2] * x + m[1][2] * y + m[2][2] * z + m[3][2];
        const float lim = 1.1f * cw;
        if (cw <= 0.0f || cx < -lim || cx > lim || cy < -lim || cy > lim || cz < -cw || cz > cw) {
            continue;
        }
        if (sel.lod) {
            const float dx = x - sel.eye.x, dy = y - sel.eye.y, dz = z - sel.eye.z;
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 > lod2 && slot_fraction(i) * d2 >= lod2) {
                continue;
            }
        }
        dst[0] = x;
        dst[1] = y;
        dst[2] = z;
        dst[3] = pool.size[i] * sel.size_scale;
        dst += 4;
        ++count;
    }
    return count;
}

} // namespace snow
