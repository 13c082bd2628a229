// integrate: F = m·g + k·(w − v), a = F/m (seeds 002 §3, 003 §III.C), one
// rule per SimConfig::integrator. Flakes too stiff for the chosen rule
// (c·dt past its limit) take the exact update instead and are counted.
#include "systems/flake_pool.hpp"
#include "systems/integrator.hpp"
#include "systems/jobs.hpp"
#include "systems/sim_config.hpp"
#include "systems/systems.hpp"
#include "systems/wind.hpp"

#include <array>
#include <vector>

namespace snow {

namespace {

/// World resource: per-chunk stiff counts of the last integrate pass.
struct StiffCounts {
    std::vector<std::uint64_t> per_chunk;
};

using AxisRule = void (*)(float&, float&, float, float, float, float);

struct Params {
    glm::vec3 g;
    glm::vec3 w;
    float dt;
};

/// The rule for every alive flake whose c·dt <= limit; returns how many
/// alive flakes were over the limit (left untouched for the exact pass).
template <AxisRule rule>
std::uint64_t guarded_pass(FlakePool& f, std::size_t b, std::size_t e, const Params& q,
                           float limit) {
    float* px = f.px.data();
    float* py = f.py.data();
    float* pz = f.pz.data();
    float* vx = f.vx.data();
    float* vy = f.vy.data();
    float* vz = f.vz.data();
    const float* kom = f.k_over_m.data();
    const std::uint32_t* mass = f.mass_units.data();
    std::uint64_t stiff = 0;
    for (std::size_t i = b; i < e; ++i) {
        const float c = kom[i];
        float x = px[i], y = py[i], z = pz[i], u = vx[i], v = vy[i], s = vz[i];
        rule(x, u, c, q.g.x, q.w.x, q.dt);
        rule(y, v, c, q.g.y, q.w.y, q.dt);
        rule(z, s, c, q.g.z, q.w.z, q.dt);
        const bool alive = mass[i] != 0;
        const bool over = c * q.dt > limit;
        const bool use = alive && !over;
        px[i] = use ? x : px[i];
        py[i] = use ? y : py[i];
        pz[i] = use ? z : pz[i];
        vx[i] = use ? u : vx[i];
        vy[i] = use ? v : vy[i];
        vz[i] = use ? s : vz[i];
        stiff += (alive && over) ? 1u : 0u;
    }
    return stiff;
}

/// Exact update for the alive flakes a guarded pass skipped.
void exact_pass(FlakePool& f, std::size_t b, std::size_t e, const Params& q, float limit) {
    for (std::size_t i = b; i < e; ++i) {
        const float c = f.k_over_m[i];
        if (f.mass_units[i] == 0 || !(c * q.dt > limit)) {
            continue;
        }
        integrate::exponential(f.px[i], f.vx[i], c, q.g.x, q.w.x, q.dt);
        integrate::exponential(f.py[i], f.vy[i], c, q.g.y, q.w.y, q.dt);
        integrate::exponential(f.pz[i], f.vz[i], c, q.g.z, q.w.z, q.dt);
    }
}

std::uint64_t integrate_chunk(Integrator kind, FlakePool& f, std::size_t b, std::size_t e,
                              const Params& q) {
    // Rules without a stability limit get an infinite one.
    constexpr float none = 3.0e38f;
    std::uint64_t stiff = 0;
    float limit = none;
    switch (kind) {
    case Integrator::explicit_euler:
        limit = integrate::explicit_limit;
        stiff = guarded_pass<integrate::explicit_euler>(f, b, e, q, limit);
        break;
    case Integrator::automatic:
        limit = integrate::automatic_limit;
        stiff = guarded_pass<integrate::explicit_euler>(f, b, e, q, limit);
        break;
    case Integrator::rk4:
        limit = integrate::rk4_limit;
        stiff = guarded_pass<integrate::rk4>(f, b, e, q, limit);
        break;
    case Integrator::semi_implicit_euler:
        guarded_pass<integrate::semi_implicit_euler>(f, b, e, q, none);
        break;
    case Integrator::exponential:
        guarded_pass<integrate::exponential>(f, b, e, q, none);
        break;
    }
    if (stiff > 0) {
        exact_pass(f, b, e, q, limit);
    }
    return stiff;
}

} // namespace

void integrate_system(World& w) {
    const auto& cfg = w.resource<SimConfig>();
    FlakePool& f = w.resource<FlakePool>();
    const auto* wind = w.try_resource<Wind>();
    const Params q{cfg.gravity, wind ? wind->current : glm::vec3(0.0f), cfg.dt};
    const std::size_t n = f.capacity();
    const std::size_t chunks = JobPool::chunk_count(n, flake_grain);
    // One counter per chunk, summed in chunk order (thread-count independent);
    // kept in the world so no tick after the first allocates.
    auto* scratch = w.try_resource<StiffCounts>();
    if (scratch == nullptr) {
        scratch = &w.set_resource<StiffCounts>();
    }
    std::vector<std::uint64_t>& stiff = scratch->per_chunk;
    stiff.assign(chunks, 0);
    for_chunks(w, n, flake_grain, [&](std::size_t c, std::size_t b, std::size_t e) {
        stiff[c] = integrate_chunk(cfg.integrator, f, b, e, q);
    });
    auto& counters = w.resource<SimCounters>();
    for (const std::uint64_t s : stiff) {
        counters.stiff_flake_ticks += s;
    }
}

} // namespace snow
