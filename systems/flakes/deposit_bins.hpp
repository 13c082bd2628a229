/// @file deposit_bins.hpp
/// @brief The deposit system's prefilter: a coarse XZ grid of bins over the
/// surfaces, each listing the surfaces overlapping it and the highest y at
/// which a flake over it can still land, so a flake far above every surface
/// costs one lookup. Rebuilt from SourceVersions::surfaces and each
/// surface's base_version (a cover's base follows its geometry); its bin tops
/// follow each surface's level_bound (source_versions.hpp).
#pragma once

#include "ecs/host_memory.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <cstddef>
#include <cstdint>

namespace snow {

/// Metres a flake may be off a snow top and still count as on it: the collide
/// system places flakes on tops, and tops are rounded to float.
inline constexpr float landing_tolerance = 1.0e-3f;

/// Placement of the bins: square bins over the union of the surface
/// rectangles plus one bin of margin.
struct BinGrid {
    float gx0 = 0.0f, gz0 = 0.0f, inv = 1.0f, fnx = 0.0f, fnz = 0.0f;
    std::uint32_t nbx = 0, nbz = 0;

    /// Bin of world (x, z), or false when outside the grid. Branch-free so the
    /// prefilter vectorises; monotone in x and in z.
    bool bin_of(float x, float z, std::uint32_t& bin) const {
        const float fx = (x - gx0) * inv;
        const float fz = (z - gz0) * inv;
        const bool in = (fx >= 0.0f) & (fz >= 0.0f) & (fx < fnx) & (fz < fnz);
        bin = in ? static_cast<std::uint32_t>(fz) * nbx + static_cast<std::uint32_t>(fx) : 0u;
        return in;
    }
    /// Whether (x, z) is over a bin (its index to `bin`) and y is not above
    /// that bin's entry of `tops` (one per bin): the deposit prefilter's test.
    bool under_top(float x, float y, float z, const float* tops, std::uint32_t& bin) const {
        const bool in = bin_of(x, z, bin);
        return in & (y <= tops[bin]);
    }
    /// The same column / row computation, clamped into the grid.
    [[nodiscard]] std::uint32_t column(float x) const { return clamped((x - gx0) * inv, nbx); }
    [[nodiscard]] std::uint32_t row(float z) const { return clamped((z - gz0) * inv, nbz); }

  private:
    static std::uint32_t clamped(float f, std::uint32_t n) {
        return !(f >= 0.0f)                 ? 0u
               : f >= static_cast<float>(n) ? n - 1
                                            : static_cast<std::uint32_t>(f);
    }
};

/// World resource (a cache of the surfaces). Surfaces are named by their
/// dense index in the SnowSurface pool.
///
/// Under a raised surface (a roof over the ground) a bin's highest y is the
/// roof's, yet a flake between the ground and the roof, not crossing the roof
/// this tick, can land on neither (flakes sliding down walls, [WF §4]).
/// Two scene-wide heights exclude it: every flake that lands on the lowest
/// surface of its bin is at or below `floor_top`; every flake that lands on
/// another one is, now or at the start of its tick, at or above `upper_bare`.
struct DepositBins {
    bool built = false;
    std::uint64_t surfaces_version = 0;  ///< SourceVersions::surfaces it was built from
    Vector<std::uint64_t> base_versions; ///< SnowSurface::base_version per surface, the same
    Vector<std::int64_t> bounds;         ///< level_bound per surface when bin_top was set
    Vector<float> min_bare;              ///< lowest bare top (m) per surface; +inf if all void
    float floor_top = 0.0f;  ///< max over bins: highest y landing on the bin's lowest surface
    float upper_bare = 0.0f; ///< min over bins: lowest bare top of the others, less tolerance
    BinGrid grid;
    Vector<float> bin_top;           ///< -inf where no surface
    std::uint64_t tops_version = 0;  ///< counts the changes of bin_top
    Vector<std::uint32_t> bin_start; ///< bin b lists bin_items[bin_start[b], bin_start[b+1])
    Vector<std::uint32_t> bin_items; ///< surface indices, ascending

    /// False when a flake at y (y_start at the start of its tick) can land on
    /// no surface: above every bin's lowest surface and below every other
    /// bare top, not crossing one.
    [[nodiscard]] bool may_land(float y, float y_start) const {
        return y <= floor_top || y >= upper_bare || y_start >= upper_bare;
    }
};

/// Brings the bins up to date with the surfaces (pool order) of version
/// `surfaces_version`: rebuilt when that or a base_version changed, bin tops
/// raised when a level_bound moved.
void update_deposit_bins(DepositBins& bins, const Vector<SnowSurface>& surfaces,
                         std::uint64_t surfaces_version);

/// flags[j] = 1 where the flake at (px[j], py[j], pz[j]) is over a bin and
/// not above its top (it may land), else 0; j in [0, n). Free slots (py =
/// FlakePool::parked_y) are never flagged. Branch-free: it vectorises.
void flag_deposit_candidates(const DepositBins& bins, const float* __restrict px,
                             const float* __restrict py, const float* __restrict pz, std::size_t n,
                             std::uint8_t* __restrict flags);

} // namespace snow
