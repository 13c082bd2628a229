// integrate: F = m·g + k·(w − v), a = F/m ([WF §3], [ZCL §III.C]), one
// rule per SimConfig::integrator. Flakes too stiff for the chosen rule
// (c·dt past its limit) take the exact update instead and are counted.
//
// Each flake moves in place; its old position goes to the block's PathStarts
// (flake_stages.hpp): the path start is produced here, once, for collide and
// deposit. With a declared wind field each flake drags towards the field's
// wind it holds instead of the one global wind; the block's due slots sample
// the field first, half a hold ahead of their path start (trilinear,
// WindSampler::steps_at; which slots when: held_wind.hpp).
//
// The guarded pass is one branch-free loop over distinct (__restrict) arrays
// so GCC and Clang vectorise it (selects need -fno-trapping-math, set
// project-wide); it computes exactly what the scalar rule computes, lane by
// lane (no FMA contraction, no reassociation), so SIMD and scalar builds agree
// bit for bit.
#include "systems/api/systems.hpp"
#include "systems/core/jobs.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/flakes/flake_stages.hpp"
#include "systems/flakes/held_wind.hpp"
#include "systems/flakes/integrator.hpp"
#include "systems/wind/wind.hpp"
#include "systems/wind/wind_field.hpp"

#include <bit>
#include <cstdint>

namespace snow {

namespace {

using AxisRule = void (*)(float&, float&, float, float, float, float);

struct Params {
    glm::vec3 g;
    glm::vec3 w;
    float dt;
};

/// The wind a flake drags towards: the global wind, or the field's wind the
/// slot holds (HeldWind). Both give it as scalars: a vec3 per lane stops GCC
/// vectorising.
struct GlobalWind {
    float x, y, z;
    void at(std::size_t, float& wx, float& wy, float& wz) const {
        wx = x;
        wy = y;
        wz = z;
    }
};

/// The field's wind each slot holds (held_wind.hpp), in m/s.
struct HeldWind {
    const std::int16_t* x;
    const std::int16_t* y;
    const std::int16_t* z;
    void at(std::size_t i, float& wx, float& wy, float& wz) const {
        wx = held_wind_component(x[i]);
        wy = held_wind_component(y[i]);
        wz = held_wind_component(z[i]);
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
    // With a field: what the held winds are sampled from, and when.
    WindSampler sampler{};
    std::int16_t* held[3] = {nullptr, nullptr, nullptr};
    std::uint32_t sample_every = 1;
    std::uint32_t phase = 0; ///< each block's run number phase samples this tick
    float lookahead = 0.0f;  ///< s: half a hold, how far ahead of the flake a sample is taken
    Integrator kind = Integrator::explicit_euler;
    /// One count per chunk, sized with the pool; each chunk's blocks
    /// (one thread, one after another) add to its own entry only.
    mutable Vector<std::uint32_t> stiff;
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

IntegrateTick& prepare_integrate(World& w) {
    auto* t = w.try_resource<IntegrateTick>();
    if (t == nullptr) {
        t = &w.set_resource<IntegrateTick>();
    }
    t->stiff.resize(chunk_count(w.resource<FlakePool>().capacity(), flake_grain));
    return *t;
}

IntegrateTick& integrate_begin(World& w) {
    const auto& cfg = w.resource<SimConfig>();
    FlakePool& f = w.resource<FlakePool>();
    const auto* wind = w.try_resource<Wind>();
    IntegrateTick* t = &prepare_integrate(w);
    t->pool = {
        nullptr,     nullptr,     nullptr,     f.px.data(),       f.py.data(),        f.pz.data(),
        f.vx.data(), f.vy.data(), f.vz.data(), f.k_over_m.data(), f.mass_units.data()};
    t->q = {cfg.gravity, wind ? wind->current : glm::vec3(0.0f), cfg.dt};
    t->field = w.try_resource<WindField>();
    if (t->field != nullptr) {
        t->sampler = t->field->sampler();
        for (int a = 0; a < 3; ++a) {
            t->held[a] = f.held_wind[a].data();
        }
        t->sample_every = t->field->def.sample_every;
        t->phase = static_cast<std::uint32_t>(w.resource<SimClock>().tick % t->sample_every);
        t->lookahead = 0.5f * static_cast<float>(t->sample_every) * cfg.dt;
    }
    t->kind = cfg.integrator;
    std::fill(t->stiff.begin(), t->stiff.end(), 0u);
    return *t;
}

namespace {

/// The field where the n slots from s will be halfway through the hold
/// (their path start plus half a hold at their velocity: the hold's lag,
/// centred), held. Sampled into local arrays first, in a loop that writes
/// nothing else, so GCC vectorises it (its gathers cannot alias a store).
void sample_held(const IntegrateTick& t, std::size_t s, std::size_t n) {
    alignas(64) float wx[flake_block], wy[flake_block], wz[flake_block];
    const float* __restrict px = t.pool.px + s;
    const float* __restrict py = t.pool.py + s;
    const float* __restrict pz = t.pool.pz + s;
    const float* __restrict vx = t.pool.vx + s;
    const float* __restrict vy = t.pool.vy + s;
    const float* __restrict vz = t.pool.vz + s;
    const WindSampler sampler = t.sampler;
    const float ahead = t.lookahead;
    for (std::size_t i = 0; i < n; ++i) {
        sampler.steps_at(px[i] + ahead * vx[i], py[i] + ahead * vy[i], pz[i] + ahead * vz[i], wx[i],
                         wy[i], wz[i]);
    }
    std::int16_t* __restrict hx = t.held[0] + s;
    std::int16_t* __restrict hy = t.held[1] + s;
    std::int16_t* __restrict hz = t.held[2] + s;
    for (std::size_t i = 0; i < n; ++i) {
        hx[i] = hold_steps(wx[i]);
        hy[i] = hold_steps(wy[i]);
        hz[i] = hold_steps(wz[i]);
    }
}

/// Samples the field for the slots of the block [b, e) due this tick,
/// before they move: the block's phase-th run of flake_block / sample_every
/// slots (rounded up), and those made since the last tick (unset), alive or
/// not (a free slot's sample is never read). The run is contiguous, so the
/// sampling vectorises and its reads stay in the few columns the block's
/// flakes lie in (flake_order.hpp); the unset are rare, found by a scan that
/// vectorises.
void refresh_held(const IntegrateTick& t, std::size_t b, std::size_t e) {
    const std::size_t run = (flake_block + t.sample_every - 1) / t.sample_every;
    const std::size_t first = b + std::size_t{t.phase} * run;
    if (first < e) {
        sample_held(t, first, std::min(run, e - first));
    }
    const std::int16_t* hx = t.held[0];
    const std::uint32_t* mass = t.pool.mass;
    std::uint32_t unset = 0;
    for (std::size_t s = b; s < e; ++s) {
        unset |= (hx[s] == held_wind_unset ? 1u : 0u) & (mass[s] != 0 ? 1u : 0u);
    }
    if (unset == 0) {
        return;
    }
    for (std::size_t s = b; s < e; ++s) {
        if (hx[s] == held_wind_unset && mass[s] != 0) {
            sample_held(t, s, 1);
        }
    }
}

} // namespace

void integrate_block(const IntegrateTick& t, std::size_t chunk, const PathStarts& starts,
                     std::size_t b, std::size_t e) {
    const Lanes& a = t.pool;
    const std::size_t o = b - starts.base;
    const Lanes l{starts.x + o, starts.y + o, starts.z + o, a.px + b,  a.py + b,  a.pz + b,
                  a.vx + b,     a.vy + b,     a.vz + b,     a.kom + b, a.mass + b};
    const std::size_t n = e - b;
    std::uint32_t stiff = 0;
    if (t.field != nullptr) {
        refresh_held(t, b, e);
        stiff = integrate_lanes(t, HeldWind{t.held[0] + b, t.held[1] + b, t.held[2] + b}, l, n);
    } else {
        stiff = integrate_lanes(t, GlobalWind{t.q.w.x, t.q.w.y, t.q.w.z}, l, n);
    }
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
