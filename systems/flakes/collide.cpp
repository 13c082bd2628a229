// collide: flakes against the bounds, spheres, boxes and mesh tops ([WF §4];
// meshes through the sky map of [SKY]). Detection runs in parallel over
// fixed chunks of slots, block by block (flake_stages.hpp); removals are
// applied afterwards in slot order, so the free stack and the state hash do
// not depend on the thread count.
#include "systems/api/systems.hpp"
#include "systems/bodies/body.hpp"
#include "systems/core/jobs.hpp"
#include "systems/core/mass_ledger.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/source_versions.hpp"
#include "systems/flakes/deposit_bins.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/flakes/flake_stages.hpp"
#include "systems/geometry/collider_grid.hpp"
#include "systems/geometry/narrow_phase.hpp"
#include "systems/sky/occlusion.hpp"
#include "systems/snowpack/snow_cover.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

namespace {

enum class Removal : std::uint8_t { bounds, sphere, bare };

/// Texels per side of a block of the mesh-top summary.
constexpr std::uint32_t block_shift = 3;

/// Private to this file: candidate/removal lists (chunk c uses
/// [c·flake_grain, ...)), sized to the pool capacity once; the SnowSurface of each
/// ColliderGrid::holder_surfaces entry and of each cover (rebuilt from SourceVersions::solids and
/// ::surfaces); and, per 8×8 block of the
/// occlusion map, the highest mesh top in it, so most flakes skip the
/// (cache-missing) texel lookup (rebuilt from the map's version and
/// SourceVersions::solids).
struct CollideScratch {
    Vector<std::uint32_t> slots;
    Vector<Removal> reasons;
    Vector<std::uint32_t> units;  ///< per removal: the flake's mass, read in its block
    Vector<std::uint32_t> counts; ///< removals listed per chunk so far
    Vector<const SnowSurface*> surfaces;
    Vector<const SnowSurface*> covers; ///< the cover surfaces, pool order
    bool surfaces_built = false;
    std::uint64_t surfaces_solids_version = 0;
    std::uint64_t surfaces_version = 0;
    Vector<float> mesh_block_top;
    std::uint32_t blocks_x = 0;
    bool blocks_built = false;
    std::uint64_t blocks_map_version = 0;
    std::uint64_t blocks_solids_version = 0;
    /// The flake pass's prefilter table (ColliderGrid::cell_reach raised to
    /// the deposit bins' tops, collide_share_flags), rebuilt from the grid's
    /// versions and the bins' tops_version.
    Vector<float> shared_reach;
    Vector<float> shared_row_reach;    ///< row_tops() of shared_reach
    Vector<std::uint32_t> bin_columns; ///< per grid column: its first and last bin column
    /// Per block of the pool: its prefilter needed the per-flake table last
    /// tick (flag_block), so it goes straight there; a choice of speed only.
    Vector<std::uint8_t> exact_block;
    bool shared_built = false;
    std::uint64_t shared_solids_version = 0;
    std::uint64_t shared_surfaces_version = 0;
    std::uint64_t shared_tops_version = 0;
};

struct Context {
    FlakePool* pool = nullptr;
    const ColliderGrid* grid = nullptr;
    /// The prefilter's table: grid->cell_reach, or the pass's shared one.
    const float* reach = nullptr;
    const float* row_reach = nullptr;  ///< row_tops() of reach
    bool shared = false;               ///< reach is the shared table
    bool retry_bound = false;          ///< every block tries its one bound (flag_block) this tick
    const OcclusionMap* map = nullptr; ///< null when no usable map exists
    const float* mesh_block_top = nullptr;
    std::uint32_t blocks_x = 0;
    const SnowSurface* const* surfaces = nullptr;
    const SnowSurface* const* covers = nullptr;
    std::uint32_t cover_count = 0;
    const Body* bodies = nullptr;
    std::uint32_t body_count = 0;
    Aabb body_box{
        glm::vec3{std::numeric_limits<float>::infinity()},
        glm::vec3{-std::numeric_limits<float>::infinity()}}; ///< where bodies swept this tick
    Aabb bounds;
    float dt = 0.0f;
    /// Path lengths (m) per axis this tick at or above which a flake may have
    /// started outside the 3×3 cells around it (y: through a tilted map
    /// lookup), so cell_reach cannot clear it.
    float far_x = 0.0f, far_y = 0.0f, far_z = 0.0f;
    CollideScratch* scratch = nullptr;
};

/// A path of this tick's displacement (dx, dy, dz) may have started past the
/// 3×3 cells around its end, so the grid's reach tables cannot clear it (NaN
/// counts as long).
bool is_long(const Context& c, float dx, float dy, float dz) {
    const float ax = std::abs(dx), ay = std::abs(dy), az = std::abs(dz);
    return !(ax < c.far_x) | !(az < c.far_z) | !(ay < c.far_y);
}

/// The path (x0, y0, z0)→(x, y, z) comes near `b` (its bounding box meets
/// the box). Written as ors of plain compares, not min/max: GCC 12 turns a
/// compare of a select into a select of masks, which AVX-512 cannot
/// vectorise, and the flagging loop must stay branch-free and vector.
bool path_near(const Aabb& b, float x, float y, float z, float x0, float y0, float z0) {
    const bool meets_x = ((x <= b.max.x) | (x0 <= b.max.x)) & ((x >= b.min.x) | (x0 >= b.min.x));
    const bool meets_y = ((y <= b.max.y) | (y0 <= b.max.y)) & ((y >= b.min.y) | (y0 >= b.min.y));
    const bool meets_z = ((z <= b.max.z) | (z0 <= b.max.z)) & ((z >= b.min.z) | (z0 >= b.min.z));
    return meets_x & meets_y & meets_z;
}

/// Result of the per-flake tests for a flake that is still inside the bounds.
enum class Outcome : std::uint8_t { keep, sphere, bare };

/// The snow top of the first of the solid's surfaces that covers (x, z), or
/// NaN when none does.
float covering_top(const Context& c, std::uint32_t begin, std::uint32_t end, float x, float z) {
    for (std::uint32_t i = begin; i < end; ++i) {
        std::uint32_t ix = 0, iz = 0;
        if (c.surfaces[i]->cell_at(x, z, ix, iz)) {
            return c.surfaces[i]->top_y(c.surfaces[i]->index(ix, iz));
        }
    }
    return std::numeric_limits<float>::quiet_NaN();
}

/// A flake met geometry at `at`. When that is the top of a cover's column
/// (within the slope a cell spans), it is placed on the cover's snow top for
/// the deposit system and true is returned.
bool cover_catches(const Context& c, const glm::vec3& at, glm::vec3& p, glm::vec3& v) {
    for (std::uint32_t k = 0; k < c.cover_count; ++k) {
        const SnowSurface& s = *c.covers[k];
        std::uint32_t ix = 0, iz = 0;
        if (!s.cell_at(at.x, at.z, ix, iz)) {
            continue;
        }
        const std::size_t i = s.index(ix, iz);
        if (!s.is_void(i) && at.y >= s.height(s.base_level[i]) - 2.0f * s.cell) {
            p = {at.x, s.top_y(i), at.z};
            v = glm::vec3{0.0f};
            return true;
        }
    }
    return false;
}

/// A flake reached the top of a solid at `at`: it waits there for the
/// deposit system when a surface of the solid or a cover covers the spot,
/// otherwise it lands on bare geometry and leaves the books (it would rest
/// there forever). On a surface it waits no higher than the snow top of its
/// cell, so the deposit system takes it: a tilted solid's top (a mesh roof
/// through the sky map's texels) may lie above the cell's, and a flake held
/// there would lie at rest on the bare roof for ever.
Outcome land_on_top(const Context& c, std::uint32_t surf_begin, std::uint32_t surf_end,
                    const glm::vec3& at, glm::vec3& p, glm::vec3& v, bool& moved) {
    const float snow_top = covering_top(c, surf_begin, surf_end, at.x, at.z);
    if (std::isnan(snow_top)) {
        moved = cover_catches(c, at, p, v);
        return moved ? Outcome::keep : Outcome::bare;
    }
    p = {at.x, std::min(at.y, snow_top), at.z};
    v.y = 0.0f;
    moved = true;
    return Outcome::keep;
}

/// The first box or sphere along p0→p from the grid cells the path overlaps.
struct FirstContact {
    std::uint32_t item = 0; ///< as in ColliderGrid::cell_items
    BoxContact box;         ///< when the item is a box
    float t = 0.0f;         ///< where along the path
    bool found = false;
};

FirstContact first_contact(const ColliderGrid& g, const glm::vec3& p0, const glm::vec3& p) {
    // The best hit so far in locals, the result built once: rebuilding it on
    // every hit costs a reload of stores still in flight.
    float best = std::numeric_limits<float>::infinity();
    std::uint32_t best_item = 0;
    BoxContact best_box;
    bool found = false;
    const float lo = std::min(p.y, p0.y);
    const std::uint32_t i0 = g.cell_x(std::min(p.x, p0.x)), i1 = g.cell_x(std::max(p.x, p0.x));
    const std::uint32_t j0 = g.cell_z(std::min(p.z, p0.z)), j1 = g.cell_z(std::max(p.z, p0.z));
    for (std::uint32_t j = j0; j <= j1; ++j) {
        for (std::uint32_t i = i0; i <= i1; ++i) {
            const std::size_t cell = static_cast<std::size_t>(j) * g.nx + i;
            if (lo > g.cell_top[cell]) {
                continue; // the path stays above everything in this cell
            }
            for (std::uint32_t n = g.cell_start[cell]; n < g.cell_start[cell + 1]; ++n) {
                const std::uint32_t item = g.cell_items[n];
                const bool sphere = (item & ColliderGrid::sphere_tag) != 0;
                float t = 0.0f;
                BoxContact k;
                bool hit = false;
                if (sphere) {
                    const GridSphere& s = g.spheres[item & ~ColliderGrid::sphere_tag];
                    hit = sphere_entry(p0, p, s.center, s.radius, t);
                } else {
                    hit = box_contact(g.boxes[item].box, p0, p, k);
                    t = k.t;
                }
                if (hit && t < best) { // strict: the first listed wins a tie
                    best = t;
                    best_item = item;
                    best_box = k;
                    found = true;
                }
            }
        }
    }
    return FirstContact{best_item, best_box, best, found};
}

/// Slides a flake may make along box faces in one tick (a corner between
/// boxes needs two or three); past that it stays where the last one put it.
constexpr int max_slides = 4;

/// Boxes and spheres, in the order the flake's path meets them. Sets `moved`
/// when p or v changed and `done` when the flake reached a top (and so needs
/// no further test).
Outcome grid_colliders(const Context& c, const glm::vec3& p0, glm::vec3& p, glm::vec3& v,
                       bool& moved, bool& done) {
    const ColliderGrid& g = *c.grid;
    for (int slide = 0; slide < max_slides; ++slide) {
        const FirstContact f = first_contact(g, p0, p);
        if (!f.found) {
            break;
        }
        if ((f.item & ColliderGrid::sphere_tag) != 0) {
            // [WF §4]: the sphere eliminates it, unless a cover holds snow there.
            done = cover_catches(c, p0 + (p - p0) * f.t, p, v);
            moved = moved || done;
            return done ? Outcome::keep : Outcome::sphere;
        }
        const GridBox& b = g.boxes[f.item];
        const BoxContact& k = f.box;
        if (k.axis == 1 && k.max_side) {
            done = true;
            return land_on_top(c, b.surf_begin, b.surf_end, k.at, p, v, moved);
        }
        // [WF §4]: to the nearest point outside (on the face); the motion
        // along the face is kept, so the flake slides and drifts build at
        // windward bases.
        p = with_component(p, k.axis, k.at[k.axis]);
        v = with_component(v, k.axis,
                           k.max_side ? std::max(v[k.axis], 0.0f) : std::min(v[k.axis], 0.0f));
        moved = true;
    }
    return Outcome::keep;
}

/// A mesh top from the sky map [SKY]: only a flake that crossed the
/// top from above this tick lands; one that came in sideways is left alone.
Outcome mesh_top(const Context& c, const glm::vec3& p0, glm::vec3& p, glm::vec3& v, bool& moved) {
    std::uint32_t ti = 0, tj = 0;
    if (!occlusion_texel(*c.map, p.x, p.y, p.z, ti, tj)) {
        return Outcome::keep;
    }
    if (!(p.y < c.mesh_block_top[(tj >> block_shift) * c.blocks_x + (ti >> block_shift)])) {
        return Outcome::keep; // no mesh top in this block is above the flake
    }
    const std::size_t t = static_cast<std::size_t>(tj) * c.map->width + ti;
    const float top = c.map->top_y[t];
    if (!(p0.y >= top && top > p.y)) {
        return Outcome::keep;
    }
    const GridMesh* m = c.grid->find_mesh(c.map->top_id[t]);
    if (m == nullptr) {
        return Outcome::keep;
    }
    return land_on_top(c, m->surf_begin, m->surf_end, glm::vec3{p.x, top, p.z}, p, v, moved);
}

/// Moving bodies, each tested in its own frame: the flake's path this tick,
/// from its start (FlakePool::start_*) to p, less the body's motion from
/// `previous` to `position`, so a body sweeping over a resting flake meets it
/// too. A flake that enters is put on the body's surface and moves with it.
void push_out_of_bodies(const Context& c, const glm::vec3& p0, glm::vec3& p, glm::vec3& v,
                        bool& moved) {
    for (std::uint32_t k = 0; k < c.body_count; ++k) {
        const Body& b = c.bodies[k];
        glm::vec3 out{0.0f};
        if (body_contact(b, p0 - b.previous, p - b.position, out)) {
            p = b.position + out;
            v = (b.position - b.previous) / c.dt;
            moved = true;
        }
    }
}

/// Every collider test for one flake that may meet something (finite position).
Outcome resolve(const Context& c, const PathStarts& st, std::size_t i) {
    FlakePool& f = *c.pool;
    glm::vec3 p{f.px[i], f.py[i], f.pz[i]};
    glm::vec3 v{f.vx[i], f.vy[i], f.vz[i]};
    const std::size_t o = i - st.base;
    const glm::vec3 p0{st.x[o], st.y[o], st.z[o]};
    bool moved = false, done = false;
    Outcome out = grid_colliders(c, p0, p, v, moved, done);
    if (out == Outcome::keep && !done && c.map != nullptr) {
        const ColliderGrid& g = *c.grid;
        const float mesh_reach = g.cell_mesh_reach[g.cell_z(p.z) * g.nx + g.cell_x(p.x)];
        if (!(std::min(p.y, p0.y) > mesh_reach) || is_long(c, p.x - p0.x, p.y - p0.y, p.z - p0.z)) {
            out = mesh_top(c, p0, p, v, moved);
        }
    }
    if (out == Outcome::keep && path_near(c.body_box, p.x, p.y, p.z, p0.x, p0.y, p0.z)) {
        push_out_of_bodies(c, p0, p, v, moved);
    }
    if (out == Outcome::keep && moved) { // untouched flakes leave their cache lines clean
        f.px[i] = p.x;
        f.py[i] = p.y;
        f.pz[i] = p.z;
        f.vx[i] = v.x;
        f.vy[i] = v.y;
        f.vz[i] = v.z;
    }
    return out;
}

/// The prefilter's bound for one path: the entry of the tick's table that
/// applies to it (ColliderGrid::cell_reach's layout). A path that starts and
/// ends in one cell can meet only what is over that cell: most paths, as a
/// flake moves a few cm a tick. A signed 32-bit index: GCC gathers with it
/// (vgatherdps); an unsigned one it widens to 64 bits and loads lane by lane.
struct CellTop {
    const ColliderGrid* grid;
    const float* reach;
    [[gnu::always_inline]] float at(float x, float z, float x0, float z0) const {
        const ColliderGrid& g = *grid;
        const std::uint32_t cx = g.cell_x(x), cz = g.cell_z(z);
        const std::uint32_t start_x = g.cell_x(x0), start_z = g.cell_z(z0);
        const bool same_cell = (start_x == cx) & (start_z == cz);
        const auto cell = static_cast<std::int32_t>(cz * g.nx + cx);
        return reach[2 * cell + (same_cell ? 0 : 1)];
    }
};

/// One bound for every path of a block: the highest entry over the cells
/// the block's paths end in (block_top()). No table read per flake.
struct BlockTop {
    float top;
    [[gnu::always_inline]] float at(float, float, float, float) const { return top; }
};

/// Whether the flake at (x, y, z), whose path this tick started at (x0, y0,
/// z0), may need work: out of bounds, on a long path, or low enough to meet
/// a collider near it by `bound`. Selects only, so a loop over flakes
/// vectorises. Without bodies the box test is left out (its empty box flags
/// nothing): a tenth of the work.
template <bool with_bodies, typename Bound>
[[gnu::always_inline]] inline bool needs_tests(const Context& c, const Bound& bound, float x,
                                               float y, float z, float x0, float y0, float z0,
                                               std::uint32_t mass) {
    const Aabb& bb = c.bounds;
    // [WF §4]: flakes outside the world's bounds are deactivated (NaN too).
    const bool inside = (x >= bb.min.x) & (x <= bb.max.x) & (y >= bb.min.y) & (y <= bb.max.y) &
                        (z >= bb.min.z) & (z <= bb.max.z);
    const float top = bound.at(x, z, x0, z0);
    const bool low = !((y < y0 ? y : y0) > top);
    const bool far = is_long(c, x - x0, y - y0, z - z0);
    const bool body = with_bodies && path_near(c.body_box, x, y, z, x0, y0, z0);
    return (mass != 0) & (!inside | low | far | body);
}

/// Marks the flakes of [b, e) that needs_tests() picks by `bound`; returns
/// how many. Most flakes are above everything near them and are never looked
/// at again.
template <bool with_bodies, typename Bound>
std::uint32_t flag_block(const Context& c, const Bound& bound, const PathStarts& st, std::size_t b,
                         std::size_t e, std::uint8_t* __restrict flags) {
    const FlakePool& f = *c.pool;
    const std::uint32_t* mass = f.mass_units.data() + b;
    const float* px = f.px.data() + b;
    const float* py = f.py.data() + b;
    const float* pz = f.pz.data() + b;
    const float* sx = st.x + (b - st.base);
    const float* sy = st.y + (b - st.base);
    const float* sz = st.z + (b - st.base);
    const Context local = c; // copies: the flag stores cannot alias them
    const Bound local_bound = bound;
    std::uint32_t count = 0;
    for (std::size_t j = 0; j < e - b; ++j) {
        const bool flag = needs_tests<with_bodies>(local, local_bound, px[j], py[j], pz[j], sx[j],
                                                   sy[j], sz[j], mass[j]);
        flags[j] = flag ? 1 : 0;
        count += flag ? 1u : 0u;
    }
    return count;
}

/// The highest entry of the tick's table over the cells the paths of [b, e)
/// end in, bounded by their rows and columns (free slots too: a wider
/// bound, never a narrower one). A row the block spans most of is taken
/// whole (row_reach): the work stays a few dozen reads per block.
float block_top(const Context& c, std::size_t b, std::size_t e) {
    const ColliderGrid& g = *c.grid;
    const float* px = c.pool->px.data() + b;
    const float* pz = c.pool->pz.data() + b;
    std::uint32_t col_lo = g.nx - 1, col_hi = 0, row_lo = g.nz - 1, row_hi = 0;
    for (std::size_t j = 0; j < e - b; ++j) {
        const std::uint32_t col = g.cell_x(px[j]), row = g.cell_z(pz[j]);
        col_lo = col < col_lo ? col : col_lo;
        col_hi = col > col_hi ? col : col_hi;
        row_lo = row < row_lo ? row : row_lo;
        row_hi = row > row_hi ? row : row_hi;
    }
    const bool whole_rows = col_hi - col_lo >= g.nx / 2;
    float top = -std::numeric_limits<float>::infinity();
    for (std::uint32_t row = row_lo; row <= row_hi; ++row) {
        if (whole_rows) {
            top = std::max(top, c.row_reach[row]);
            continue;
        }
        const float* entries = c.reach + 2 * (static_cast<std::size_t>(row) * g.nx + col_lo);
        top = std::max(top, *std::max_element(entries, entries + 2 * (col_hi - col_lo + 1)));
    }
    return top;
}

/// Ticks between a block's tries of its one bound after it needed the
/// per-flake table (flag_block).
constexpr std::uint64_t bound_retry = 8;

/// Flags the flakes of [b, e) that may need work (needs_tests()). The
/// block's one bound first: where it picks few (most blocks: the tallest
/// collider near them is below most of their flakes), those few go on
/// to the exact tests, which clear what the wider bound let through;
/// otherwise the table's entry per flake. A block that needed the table
/// goes straight to it on the next ticks (flakes move a few cm a tick) and
/// tries the bound again every bound_retry ticks. Returns how many are
/// flagged.
template <bool with_bodies>
std::uint32_t flag_block(const Context& c, const PathStarts& st, std::size_t b, std::size_t e,
                         std::uint8_t* flags) {
    std::uint8_t& exact = c.scratch->exact_block[b / flake_block];
    if (exact == 0 || c.retry_bound) {
        const std::uint32_t few = static_cast<std::uint32_t>(e - b) / 32;
        const std::uint32_t n =
            flag_block<with_bodies>(c, BlockTop{block_top(c, b, e)}, st, b, e, flags);
        exact = n > few ? 1 : 0;
        if (exact == 0) {
            return n;
        }
    }
    return flag_block<with_bodies>(c, CellTop{c.grid, c.reach}, st, b, e, flags);
}

/// needs_tests() by the grid's own table for `count` listed slots the shared
/// table flagged (some only for deposit): 1 in own[k] where collide itself
/// must look at slots[k]. Selects only, so the loop vectorises (gathers).
template <bool with_bodies>
void own_flags(const Context& c, const PathStarts& st, const std::uint32_t* __restrict slots,
               std::size_t count, std::uint8_t* __restrict own) {
    const FlakePool& f = *c.pool;
    const std::uint32_t* mass = f.mass_units.data();
    const float* px = f.px.data();
    const float* py = f.py.data();
    const float* pz = f.pz.data();
    const float* sx = st.x - st.base;
    const float* sy = st.y - st.base;
    const float* sz = st.z - st.base;
    const Context local = c; // copies: the flag stores cannot alias them
    const CellTop table{c.grid, c.grid->cell_reach.data()};
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t i = slots[k];
        own[k] = needs_tests<with_bodies>(local, table, px[i], py[i], pz[i], sx[i], sy[i], sz[i],
                                          mass[i])
                     ? 1
                     : 0;
    }
}

} // namespace

/// This tick's context and lists (the world resource of this file).
struct CollideTick {
    CollideScratch scratch;
    Context context;
};

std::span<const std::uint32_t> collide_block(const CollideTick& t, std::size_t chunk,
                                             const PathStarts& st, std::size_t b, std::size_t e,
                                             BlockCandidates* shared) {
    const Context& c = t.context;
    const FlakePool& f = *c.pool;
    const float* px = f.px.data();
    const float* py = f.py.data();
    const float* pz = f.pz.data();
    const Aabb& bb = c.bounds;
    alignas(64) std::uint8_t flags[flake_block];
    const std::uint32_t flagged = c.body_count > 0 ? flag_block<true>(c, st, b, e, flags)
                                                   : flag_block<false>(c, st, b, e, flags);
    // The chunk's lists: removals so far, then this block's candidates,
    // compacted in place to its removals.
    std::uint32_t* slots = c.scratch->slots.data() + chunk * flake_grain;
    Removal* reasons = c.scratch->reasons.data() + chunk * flake_grain;
    const std::uint32_t first = c.scratch->counts[chunk];
    // List the flagged slots (none when nothing is flagged).
    const std::size_t m = flagged > 0 ? e - b : 0;
    const std::uint32_t candidates = first + list_flagged(flags, m, b, slots + first);
    if (shared != nullptr) {
        shared->count = candidates - first;
        std::copy(slots + first, slots + candidates, shared->slots);
    }
    // Shared flags: drop the slots flagged for deposit alone first, all at
    // once (a vector loop) rather than one by one between exact tests.
    std::uint32_t own_end = candidates;
    if (c.shared) {
        alignas(64) std::uint8_t own[flake_block];
        const std::size_t listed = candidates - first;
        if (c.body_count > 0) {
            own_flags<true>(c, st, slots + first, listed, own);
        } else {
            own_flags<false>(c, st, slots + first, listed, own);
        }
        own_end = first;
        for (std::size_t k = 0; k < listed; ++k) {
            slots[own_end] = slots[first + k]; // own_end <= first + k
            own_end += own[k];
        }
    }
    // The grid's cells under the paths' ends start loading for all of them
    // (the pass's stream has long evicted them).
    const ColliderGrid& g = *c.grid;
    for (std::uint32_t k = first; k < own_end; ++k) {
        const std::uint32_t i = slots[k];
        const std::size_t cell = std::size_t{g.cell_z(pz[i])} * g.nx + g.cell_x(px[i]);
        __builtin_prefetch(g.cell_top.data() + cell);
        __builtin_prefetch(g.cell_start.data() + cell);
    }
    std::uint32_t n = first;
    for (std::uint32_t k = first; k < own_end; ++k) {
        const std::uint32_t i = slots[k];
        // Colliders first: a flake whose path crosses a roof and ends below the
        // bounds floor in the same tick is stopped by the roof, not removed.
        if (std::isfinite(px[i]) && std::isfinite(py[i]) && std::isfinite(pz[i])) {
            const Outcome o = resolve(c, st, i);
            if (o != Outcome::keep) {
                slots[n] = i; // n <= k: the compaction never overtakes the reading
                reasons[n++] = o == Outcome::sphere ? Removal::sphere : Removal::bare;
                continue;
            }
        }
        const float x = px[i], y = py[i], z = pz[i];
        if (!(x >= bb.min.x && x <= bb.max.x && y >= bb.min.y && y <= bb.max.y && z >= bb.min.z &&
              z <= bb.max.z)) {
            slots[n] = i;
            reasons[n++] = Removal::bounds;
        }
    }
    // The removed flakes leave the pool while their slots are in cache;
    // collide_end books them and frees the slots in slot order.
    std::uint32_t* units = c.scratch->units.data() + chunk * flake_grain;
    for (std::uint32_t k = first; k < n; ++k) {
        units[k] = f.mass_units[slots[k]];
        c.pool->park(slots[k]);
    }
    c.scratch->counts[chunk] = n;
    return {slots + first, n - first};
}

namespace {

/// Blocks of the mesh-top summary along `texels` of the map.
std::uint32_t blocks_along(std::uint32_t texels) {
    return (texels + (1u << block_shift) - 1) >> block_shift;
}

void update_scratch(World& w, CollideScratch* s, const FlakePool& pool, const ColliderGrid& grid,
                    const SourceVersions& versions) {
    // Sizes change only with the pool capacity.
    s->slots.resize(pool.capacity());
    s->reasons.resize(pool.capacity());
    s->units.resize(pool.capacity());
    s->counts.resize(chunk_count(pool.capacity(), flake_grain));
    s->exact_block.resize(pool.capacity() / flake_block + 1);
    // Room for the tables a tick rebuilds later: the mesh tops per block of
    // the camera's map, and the flake pass's shared prefilter (collide_share_flags).
    if (const auto* cam = w.try_resource<OcclusionCamera>()) {
        const OcclusionGrid map = occlusion_grid(w, *cam);
        s->mesh_block_top.reserve(std::size_t{blocks_along(map.width)} * blocks_along(map.height));
    }
    s->shared_reach.reserve(2 * static_cast<std::size_t>(grid.nx) * grid.nz);
    s->shared_row_reach.reserve(grid.nz);
    s->bin_columns.reserve(2 * std::size_t{grid.nx});
    // Surfaces (covers too) move in memory only when one is added or removed;
    // the grid's list of them changes order only with the solids and the surfaces.
    if (!s->surfaces_built || s->surfaces_solids_version != versions.solids ||
        s->surfaces_version != versions.surfaces) {
        s->surfaces.resize(grid.holder_surfaces.size());
        for (std::size_t i = 0; i < grid.holder_surfaces.size(); ++i) {
            s->surfaces[i] = &w.get<SnowSurface>(grid.holder_surfaces[i]);
        }
        s->covers.clear();
        if (const auto* covers = w.find_pool<SnowCover>()) {
            for (const Entity e : covers->entities()) {
                s->covers.push_back(&w.get<SnowSurface>(e));
            }
        }
        s->surfaces_solids_version = versions.solids;
        s->surfaces_version = versions.surfaces;
        s->surfaces_built = true;
    }
}

/// Rebuilds the per-block highest mesh top when the map or the meshes changed.
void update_mesh_blocks(CollideScratch& s, const OcclusionMap& map, const ColliderGrid& grid,
                        const SourceVersions& versions) {
    if (s.blocks_built && s.blocks_map_version == map.version &&
        s.blocks_solids_version == versions.solids) {
        return;
    }
    s.blocks_x = blocks_along(map.width);
    const std::uint32_t blocks_z = blocks_along(map.height);
    s.mesh_block_top.assign(static_cast<std::size_t>(s.blocks_x) * blocks_z,
                            -std::numeric_limits<float>::infinity());
    for (std::uint32_t j = 0; j < map.height; ++j) {
        for (std::uint32_t i = 0; i < map.width; ++i) {
            const std::size_t t = static_cast<std::size_t>(j) * map.width + i;
            if (map.top_id[t] != 0 && grid.find_mesh(map.top_id[t]) != nullptr) {
                float& top = s.mesh_block_top[(j >> block_shift) * s.blocks_x + (i >> block_shift)];
                top = std::max(top, map.top_y[t]);
            }
        }
    }
    s.blocks_map_version = map.version;
    s.blocks_solids_version = versions.solids;
    s.blocks_built = true;
}

/// The world's CollideTick (made when missing) with its scratch sized for `grid`.
CollideTick& collide_tick(World& w, const ColliderGrid& grid) {
    auto* t = w.try_resource<CollideTick>();
    if (t == nullptr) {
        t = &w.set_resource<CollideTick>();
    }
    update_scratch(w, &t->scratch, w.resource<FlakePool>(), grid, source_versions(w));
    return *t;
}

} // namespace

void prepare_collide(World& w) {
    reserve_collider_grid(w);
    collide_tick(w, w.resource<ColliderGrid>());
}

CollideTick& collide_begin(World& w) {
    FlakePool& pool = w.resource<FlakePool>();
    const SourceVersions versions = source_versions(w);
    const ColliderGrid& grid = update_collider_grid(w);
    CollideTick* t = &collide_tick(w, grid);
    CollideScratch& scratch = t->scratch;
    std::fill(scratch.counts.begin(), scratch.counts.end(), 0u);

    Context& c = t->context;
    c = Context{};
    c.pool = &pool;
    c.grid = &grid;
    c.reach = grid.cell_reach.data();
    c.row_reach = grid.row_reach.data();
    const auto* map = w.try_resource<OcclusionMap>();
    c.map = map != nullptr && map->width > 0 && !grid.meshes.empty() ? map : nullptr;
    if (c.map != nullptr) {
        update_mesh_blocks(scratch, *c.map, grid, versions);
        c.mesh_block_top = scratch.mesh_block_top.data();
        c.blocks_x = scratch.blocks_x;
    }
    c.surfaces = scratch.surfaces.data();
    c.covers = scratch.covers.data();
    c.cover_count = static_cast<std::uint32_t>(scratch.covers.size());
    const auto& cfg = w.resource<SimConfig>();
    c.bounds = cfg.bounds;
    c.dt = cfg.dt;
    if (const auto* bodies = w.find_pool<Body>(); bodies != nullptr && bodies->size() > 0) {
        c.bodies = bodies->components().data();
        c.body_count = static_cast<std::uint32_t>(bodies->size());
        // Where they swept this tick: a flake whose path misses this box meets none.
        for (const Body& b : bodies->components()) {
            const glm::vec3 r{b.shape == BodyShape::box ? b.half_extents : glm::vec3{b.reach()}};
            const glm::vec3 lift{0.0f, b.shape == BodyShape::capsule ? b.half_height : 0.0f, 0.0f};
            c.body_box.min = glm::min(c.body_box.min, glm::min(b.previous, b.position) - r - lift);
            c.body_box.max = glm::max(c.body_box.max, glm::max(b.previous, b.position) + r + lift);
        }
    }
    // 0.9 of a cell leaves margin for the rounding of the cell indices.
    c.far_x = 0.9f * grid.cell_size_x;
    c.far_z = 0.9f * grid.cell_size_z;
    const float shear =
        c.map != nullptr ? std::max(std::abs(c.map->shear_x), std::abs(c.map->shear_z)) : 0.0f;
    c.far_y = shear > 0.0f ? 0.9f * std::min(grid.cell_size_x, grid.cell_size_z) / shear
                           : std::numeric_limits<float>::infinity();
    c.retry_bound = w.resource<SimClock>().tick % bound_retry == 0;
    c.scratch = &scratch;
    return *t;
}

void collide_share_flags(CollideTick& t, const DepositBins& bins) {
    CollideScratch& s = t.scratch;
    const ColliderGrid& g = *t.context.grid;
    if (!s.shared_built || s.shared_solids_version != g.solids_version ||
        s.shared_surfaces_version != g.surfaces_version ||
        s.shared_tops_version != bins.tops_version) {
        // Each cell's table entries raised to the highest bin top over it: a
        // flake deposit's prefilter flags is at or below its bin's top, so at
        // or below this (its path's lower end too). The cell's rectangle is
        // widened by a hundredth of a cell for the rounding of cell_x/cell_z.
        s.shared_reach = g.cell_reach;
        const BinGrid& bg = bins.grid;
        // The bin columns of each cell column, once (not per cell).
        s.bin_columns.resize(2 * static_cast<std::size_t>(g.nx));
        for (std::uint32_t i = 0; i < g.nx; ++i) {
            s.bin_columns[2 * i] =
                bg.column(g.x0 + (static_cast<float>(i) - 0.01f) * g.cell_size_x);
            s.bin_columns[2 * i + 1] =
                bg.column(g.x0 + (static_cast<float>(i) + 1.01f) * g.cell_size_x);
        }
        for (std::uint32_t j = 0; j < g.nz; ++j) {
            const std::uint32_t bz0 =
                bg.row(g.z0 + (static_cast<float>(j) - 0.01f) * g.cell_size_z);
            const std::uint32_t bz1 =
                bg.row(g.z0 + (static_cast<float>(j) + 1.01f) * g.cell_size_z);
            for (std::uint32_t i = 0; i < g.nx; ++i) {
                float top = -std::numeric_limits<float>::infinity();
                for (std::uint32_t bz = bz0; bz <= bz1; ++bz) {
                    const float* row = bins.bin_top.data() + static_cast<std::size_t>(bz) * bg.nbx;
                    for (std::uint32_t bx = s.bin_columns[2 * i]; bx <= s.bin_columns[2 * i + 1];
                         ++bx) {
                        top = std::max(top, row[bx]);
                    }
                }
                const std::size_t cell = static_cast<std::size_t>(j) * g.nx + i;
                s.shared_reach[2 * cell] = std::max(s.shared_reach[2 * cell], top);
                s.shared_reach[2 * cell + 1] = std::max(s.shared_reach[2 * cell + 1], top);
            }
        }
        row_tops(g, s.shared_reach, s.shared_row_reach);
        s.shared_built = true;
        s.shared_solids_version = g.solids_version;
        s.shared_surfaces_version = g.surfaces_version;
        s.shared_tops_version = bins.tops_version;
    }
    t.context.reach = s.shared_reach.data();
    t.context.row_reach = s.shared_row_reach.data();
    t.context.shared = true;
}

void collide_end(World& w, const CollideTick& t) {
    // Sequential, in slot order: the ledger and the free stack see one order.
    const CollideScratch& scratch = t.scratch;
    FlakePool& pool = w.resource<FlakePool>();
    auto& ledger = w.resource<MassLedger>();
    for (std::size_t chunk = 0; chunk < scratch.counts.size(); ++chunk) {
        const std::size_t base = chunk * flake_grain;
        for (std::uint32_t k = 0; k < scratch.counts[chunk]; ++k) {
            const std::uint32_t slot = scratch.slots[base + k];
            const std::uint64_t units = scratch.units[base + k];
            switch (scratch.reasons[base + k]) {
            case Removal::bounds:
                ledger.removed_bounds += units;
                break;
            case Removal::sphere:
                ledger.removed_sphere += units;
                break;
            case Removal::bare:
                ledger.removed_bare += units;
                break;
            }
            pool.free_parked(slot); // parked by collide_block
        }
    }
}

} // namespace snow
