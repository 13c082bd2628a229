// collide: flakes against the bounds, spheres, boxes and mesh tops ([WF §4];
// meshes through the sky map of [SKY]). Detection runs in parallel over
// fixed chunks of slots; removals are applied afterwards in slot order, so the
// free stack and the state hash do not depend on the thread count.
#include "systems/body.hpp"
#include "systems/collider_grid.hpp"
#include "systems/flake_pool.hpp"
#include "systems/integrator.hpp"
#include "systems/jobs.hpp"
#include "systems/mass_ledger.hpp"
#include "systems/occlusion.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_cover.hpp"
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"
#include "systems/wind.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <glm/common.hpp>

namespace snow {

namespace {

enum class Removal : std::uint8_t { bounds, sphere, bare };

/// Texels per side of a block of the mesh-top summary.
constexpr std::uint32_t block_shift = 3;

/// World resource private to this file: per-slot "needs work" flags and
/// candidate/removal lists (chunk c uses [c·flake_grain, ...)), sized to the
/// pool capacity once; this tick's
/// SnowSurface pointers for ColliderGrid::holder_surfaces; and, per 8×8 block
/// of the occlusion map, the highest mesh top in it, so most flakes skip the
/// (cache-missing) texel lookup. The summary is rebuilt when the map or the
/// grid changes.
struct CollideScratch {
    std::vector<std::uint8_t> flags;
    std::vector<std::uint32_t> slots;
    std::vector<Removal> reasons;
    std::vector<std::uint32_t> counts;
    std::vector<const SnowSurface*> surfaces;
    std::vector<const SnowSurface*> covers; ///< this tick's cover surfaces
    std::vector<float> mesh_block_top;
    std::uint32_t blocks_x = 0;
    const OcclusionMap* blocks_map = nullptr;
    std::uint64_t blocks_map_version = 0;
    std::uint64_t blocks_grid_version = 0;
};

struct Context {
    FlakePool* pool = nullptr;
    const ColliderGrid* grid = nullptr;
    const OcclusionMap* map = nullptr; ///< null when no usable map exists
    const float* mesh_block_top = nullptr;
    std::uint32_t blocks_x = 0;
    const SnowSurface* const* surfaces = nullptr;
    const SnowSurface* const* covers = nullptr;
    std::uint32_t cover_count = 0;
    const Body* bodies = nullptr;
    std::uint32_t body_count = 0;
    Aabb body_box{glm::vec3{std::numeric_limits<float>::infinity()},
                  glm::vec3{-std::numeric_limits<float>::infinity()}}; ///< where bodies swept this tick
    Aabb bounds;
    float dt = 0.0f;
    Integrator integrator = Integrator::explicit_euler;
    glm::vec3 gravity{0.0f};
    glm::vec3 wind{0.0f};
    /// Speeds (m/s) at or above which a flake may leave the 3×3 cells around
    /// it in one tick (y: through a tilted map lookup), so cell_reach cannot
    /// clear it.
    float fast_x = 0.0f, fast_y = 0.0f, fast_z = 0.0f;
    CollideScratch* scratch = nullptr;
};

/// The flake may leave the 3×3 cells around it this tick, so the grid's
/// reach tables cannot clear it (NaN counts as fast).
bool is_fast(const Context& c, float vx, float vy, float vz) {
    // All three tests, no short cut: the caller's loop stays branch-free.
    const bool slow_x = std::abs(vx) < c.fast_x;
    const bool slow_y = std::abs(vy) < c.fast_y;
    const bool slow_z = std::abs(vz) < c.fast_z;
    return !(slow_x & slow_y & slow_z);
}

/// Result of the per-flake tests for a flake that is still inside the bounds.
enum class Outcome : std::uint8_t { keep, sphere, bare };

bool strictly_inside(const Aabb& b, const glm::vec3& p) {
    return p.x > b.min.x && p.x < b.max.x && p.y > b.min.y && p.y < b.max.y && p.z > b.min.z &&
           p.z < b.max.z;
}

/// Where along p0→p1 (t in [0, 1)) the segment enters the open sphere: 0 if
/// p0 is already inside; false if it never does (swept, so fast flakes
/// cannot jump over a sphere).
bool sphere_entry(const glm::vec3& p0, const glm::vec3& p1, const GridSphere& s, float& t) {
    const glm::vec3 d = p1 - p0;
    const glm::vec3 w = p0 - s.center;
    const float c = w.x * w.x + w.y * w.y + w.z * w.z - s.radius * s.radius;
    if (c < 0.0f) {
        t = 0.0f;
        return true;
    }
    const float a = d.x * d.x + d.y * d.y + d.z * d.z;
    const float b = w.x * d.x + w.y * d.y + w.z * d.z; // half the linear coefficient
    const float disc = b * b - a * c;
    if (!(a > 0.0f) || !(disc > 0.0f) || !(b < 0.0f)) {
        return false; // still, grazing, or moving away
    }
    t = (-b - std::sqrt(disc)) / a;
    return t < 1.0f;
}

/// A face of a box that a flake met, and the point on it.
struct BoxContact {
    int axis = 0;          ///< 0 x, 1 y, 2 z
    bool max_side = false; ///< the face at box.max[axis] (outward normal +axis)
    glm::vec3 at{0.0f};    ///< entry point (swept hit) or nearest face point
    float t = 0.0f;        ///< where along the path: 0 when it started inside
};

/// The face through which the segment p0→p1 enters the open box (slab test),
/// or, when p0 is already inside and p1 still is, the face nearest to p1.
/// False when the segment never reaches the interior or is leaving it.
bool box_contact(const Aabb& b, const glm::vec3& p0, const glm::vec3& p1, BoxContact& k) {
    // The path's bounding box misses the open box: the usual case, no divisions.
    const glm::vec3 lo = glm::min(p0, p1);
    const glm::vec3 hi = glm::max(p0, p1);
    if ((hi.x <= b.min.x) | (lo.x >= b.max.x) | (hi.y <= b.min.y) | (lo.y >= b.max.y) |
        (hi.z <= b.min.z) | (lo.z >= b.max.z)) {
        return false;
    }
    if (strictly_inside(b, p0)) {
        if (!strictly_inside(b, p1)) {
            return false;
        }
        // Nearest face; the top is tried first so a tie lands the flake.
        const float dist[6] = {b.max.y - p1.y, p1.x - b.min.x, b.max.x - p1.x,
                               p1.z - b.min.z, b.max.z - p1.z, p1.y - b.min.y};
        const int axes[6] = {1, 0, 0, 2, 2, 1};
        const bool maxes[6] = {true, false, true, false, true, false};
        int best = 0;
        for (int f = 1; f < 6; ++f) {
            best = dist[f] < dist[best] ? f : best;
        }
        k.axis = axes[best];
        k.max_side = maxes[best];
        k.at = p1;
        k.at[k.axis] = k.max_side ? b.max[k.axis] : b.min[k.axis];
        k.t = 0.0f;
        return true;
    }
    float enter = -std::numeric_limits<float>::infinity();
    float exit = std::numeric_limits<float>::infinity();
    int axis = -1;
    bool max_side = false;
    for (const int a : {1, 0, 2}) { // y first: a corner hit counts as a top hit
        const float d = p1[a] - p0[a];
        if (d == 0.0f) {
            if (!(p0[a] > b.min[a] && p0[a] < b.max[a])) {
                return false;
            }
            continue;
        }
        const float t_min = (b.min[a] - p0[a]) / d;
        const float t_max = (b.max[a] - p0[a]) / d;
        const float near = d > 0.0f ? t_min : t_max;
        const float far = d > 0.0f ? t_max : t_min;
        if (near > enter) {
            enter = near;
            axis = a;
            max_side = d < 0.0f;
        }
        exit = std::min(exit, far);
    }
    if (axis < 0 || !(enter < exit) || !(enter < 1.0f) || !(exit > 0.0f)) {
        return false;
    }
    k.axis = axis;
    k.max_side = max_side;
    k.at = p0 + (p1 - p0) * enter;
    for (int a = 0; a < 3; ++a) {
        k.at[a] = std::clamp(k.at[a], b.min[a], b.max[a]);
    }
    k.at[axis] = max_side ? b.max[axis] : b.min[axis];
    k.t = enter;
    return true;
}

/// One of the solid's surfaces covers (x, z).
bool covered(const Context& c, std::uint32_t begin, std::uint32_t end, float x, float z) {
    for (std::uint32_t i = begin; i < end; ++i) {
        std::uint32_t ix = 0, iz = 0;
        if (c.surfaces[i] != nullptr && c.surfaces[i]->cell_at(x, z, ix, iz)) {
            return true;
        }
    }
    return false;
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
/// there forever).
Outcome land_on_top(const Context& c, std::uint32_t surf_begin, std::uint32_t surf_end,
                    const glm::vec3& at, glm::vec3& p, glm::vec3& v, bool& moved) {
    if (!covered(c, surf_begin, surf_end, at.x, at.z)) {
        moved = cover_catches(c, at, p, v);
        return moved ? Outcome::keep : Outcome::bare;
    }
    p = at;
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
    FirstContact first;
    float best = std::numeric_limits<float>::infinity();
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
                float t = 0.0f;
                BoxContact k;
                const bool hit =
                    (item & ColliderGrid::sphere_tag) != 0
                        ? sphere_entry(p0, p, g.spheres[item & ~ColliderGrid::sphere_tag], t)
                        : box_contact(g.boxes[item].box, p0, p, k);
                t = (item & ColliderGrid::sphere_tag) != 0 ? t : k.t;
                if (hit && t < best) { // strict: the first listed wins a tie
                    best = t;
                    first = FirstContact{item, k, t, true};
                }
            }
        }
    }
    return first;
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
        p[k.axis] = k.at[k.axis];
        v[k.axis] = k.max_side ? std::max(v[k.axis], 0.0f) : std::min(v[k.axis], 0.0f);
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

/// Where relative path a→e (in a body's frame, centre at the origin) meets
/// the body: the point on its surface the flake is put on.
bool body_contact(const Body& b, const glm::vec3& a, const glm::vec3& e, glm::vec3& out) {
    switch (b.shape) {
    case BodyShape::box: {
        BoxContact k;
        if (!box_contact(Aabb{-b.half_extents, b.half_extents}, a, e, k)) {
            return false;
        }
        out = k.at;
        return true;
    }
    case BodyShape::capsule: {
        const glm::vec3 core{0.0f, std::clamp(e.y, -b.half_height, b.half_height), 0.0f};
        const glm::vec3 d = e - core;
        const float len = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
        if (!(len < b.radius)) {
            return false;
        }
        out = core + (len > 0.0f ? d / len : glm::vec3{1.0f, 0.0f, 0.0f}) * b.radius;
        return true;
    }
    case BodyShape::sphere:
        break;
    }
    float t = 0.0f;
    if (!sphere_entry(a, e, GridSphere{glm::vec3{0.0f}, b.radius}, t)) {
        return false;
    }
    const glm::vec3 q = a + (e - a) * t;
    const float len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    out = (len > 0.0f ? q / len : glm::vec3{0.0f, 1.0f, 0.0f}) * b.radius;
    return true;
}

/// Moving bodies, each tested in its own frame (its motion this tick taken
/// out), so a body sweeping over a resting flake meets it too. A flake that
/// enters is put on the body's surface and moves with it.
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
Outcome resolve(const Context& c, std::size_t i) {
    FlakePool& f = *c.pool;
    glm::vec3 p{f.px[i], f.py[i], f.pz[i]};
    glm::vec3 v{f.vx[i], f.vy[i], f.vz[i]};
    const float k = f.k_over_m[i];
    const glm::vec3 p0{
        integrate::path_start(c.integrator, p.x, v.x, k, c.gravity.x, c.wind.x, c.dt),
        integrate::path_start(c.integrator, p.y, v.y, k, c.gravity.y, c.wind.y, c.dt),
        integrate::path_start(c.integrator, p.z, v.z, k, c.gravity.z, c.wind.z, c.dt)};
    bool moved = false, done = false;
    Outcome out = grid_colliders(c, p0, p, v, moved, done);
    if (out == Outcome::keep && !done && c.map != nullptr) {
        const ColliderGrid& g = *c.grid;
        const float mesh_reach = g.cell_mesh_reach[g.cell_z(p.z) * g.nx + g.cell_x(p.x)];
        if (!(std::min(p.y, p0.y) > mesh_reach) || is_fast(c, v.x, v.y, v.z)) {
            out = mesh_top(c, p0, p, v, moved);
        }
    }
    if (out == Outcome::keep && c.body_box.contains(p)) {
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

/// Marks the flakes of [b, e) that may need work: out of bounds, fast, or low
/// enough to meet a collider near them. Selects only, so it vectorises; most
/// flakes are above everything near them and are never looked at again.
void flag_chunk(const Context& c, std::size_t b, std::size_t e, std::uint8_t* __restrict flags) {
    const FlakePool& f = *c.pool;
    const ColliderGrid& g = *c.grid;
    const std::uint32_t* mass = f.mass_units.data();
    const float* px = f.px.data();
    const float* py = f.py.data();
    const float* pz = f.pz.data();
    const float* vx = f.vx.data();
    const float* vy = f.vy.data();
    const float* vz = f.vz.data();
    const float* reach = g.cell_reach.data();
    const Aabb bb = c.bounds;
    const float dt = c.dt;
    for (std::size_t i = b; i < e; ++i) {
        const float x = px[i], y = py[i], z = pz[i];
        // [WF §4]: flakes outside the world's bounds are deactivated (NaN too).
        const bool inside = (x >= bb.min.x) & (x <= bb.max.x) & (y >= bb.min.y) & (y <= bb.max.y) &
                            (z >= bb.min.z) & (z <= bb.max.z);
        const float top = reach[g.cell_z(z) * g.nx + g.cell_x(x)];
        const float y0 = y - vy[i] * dt;
        const bool low = !((y < y0 ? y : y0) > top);
        const bool fast = is_fast(c, vx[i], vy[i], vz[i]);
        const Aabb& near = c.body_box;
        const bool body = (x >= near.min.x) & (x <= near.max.x) & (y >= near.min.y) &
                          (y <= near.max.y) & (z >= near.min.z) & (z <= near.max.z);
        flags[i - b] = (mass[i] != 0) & (!inside | low | fast | body) ? 1 : 0;
    }
}

/// Detection over slots [b, e) of one chunk: flag, list the flagged slots,
/// handle them, and compact the list in place to the removals.
void detect_chunk(const Context& c, std::size_t chunk, std::size_t b, std::size_t e) {
    const FlakePool& f = *c.pool;
    const float* px = f.px.data();
    const float* py = f.py.data();
    const float* pz = f.pz.data();
    const Aabb& bb = c.bounds;
    std::uint8_t* flags = c.scratch->flags.data() + chunk * flake_grain;
    std::uint32_t* slots = c.scratch->slots.data() + chunk * flake_grain;
    Removal* reasons = c.scratch->reasons.data() + chunk * flake_grain;
    flag_chunk(c, b, e, flags);
    // List the flagged slots, 8 flags per word: most words are zero (flakes
    // high above everything), so the scan costs a load per 8 slots.
    std::uint32_t candidates = 0;
    const std::size_t m = e - b;
    const std::size_t whole = m & ~std::size_t{7};
    for (std::size_t j = 0; j < whole; j += 8) {
        std::uint64_t word = 0;
        std::memcpy(&word, flags + j, sizeof word);
        for (; word != 0; word &= word - 1) {
            slots[candidates++] = static_cast<std::uint32_t>(b + j + std::countr_zero(word) / 8);
        }
    }
    for (std::size_t j = whole; j < m; ++j) {
        slots[candidates] = static_cast<std::uint32_t>(b + j);
        candidates += flags[j];
    }
    std::uint32_t n = 0;
    for (std::uint32_t k = 0; k < candidates; ++k) {
        const std::uint32_t i = slots[k];
        // Colliders first: a flake whose path crosses a roof and ends below the
        // bounds floor in the same tick is stopped by the roof, not removed.
        if (std::isfinite(px[i]) && std::isfinite(py[i]) && std::isfinite(pz[i])) {
            const Outcome o = resolve(c, i);
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
    c.scratch->counts[chunk] = n;
}

CollideScratch& scratch_for(World& w, const FlakePool& pool, const ColliderGrid& grid) {
    auto* s = w.try_resource<CollideScratch>();
    if (s == nullptr) {
        s = &w.set_resource<CollideScratch>();
    }
    // Sizes change only with the pool capacity or a grid rebuild: no steady-tick allocation.
    s->flags.resize(pool.capacity());
    s->slots.resize(pool.capacity());
    s->reasons.resize(pool.capacity());
    s->counts.resize(JobPool::chunk_count(pool.capacity(), flake_grain));
    s->surfaces.resize(grid.holder_surfaces.size());
    for (std::size_t i = 0; i < grid.holder_surfaces.size(); ++i) {
        s->surfaces[i] = w.try_get<SnowSurface>(grid.holder_surfaces[i]);
    }
    s->covers.clear(); // capacity stays: no steady-tick allocation
    if (const auto* covers = w.find_pool<SnowCover>()) {
        for (const Entity e : covers->entities()) {
            s->covers.push_back(&w.get<SnowSurface>(e));
        }
    }
    return *s;
}

/// Rebuilds the per-block highest mesh top when the map or the grid changed.
void update_mesh_blocks(CollideScratch& s, const OcclusionMap& map, const ColliderGrid& grid) {
    if (s.blocks_map == &map && s.blocks_map_version == map.version &&
        s.blocks_grid_version == grid.geometry_version && !s.mesh_block_top.empty()) {
        return;
    }
    const std::uint32_t block = 1u << block_shift;
    s.blocks_x = (map.width + block - 1) >> block_shift;
    const std::uint32_t blocks_z = (map.height + block - 1) >> block_shift;
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
    s.blocks_map = &map;
    s.blocks_map_version = map.version;
    s.blocks_grid_version = grid.geometry_version;
}

} // namespace

void collide_system(World& w) {
    FlakePool& pool = w.resource<FlakePool>();
    const ColliderGrid& grid = update_collider_grid(w);
    CollideScratch& scratch = scratch_for(w, pool, grid);

    Context c;
    c.pool = &pool;
    c.grid = &grid;
    const auto* map = w.try_resource<OcclusionMap>();
    c.map = map != nullptr && map->width > 0 && !grid.meshes.empty() ? map : nullptr;
    if (c.map != nullptr) {
        update_mesh_blocks(scratch, *c.map, grid);
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
        // Their swept boxes, grown by what a flake moves in a tick at 20 m/s
        // (faster flakes are flagged as fast anyway).
        for (const Body& b : bodies->components()) {
            const glm::vec3 r{b.shape == BodyShape::box ? b.half_extents : glm::vec3{b.reach()}};
            const glm::vec3 lift{0.0f, b.shape == BodyShape::capsule ? b.half_height : 0.0f, 0.0f};
            const glm::vec3 margin = r + lift + glm::vec3{20.0f * c.dt};
            c.body_box.min = glm::min(c.body_box.min, glm::min(b.previous, b.position) - margin);
            c.body_box.max = glm::max(c.body_box.max, glm::max(b.previous, b.position) + margin);
        }
    }
    c.integrator = cfg.integrator;
    c.gravity = cfg.gravity;
    if (const auto* wind = w.try_resource<Wind>()) {
        c.wind = wind->current;
    }
    // 0.9 of a cell per tick leaves margin for the rounding of p - v·dt.
    c.fast_x = 0.9f * grid.cell_size_x / c.dt;
    c.fast_z = 0.9f * grid.cell_size_z / c.dt;
    const float shear =
        c.map != nullptr ? std::max(std::abs(c.map->shear_x), std::abs(c.map->shear_z)) : 0.0f;
    c.fast_y = shear > 0.0f ? 0.9f * std::min(grid.cell_size_x, grid.cell_size_z) / (shear * c.dt)
                            : std::numeric_limits<float>::infinity();
    c.scratch = &scratch;

    // Slots past slot_end were never alive: no work there.
    const std::size_t n = pool.slot_end;
    for_chunks(w, n, flake_grain, [p = &c](std::size_t chunk, std::size_t b, std::size_t e) {
        detect_chunk(*p, chunk, b, e);
    });

    // Sequential, in slot order: the ledger and the free stack see one order.
    auto& ledger = w.resource<MassLedger>();
    const std::size_t chunks = JobPool::chunk_count(n, flake_grain);
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
        const std::size_t base = chunk * flake_grain;
        for (std::uint32_t k = 0; k < scratch.counts[chunk]; ++k) {
            const std::uint32_t slot = scratch.slots[base + k];
            const std::uint64_t units = pool.mass_units[slot];
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
            pool.release(slot);
        }
    }
}

} // namespace snow
