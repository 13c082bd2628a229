/// @file flake_stages.hpp
/// @brief The three per-flake stages of a tick — integrate, collide, deposit —
/// as block kernels, so the flake pass (flake_pass_system.cpp) runs all three on one
/// L1-sized block of slots while it is in cache (docs/performance.md "One
/// pass"). Each stage has a begin (serial: this tick's context), a block
/// kernel (parallel over fixed chunks; writes only its flakes and its chunk's
/// records) and an end (serial: the records applied in slot order). Internal
/// to systems/.
#pragma once

#include "ecs/world.hpp"
#include "systems/flakes/flake_pool.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace snow {

/// Slots per block: three stages' data for a block (about 40 B per slot)
/// stays in a 32 KiB L1 between them. A divisor of flake_grain and a multiple
/// of 8 (flags are scanned 8 at a time).
inline constexpr std::size_t flake_block = 512;

/// Where the paths of one block's flakes started this tick: slot i's start
/// is x[i - base], y[i - base], z[i - base]. Integrate writes it (the
/// position before its move); collide and deposit test the path from it.
struct PathStarts {
    float* x;
    float* y;
    float* z;
    std::size_t base;
};

/// World resource: path starts for the whole pool, for a stage run on its own
/// (integrate_system, collide_system, deposit_system: tests and benchmarks
/// of one stage). The tick's flake pass never uses it: it keeps each block's
/// starts in a buffer of flake_block slots.
struct StagePathStarts {
    PoolArray<float> x, y, z;
};

/// The pool-wide path starts (base 0), sized to the pool once (a free slot's
/// start is parked like its position).
PathStarts stage_path_starts(World& w);

/// This tick's context of each stage, held by a world resource of its file.
struct IntegrateTick;
struct CollideTick;
struct DepositTick;
struct DepositBins;

/// The slots of one block that the flake pass's shared prefilter flagged
/// (ascending): collide's prefilter with its reach raised to the deposit
/// bins' tops (collide_share_flags), so the one list holds every flake
/// either stage must look at and deposit needs no prefilter pass of its own.
struct BlockCandidates {
    std::uint32_t slots[flake_block];
    std::size_t count = 0;
};

/// Writes b + j for every j < m whose flags[j] is 1 (flags are 0 or 1) to
/// `out`, ascending; returns how many. Flagged slots are few and scattered:
/// the words (8 flags) holding one are kept first without a branch, where a
/// branch per word would mispredict on most of them.
inline std::uint32_t list_flagged(const std::uint8_t* flags, std::size_t m, std::size_t b,
                                  std::uint32_t* out) {
    std::uint64_t words[flake_block / 8];
    std::uint32_t at[flake_block / 8];
    std::uint32_t word_count = 0;
    const auto keep = [&](std::uint64_t word, std::size_t w) {
        words[word_count] = word;
        at[word_count] = static_cast<std::uint32_t>(w);
        word_count += word != 0 ? 1u : 0u;
    };
    const std::size_t whole = m / 8;
    for (std::size_t w = 0; w < whole; ++w) {
        std::uint64_t word = 0;
        std::memcpy(&word, flags + 8 * w, sizeof word);
        keep(word, w);
    }
    if (m % 8 != 0) { // the last flags, short of a word
        std::uint64_t word = 0;
        std::memcpy(&word, flags + 8 * whole, m % 8);
        keep(word, whole);
    }
    std::uint32_t n = 0;
    for (std::uint32_t k = 0; k < word_count; ++k) {
        const std::size_t j = std::size_t{8} * at[k];
        for (std::uint64_t word = words[k]; word != 0; word &= word - 1) {
            out[n++] = static_cast<std::uint32_t>(b + j + std::countr_zero(word) / 8);
        }
    }
    return n;
}

// Each stage's prepare makes its world resource and gives it room for the
// scene as it stands, so that no tick allocates; prepare_flake_pass() calls
// all three after each change of the scene. Integrate's and deposit's begin
// call theirs first (a no-op then); collide's begin rebuilds the collider
// grid into the room prepare_collide made.

/// Integrate ([WF §3], [ZCL §III.C]): the rule of SimConfig::integrator for
/// slots [b, e) of chunk `chunk`, in place, their old positions to `starts`.
IntegrateTick& prepare_integrate(World& w);
IntegrateTick& integrate_begin(World& w);
void integrate_block(const IntegrateTick& t, std::size_t chunk, const PathStarts& starts,
                     std::size_t b, std::size_t e);
void integrate_end(World& w, const IntegrateTick& t);

/// Collide ([WF §4], [SKY]): bounds, spheres, boxes, mesh tops and bodies for
/// slots [b, e). Returns the slots of the block it will remove (ascending),
/// which the later stages skip.
/// With `shared`, the block's flagged slots (collide's and deposit's) are
/// also listed there for deposit_list; collide tests only its own among them.
void prepare_collide(World& w);
CollideTick& collide_begin(World& w);
/// Makes this tick's prefilter flag every flake deposit's prefilter would
/// flag too (for the flake pass; a stage run alone keeps its own flags).
void collide_share_flags(CollideTick& t, const DepositBins& bins);
std::span<const std::uint32_t> collide_block(const CollideTick& t, std::size_t chunk,
                                             const PathStarts& starts, std::size_t b, std::size_t e,
                                             BlockCandidates* shared = nullptr);
void collide_end(World& w, const CollideTick& t);

/// Deposit ([WF §4], [ZCL §IV]): landings of slots [b, e) other than
/// `removed` (ascending); with `shared`, only its slots are looked at (the
/// pass's shared prefilter already passed over the rest). Begin returns null
/// when nothing can land (no surface or no flake): then the stage is skipped.
/// A block's detection has two halves: deposit_list lists the flakes that
/// may land and starts loading the surface cells under them (scattered over
/// the ground, rarely in cache), deposit_land tests them exactly and records
/// the landings; between the two the pass runs the next block, so the loads
/// have arrived.
DepositTick* prepare_deposit(World& w);
DepositTick* deposit_begin(World& w);
[[nodiscard]] const DepositBins& deposit_bins(const DepositTick& t);
/// Whether the flake pass shares collide's prefilter this tick (after
/// deposit_begin): when few slots passed deposit's own last tick (a choice
/// of speed only: both ways give the same landings).
[[nodiscard]] bool deposit_prefilter_sparse(const World& w);
/// The slots of one block deposit_list found may land (ascending), each
/// with its prefilter bin.
struct DepositCandidates {
    std::uint32_t slots[flake_block];
    std::uint32_t bins[flake_block];
    std::size_t count = 0;
};
void deposit_list(const DepositTick& t, std::size_t chunk, const PathStarts& starts, std::size_t b,
                  std::size_t e, std::span<const std::uint32_t> removed,
                  const BlockCandidates* shared, DepositCandidates& out);
void deposit_land(const DepositTick& t, std::size_t chunk, const PathStarts& starts,
                  const DepositCandidates& listed);
void deposit_end(World& w, const DepositTick& t);

} // namespace snow
