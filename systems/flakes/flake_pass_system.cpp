// The flake pass: integrate, collide and deposit of each block of
// flake_block slots one after another while the block is in L1, so a flake's
// data crosses memory once per tick (docs/performance.md "One pass"). Every
// flake's outcome depends on nothing any other flake of the tick does, and
// the records are applied in the stages' own order (stiff counts, removals in
// slot order, then landings in slot order), so the result is the same as the
// three stages run one after another over the whole pool
// (FlakePass.SameAsStagesOneAtATime) and for any thread count. While few
// flakes are low enough to land, collide's prefilter, its reach raised to
// the deposit bins' tops, flags for both stages, so deposit reads the listed
// slots instead of the whole block. Deposit's exact tests of a block wait
// until the next block has been integrated and collided: the surface cells
// under its few low flakes are scattered and rarely in cache, and their
// loads, started when the block was listed, have arrived by then.
#include "systems/api/systems.hpp"
#include "systems/core/jobs.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/flakes/flake_stages.hpp"

#include <algorithm>

namespace snow {

namespace {

/// Runs fn(chunk, b, e) over the blocks of each chunk of [0, slot_end).
template <typename Fn>
void for_blocks(World& w, const Fn& fn) {
    const std::size_t n = w.resource<FlakePool>().slot_end;
    for_chunks(w, n, flake_grain, [&fn](std::size_t chunk, std::size_t b, std::size_t e) {
        for (std::size_t base = b; base < e; base += flake_block) {
            fn(chunk, base, std::min(e, base + flake_block));
        }
    });
}

} // namespace

PathStarts stage_path_starts(World& w) {
    const FlakePool& f = w.resource<FlakePool>();
    auto* s = w.try_resource<StagePathStarts>();
    if (s == nullptr) {
        s = &w.set_resource<StagePathStarts>();
    }
    if (s->x.size() != f.capacity()) {
        s->x = f.px;
        s->y = f.py;
        s->z = f.pz;
    }
    return {s->x.data(), s->y.data(), s->z.data(), 0};
}

void prepare_flake_pass(World& w) {
    prepare_integrate(w);
    prepare_collide(w);
    prepare_deposit(w);
}

void flake_pass_system(World& w) {
    const IntegrateTick& in = integrate_begin(w);
    CollideTick& co = collide_begin(w);
    // Nothing can land without a surface: that stage is skipped (as its own
    // system it needs a SnowSurface; docs/design.md "What is declared runs").
    const DepositTick* de = deposit_begin(w);
    // One prefilter pass for both stages while few flakes are low enough to
    // land (docs/performance.md, "one prefilter for two stages"): collide's
    // flags then hold every flake deposit's would.
    const bool share = de != nullptr && deposit_prefilter_sparse(w);
    if (share) {
        collide_share_flags(co, deposit_bins(*de));
    }
    const std::size_t n = w.resource<FlakePool>().slot_end;
    const auto chunk_of_blocks = [&](std::size_t chunk, std::size_t begin, std::size_t end) {
        // Two blocks in flight: a block's landings are tested after the next
        // block's integrate and collide (deposit_list, deposit_land).
        struct Block {
            alignas(64) float x[flake_block], y[flake_block], z[flake_block];
            PathStarts starts;
            DepositCandidates listed;
        };
        Block blocks[2];
        Block* previous = nullptr;
        for (std::size_t b = begin, k = 0; b < end; b += flake_block, ++k) {
            const std::size_t e = std::min(end, b + flake_block);
            Block& block = blocks[k % 2];
            block.starts = {block.x, block.y, block.z, b};
            integrate_block(in, chunk, block.starts, b, e);
            BlockCandidates flagged;
            const auto removed =
                collide_block(co, chunk, block.starts, b, e, share ? &flagged : nullptr);
            if (de != nullptr) {
                deposit_list(*de, chunk, block.starts, b, e, removed, share ? &flagged : nullptr,
                             block.listed);
                if (previous != nullptr) {
                    deposit_land(*de, chunk, previous->starts, previous->listed);
                }
                previous = &block;
            }
        }
        if (previous != nullptr) {
            deposit_land(*de, chunk, previous->starts, previous->listed);
        }
    };
    // One reference captured: the job pool's function holds it without allocating.
    for_chunks(w, n, flake_grain, [&chunk_of_blocks](std::size_t c, std::size_t b, std::size_t e) {
        chunk_of_blocks(c, b, e);
    });
    integrate_end(w, in);
    collide_end(w, co);
    if (de != nullptr) {
        deposit_end(w, *de);
    }
}

namespace {

/// One stage over the whole pool on its own, with pool-wide path starts;
/// nothing when begin gave no tick (deposit without surfaces or flakes).
template <typename Tick, typename Block>
void run_alone(World& w, const Tick* t, const Block& block, void (*end)(World&, const Tick&)) {
    if (t == nullptr) {
        return;
    }
    const PathStarts starts = stage_path_starts(w);
    for_blocks(w, [&](std::size_t chunk, std::size_t b, std::size_t e) {
        block(*t, chunk, starts, b, e);
    });
    end(w, *t);
}

} // namespace

void integrate_system(World& w) {
    run_alone(w, &integrate_begin(w), integrate_block, integrate_end);
}

void collide_system(World& w) {
    const auto own = [](const CollideTick& t, std::size_t chunk, const PathStarts& starts,
                        std::size_t b, std::size_t e) { collide_block(t, chunk, starts, b, e); };
    run_alone(w, &collide_begin(w), own, collide_end);
}

void deposit_system(World& w) {
    const auto all = [](const DepositTick& t, std::size_t chunk, const PathStarts& starts,
                        std::size_t b, std::size_t e) {
        DepositCandidates listed;
        deposit_list(t, chunk, starts, b, e, {}, nullptr, listed);
        deposit_land(t, chunk, starts, listed);
    };
    run_alone(w, deposit_begin(w), all, deposit_end);
}

} // namespace snow
