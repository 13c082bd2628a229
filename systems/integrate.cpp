// integrate: F = m·g + k·(w − v), a = F/m ([WF §3], [ZCL §III.C]), one
// rule per SimConfig::integrator. Flakes too stiff for the chosen rule
// (c·dt past its limit) take the exact update instead and are counted.
//
// Each flake moves in place; its old position goes to the block's PathStarts
// (flake_stages.hpp): the path start is produced here, once, for collide and
// deposit. With a declared wind field each flake drags towards
// the field's wind at its path start (trilinear, WindSampler::at, sampled for
// the whole block first) instead of the one global wind.
//
// The guarded pass is one branch-free loop over distinct (__restrict) arrays
// so GCC and Clang vectorise it (selects need -fno-trapping-math, set
// project-wide); it computes exactly what the scalar rule computes, lane by
// lane (no FMA contraction, no reassociation), so SIMD and scalar builds agree
// bit for bit.
#include "systems/flake_pool.hpp"
#include "systems/flake_stages.hpp"
#include "systems/integrator.hpp"
#include "systems/jobs.hpp"
#include "systems/sim_config.hpp"
#include "systems/systems.hpp"
#include "systems/wind.hpp"
#include "systems/wind_field.hpp"

#include <bit>
#include <cstdint>
#include <vector>

namespace snow {

namespace {

using AxisRule = void (*)(float&, float&, float, float, float, float);

struct Params {
    glm::vec3 g;
    glm::vec3 w;
    float dt;
};

/// The wind a flake drags towards: the global wind, or the field's sampled
/// for each slot of the block before the move (FieldWind). Both give it as
/// scalars: a vec3 per lane stops GCC vectorising.
struct GlobalWind {
    float x, y, z;
    void at(std::size_t, float& wx, float& wy, float& wz) const {
        wx = x;
        wy = y;
        wz = z;
    }
};

/// The field's wind at each slot's path start, sampled in a loop of its own:
/// in the move's loop GCC cannot prove the field's gathers apart from the
/// stores (it gives up and stays scalar), in a loop that writes only these
/// local arrays it can.
struct FieldWind {
    alignas(64) float x[flake_block];
    alignas(64) float y[flake_block];
    alignas(64) float z[flake_block];

    FieldWind(const WindSampler& s, const float* __restrict px, const float* __restrict py,
              const float* __restrict pz, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) {
            s.at(px[i], py[i], pz[i], x[i], y[i], z[i]);
        }
    }
    void at(std::size_t i, float& wx, float& wy, float& wz) const {
        wx = x[i];
        wy = y[i];
        wz = z[i];
    }
};

/// Base pointers of the arrays one block reads and writes.
struct Lanes {
    float* sx; ///< path starts: written with the positions before the move
    float* sy;
    float* sz;
    float* px;
    float* py;
    float* pz;
    float* vx;
    float* vy;
    float* vz;
    const float* kom;
    const std::uint32_t* mass;
};

/// `a` where `mask` is all ones, `b` where it is zero, bit for bit.
inline float blend(std::uint32_t mask, float a, float b) {
    return std::bit_cast<float>((std::bit_cast<std::uint32_t>(a) & mask) |
                                (std::bit_cast<std::uint32_t>(b) & ~mask));
}

/// The rule for every alive slot of [0, n) whose c·dt <= limit; every other
/// slot keeps its position. Every slot's position before the move goes to
/// sx/sy/sz. Returns how many alive slots were over the limit
/// (left at their start for the exact pass). The arrays are distinct
/// (__restrict): that spares GCC the run-time alias checks it would otherwise
/// need (it gives up past 10 and stays scalar), and Clang the same.
template <AxisRule rule, typename Air>
std::uint32_t guarded_lanes(float* __restrict sx, float* __restrict sy, float* __restrict sz,
                            float* __restrict px, float* __restrict py, float* __restrict pz,
                            float* __restrict vx, float* __restrict vy, float* __restrict vz,
                            const float* __restrict kom, const std::uint32_t* __restrict mass,
                            std::size_t n, const Params q, const Air air, const float limit) {
    std::uint32_t stiff = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const float c = kom[i];
        const float x0 = px[i], y0 = py[i], z0 = pz[i], u0 = vx[i], v0 = vy[i], s0 = vz[i];
        sx[i] = x0;
        sy[i] = y0;
        sz[i] = z0;
        float x = x0, y = y0, z = z0, u = u0, v = v0, s = s0;
        float wx, wy, wz;
        air.at(i, wx, wy, wz);
        rule(x, u, c, q.g.x, wx, q.dt);
        rule(y, v, c, q.g.y, wy, q.dt);
        rule(z, s, c, q.g.z, wz, q.dt);
        const bool alive = mass[i] != 0;
        const bool over = c * q.dt > limit;
        const bool use = alive & !over;
        // A bitwise blend, stored in every lane: written as a select, GCC
        // turns it into masked loads and stores (vmaskmovps), which cost
        // several times plain ones on Zen. Bit for bit the same result.
        const std::uint32_t keep_new = use ? ~0u : 0u;
        px[i] = blend(keep_new, x, x0);
        py[i] = blend(keep_new, y, y0);
        pz[i] = blend(keep_new, z, z0);
        vx[i] = blend(keep_new, u, u0);
        vy[i] = blend(keep_new, v, v0);
        vz[i] = blend(keep_new, s, s0);
        stiff += (alive & over) ? 1u : 0u;
    }
    return stiff;
}

template <AxisRule rule, typename Air>
std::uint32_t guarded_pass(const Lanes& l, std::size_t n, const Params& q, const Air& air,
                           float limit) {
    return guarded_lanes<rule>(l.sx, l.sy, l.sz, l.px, l.py, l.pz, l.vx, l.vy, l.vz, l.kom, l.mass,
                               n, q, air, limit);
}

/// Exact update for the alive slots of [0, n) a guarded pass skipped.
template <typename Air>
void exact_pass(const Lanes& l, std::size_t n, const Params& q, const Air& air, float limit) {
    for (std::size_t i = 0; i < n; ++i) {
        const float c = l.kom[i];
        if (l.mass[i] == 0 || !(c * q.dt > limit)) {
            continue;
        }
        float wx, wy, wz;
        air.at(i, wx, wy, wz); // the slot has not moved: its start
        integrate::exponential(l.px[i], l.vx[i], c, q.g.x, wx, q.dt);
        integrate::exponential(l.py[i], l.vy[i], c, q.g.y, wy, q.dt);
        integrate::exponential(l.pz[i], l.vz[i], c, q.g.z, wz, q.dt);
    }
}

} // namespace

/// Everything a block reads this tick (the world resource of this file).
struct IntegrateTick {
    Lanes pool{}; ///< the pool's arrays (sx/sy/sz unused: each block gets its own)
    Params q{};
    const WindField* field = nullptr; ///< null: every flake feels q.w
    Integrator kind = Integrator::explicit_euler;
    /// One count per chunk, sized once per pool size; each chunk's blocks
    /// (one thread, one after another) add to its own entry only.
    mutable std::vector<std::uint32_t> stiff;
};

namespace {

template <typename Air>
std::uint32_t integrate_lanes(const IntegrateTick& t, const Air& air, const Lanes& l,
                              std::size_t n) {
    // Rules without a stability limit get an infinite one.
    constexpr float none = 3.0e38f;
    std::uint32_t stiff = 0;
    float limit = none;
    switch (t.kind) {
    case Integrator::explicit_euler:
        limit = integrate::explicit_limit;
        stiff = guarded_pass<integrate::explicit_euler>(l, n, t.q, air, limit);
        break;
    case Integrator::automatic:
        limit = integrate::automatic_limit;
        stiff = guarded_pass<integrate::explicit_euler>(l, n, t.q, air, limit);
        break;
    case Integrator::rk4:
        limit = integrate::rk4_limit;
        stiff = guarded_pass<integrate::rk4>(l, n, t.q, air, limit);
        break;
    case Integrator::semi_implicit_euler:
        guarded_pass<integrate::semi_implicit_euler>(l, n, t.q, air, none);
        break;
    case Integrator::exponential:
        guarded_pass<integrate::exponential>(l, n, t.q, air, none);
        break;
    }
    if (stiff > 0) {
        exact_pass(l, n, t.q, air, limit);
    }
    return stiff;
}

} // namespace

IntegrateTick& integrate_begin(World& w) {
    const auto& cfg = w.resource<SimConfig>();
    FlakePool& f = w.resource<FlakePool>();
    const auto* wind = w.try_resource<Wind>();
    auto* t = w.try_resource<IntegrateTick>();
    if (t == nullptr) {
        t = &w.set_resource<IntegrateTick>();
    }
    t->pool = {
        nullptr,     nullptr,     nullptr,     f.px.data(),       f.py.data(),        f.pz.data(),
        f.vx.data(), f.vy.data(), f.vz.data(), f.k_over_m.data(), f.mass_units.data()};
    t->q = {cfg.gravity, wind ? wind->current : glm::vec3(0.0f), cfg.dt};
    t->field = w.try_resource<WindField>();
    t->kind = cfg.integrator;
    t->stiff.resize(
        JobPool::chunk_count(f.capacity(), flake_grain)); // allocates once per pool size
    std::fill(t->stiff.begin(), t->stiff.end(), 0u);
    return *t;
}

void integrate_block(const IntegrateTick& t, std::size_t chunk, const PathStarts& starts,
                     std::size_t b, std::size_t e) {
    const Lanes& a = t.pool;
    const std::size_t o = b - starts.base;
    const Lanes l{starts.x + o, starts.y + o, starts.z + o, a.px + b,  a.py + b,  a.pz + b,
                  a.vx + b,     a.vy + b,     a.vz + b,     a.kom + b, a.mass + b};
    const std::size_t n = e - b;
    const std::uint32_t stiff =
        t.field != nullptr
            ? integrate_lanes(t, FieldWind(t.field->sampler(), l.px, l.py, l.pz, n), l, n)
            : integrate_lanes(t, GlobalWind{t.q.w.x, t.q.w.y, t.q.w.z}, l, n);
    t.stiff[chunk] += stiff;
}

void integrate_end(World& w, const IntegrateTick& t) {
    // Per-chunk counts summed in chunk order: independent of the thread count.
    auto& counters = w.resource<SimCounters>();
    for (const std::uint32_t s : t.stiff) {
        counters.stiff_flake_ticks += s;
    }
}

} // namespace snow
