// Flake selection as one streaming pass: per block of slots, a branch-free
// loop (it vectorises) marks the flakes to draw, then a branch-free loop
// copies every slot's (x, y, z, diameter) to the next free place and moves
// that place on only for the marked ones, so no test mispredicts however the
// flakes are mixed. The tests are the ones a per-flake loop with early exits
// makes, in the same float operations, so the output is the same. With
// AVX-512 the copy takes 16 slots at a time: each array's kept lanes are
// packed to the front of a register (vcompressps) and the four registers
// interleaved to (x, y, z, diameter) records, so no lane waits on the count.
#include "render/passes/flake_selection.hpp"

#include <algorithm>
#include <cstring>

#if defined(__AVX512F__) && defined(__AVX512BW__) && defined(__AVX512VL__)
#include <immintrin.h>
#define SNOW_SELECTION_AVX512 1
#endif
// GCC 12's AVX-512 shuffles pass _mm512_undefined_ps() (a self-initialised
// variable) as their unused merge source, which -Wmaybe-uninitialized flags.
#if SNOW_SELECTION_AVX512 && defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace snow {

namespace {

/// Slots per block: the block's slots and marks stay in L1 between the two
/// loops; larger blocks' runs of arrays compete for the same L1 sets
/// (docs/performance.md "Measurements the code relies on").
constexpr std::uint32_t block = 512;

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

/// keep[j] = 1 for the slots first + j (j < n) to draw: not parked (alive), inside the
/// view frustum (clip space, with a 10% margin for sprites that straddle an
/// edge) and, with level of detail, nearer than its distance d0 or, at
/// distance d, with the flake's fixed fraction under (d0 / d)².
template <bool lod>
void mark(const float* __restrict px, const float* __restrict py, const float* __restrict pz,
          const std::uint32_t* __restrict id, std::uint32_t n, const Tests t,
          std::uint8_t* __restrict keep) {
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
        // A free slot's height is FlakePool::parked_y: read instead of its mass
        // (a stream less at 1M flakes); an alive flake there could not be drawn.
        const bool parked = y == FlakePool::parked_y;
        keep[j] = static_cast<std::uint8_t>(!parked & !outside & !thinned);
    }
}

/// Appends (x, y, z, size × scale) of the kept slots among the n from the
/// arrays' starts at out + 4 × count, in slot order; returns the new count.
/// Writes up to 4 × n floats from there whether kept or not (count <= the
/// first slot, so they stay inside the output), later kept flakes overwrite.
std::uint32_t append_kept(const float* px, const float* py, const float* pz, const float* size,
                          float scale, const std::uint8_t* keep, std::uint32_t n, float* out,
                          std::uint32_t count) {
    std::uint32_t j = 0;
#if SNOW_SELECTION_AVX512
    const __m512 scales = _mm512_set1_ps(scale);
    // Lane picks of two registers (16 + i: the second's lane i).
    const __m512i pair_lo =
        _mm512_setr_epi32(0, 16, 1, 17, 2, 18, 3, 19, 4, 20, 5, 21, 6, 22, 7, 23);
    const __m512i pair_hi =
        _mm512_setr_epi32(8, 24, 9, 25, 10, 26, 11, 27, 12, 28, 13, 29, 14, 30, 15, 31);
    const __m512i records_lo =
        _mm512_setr_epi32(0, 1, 16, 17, 2, 3, 18, 19, 4, 5, 20, 21, 6, 7, 22, 23);
    const __m512i records_hi =
        _mm512_setr_epi32(8, 9, 24, 25, 10, 11, 26, 27, 12, 13, 28, 29, 14, 15, 30, 31);
    for (; j + 16 <= n; j += 16) {
        const __m128i marks = _mm_loadu_si128(reinterpret_cast<const __m128i*>(keep + j));
        const __mmask16 k = _mm_test_epi8_mask(marks, marks);
        const __m512 x = _mm512_maskz_compress_ps(k, _mm512_loadu_ps(px + j));
        const __m512 y = _mm512_maskz_compress_ps(k, _mm512_loadu_ps(py + j));
        const __m512 z = _mm512_maskz_compress_ps(k, _mm512_loadu_ps(pz + j));
        const __m512 d =
            _mm512_maskz_compress_ps(k, _mm512_mul_ps(_mm512_loadu_ps(size + j), scales));
        // 4 × 16 lanes to 16 records: (x, y) and (z, d) pairs, then four
        // records from each half of the pairs.
        const __m512 xy_lo = _mm512_permutex2var_ps(x, pair_lo, y);
        const __m512 xy_hi = _mm512_permutex2var_ps(x, pair_hi, y);
        const __m512 zd_lo = _mm512_permutex2var_ps(z, pair_lo, d);
        const __m512 zd_hi = _mm512_permutex2var_ps(z, pair_hi, d);
        float* dst = out + static_cast<std::size_t>(count) * 4;
        _mm512_storeu_ps(dst, _mm512_permutex2var_ps(xy_lo, records_lo, zd_lo));
        _mm512_storeu_ps(dst + 16, _mm512_permutex2var_ps(xy_lo, records_hi, zd_lo));
        _mm512_storeu_ps(dst + 32, _mm512_permutex2var_ps(xy_hi, records_lo, zd_hi));
        _mm512_storeu_ps(dst + 48, _mm512_permutex2var_ps(xy_hi, records_hi, zd_hi));
        count += static_cast<std::uint32_t>(__builtin_popcount(k));
    }
#endif
    for (; j < n; ++j) {
        const float flake[4] = {px[j], py[j], pz[j], size[j] * scale};
        std::memcpy(out + static_cast<std::size_t>(count) * 4, flake, sizeof flake);
        count += keep[j];
    }
    return count;
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
        const std::uint32_t* id = pool.id.data() + base;
        if (sel.lod) {
            mark<true>(px, py, pz, id, m, t, keep);
        } else {
            mark<false>(px, py, pz, id, m, t, keep);
        }
        count = append_kept(px, py, pz, pool.size.data() + base, scale, keep, m, dst, count);
    }
    return count;
}

} // namespace snow
