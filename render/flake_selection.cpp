// Flake selection as one streaming pass: per block of slots, a branch-free
// loop (it vectorises) marks the flakes to draw, then a branch-free loop
// copies every slot's (x, y, z, diameter) to the next free place and moves
// that place on only for the marked ones, so no test mispredicts however the
// flakes are mixed. The tests are the ones a per-flake loop with early exits
// makes, in the same float operations, so the output is the same.
#include "render/flake_selection.hpp"

#include <algorithm>
#include <cstring>

namespace snow {

namespace {

/// Slots per block: the marks of one block stay in L1 between the two loops.
constexpr std::uint32_t block = 1024;

/// A fixed number in [0, 1) per flake (integer hash of its id), for thinning
/// that stays put when the pool is reordered.
float flake_fraction(std::uint32_t id) {
    std::uint32_t h = id * 0x9E3779B1u;
    h ^= h >> 16;
    h *= 0x85EBCA6Bu;
    h ^= h >> 13;
    h *= 0xC2B2AE35u;
    h ^= h >> 16;
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

/// The selection's numbers as scalars, so the marking loop holds no glm type.
struct Tests {
    float m[4][4];
    float ex, ey, ez;
    float lod2; ///< lod_distance²
};

/// keep[j] = 1 for the slots first + j (j < n) to draw: alive, inside the
/// view frustum (clip space, with a 10% margin for sprites that straddle an
/// edge) and, with level of detail, nearer than its distance d0 or, at
/// distance d, with the flake's fixed fraction under (d0 / d)².
template <bool lod>
void mark(const float* __restrict px, const float* __restrict py, const float* __restrict pz,
          const std::uint32_t* __restrict mass, const std::uint32_t* __restrict id, std::uint32_t n,
          const Tests t, std::uint8_t* __restrict keep) {
    for (std::uint32_t j = 0; j < n; ++j) {
        const float x = px[j], y = py[j], z = pz[j];
        const float cw = t.m[0][3] * x + t.m[1][3] * y + t.m[2][3] * z + t.m[3][3];
        const float cx = t.m[0][0] * x + t.m[1][0] * y + t.m[2][0] * z + t.m[3][0];
        const float cy = t.m[0][1] * x + t.m[1][1] * y + t.m[2][1] * z + t.m[3][1];
        const float cz = t.m[0][2] * x + t.m[1][2] * y + t.m[2][2] * z + t.m[3][2];
        const float lim = 1.1f * cw;
        const bool outside = (cw <= 0.0f) | (cx < -lim) | (cx > lim) | (cy < -lim) | (cy > lim) |
                             (cz < -cw) | (cz > cw);
        bool thinned = false;
        if constexpr (lod) {
            const float dx = x - t.ex, dy = y - t.ey, dz = z - t.ez;
            const float d2 = dx * dx + dy * dy + dz * dz;
            thinned = (d2 > t.lod2) & (flake_fraction(id[j]) * d2 >= t.lod2);
        }
        keep[j] = static_cast<std::uint8_t>((mass[j] != 0) & !outside & !thinned);
    }
}

} // namespace

std::uint32_t select_flakes(const FlakePool& pool, const FlakeSelection& sel,
                            std::vector<float>& out) {
    Tests t{};
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            t.m[c][r] = sel.view_proj[c][r];
        }
    }
    t.ex = sel.eye.x;
    t.ey = sel.eye.y;
    t.ez = sel.eye.z;
    t.lod2 = sel.lod_distance * sel.lod_distance;
    const float scale = sel.size_scale;
    // Slots past slot_end were never alive.
    const std::uint32_t n = pool.slot_end;
    std::uint32_t count = 0;
    float* dst = out.data();
    alignas(64) std::uint8_t keep[block];
    for (std::uint32_t base = 0; base < n; base += block) {
        const std::uint32_t m = std::min(block, n - base);
        const float* px = pool.px.data() + base;
        const float* py = pool.py.data() + base;
        const float* pz = pool.pz.data() + base;
        const float* size = pool.size.data() + base;
        const std::uint32_t* mass = pool.mass_units.data() + base;
        const std::uint32_t* id = pool.id.data() + base;
        if (sel.lod) {
            mark<true>(px, py, pz, mass, id, m, t, keep);
        } else {
            mark<false>(px, py, pz, mass, id, m, t, keep);
        }
        // Written at `count` whether kept or not (one 16-byte store): count <=
        // slot, so it stays inside out, and a later kept flake overwrites it.
        for (std::uint32_t j = 0; j < m; ++j) {
            const float flake[4] = {px[j], py[j], pz[j], size[j] * scale};
            std::memcpy(dst + static_cast<std::size_t>(count) * 4, flake, sizeof flake);
            count += keep[j];
        }
    }
    return count;
}

} // namespace snow
