// Hard case 1: stiff drag. With a = k·dt/m = 50 and 1000 explicit Euler
// multiplies the gap to terminal velocity by (1 − a) per step (NaN within a
// few steps); every integrator must instead stay finite and approach
// v_t = wind + g/c monotonically (docs/design.md "Numerical stability").
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"

#include "systems/flakes/integrator.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace snow {
namespace {

constexpr Integrator all_integrators[] = {Integrator::explicit_euler,
                                          Integrator::semi_implicit_euler, Integrator::exponential,
                                          Integrator::rk4, Integrator::automatic};

/// Float rounding allowed around the terminal velocity (m/s).
constexpr double settle_eps = 1e-6;

/// The same for a mild flake: a rule that closes the gap by a factor ~a per
/// tick stops moving once a·gap is below the rounding of v (a few ulp), so
/// its float fixed point sits up to ~ulp/a from v_t.
double settle_eps_for(float a) {
    return settle_eps / std::min(1.0, static_cast<double>(a));
}

/// Start velocities on both sides of the terminal one, per axis.
const std::vector<glm::vec3> starts = {
    {0.0f, 0.0f, 0.0f}, {-40.0f, 25.0f, 60.0f}, {40.0f, -200.0f, -60.0f}, {3.0f, -1.0f, -1.5f}};

struct StiffCase {
    float a;  ///< k·dt/m
    float dt; ///< s
};

TEST(HardCaseStiffDrag, EveryIntegratorStaysFiniteMonotoneAndConverges) {
    const glm::vec3 wind_v{3.0f, 0.0f, -1.5f};
    for (const StiffCase sc : {StiffCase{50.0f, 1.0f / 60.0f}, StiffCase{1000.0f, 1.0f / 60.0f},
                               StiffCase{50.0f, 0.25f}, StiffCase{1000.0f, 0.25f}}) {
        const float c = sc.a / sc.dt;
        for (const Integrator integ : all_integrators) {
            SCOPED_TRACE(::testing::Message()
                         << integrator_name(integ) << " a=" << sc.a << " dt=" << sc.dt);
            SimConfig cfg;
            cfg.dt = sc.dt;
            cfg.integrator = integ;
            cfg.bounds = {{-1e6f, -1e6f, -1e6f}, {1e6f, 1e6f, 1e6f}};
            cfg.max_flakes = 8;
            Simulation sim(cfg);
            Wind w;
            w.base = w.current = wind_v;
            w.walk = 0.0f; // constant wind: the terminal velocity is exact
            sim.set_wind(w);
            for (const glm::vec3& v0 : starts) {
                hard::place_flake(sim, {0.0f, 100.0f, 0.0f}, v0, c, 7);
            }
            // Terminal velocity per axis, in double: wind + g/c.
            const double vt[3] = {wind_v.x, wind_v.y + cfg.gravity.y / static_cast<double>(c),
                                  wind_v.z};
            const FlakePool& f = flake_pool(sim);
            std::vector<glm::dvec3> gap(starts.size());
            auto read_gap = [&](std::size_t s) {
                return glm::dvec3{f.vx[s] - vt[0], f.vy[s] - vt[1], f.vz[s] - vt[2]};
            };
            for (std::size_t s = 0; s < starts.size(); ++s) {
                gap[s] = read_gap(s);
            }
            const int ticks = 200;
            for (int t = 0; t < ticks; ++t) {
                sim.tick();
                ASSERT_TRUE(hard::healthy(sim));
                for (std::size_t s = 0; s < starts.size(); ++s) {
                    const glm::dvec3 g = read_gap(s);
                    for (int ax = 0; ax < 3; ++ax) {
                        // Monotone: never farther, never across (beyond float rounding).
                        const bool settled = std::abs(g[ax]) <= settle_eps;
                        const bool same_side = (g[ax] > 0.0) == (gap[s][ax] > 0.0);
                        ASSERT_TRUE(settled ||
                                    (same_side && std::abs(g[ax]) <= std::abs(gap[s][ax])))
                            << "flake " << s << " axis " << ax << " tick " << t << ": gap "
                            << gap[s][ax] << " -> " << g[ax];
                    }
                    gap[s] = g;
                }
            }
            for (std::size_t s = 0; s < starts.size(); ++s) {
                for (int ax = 0; ax < 3; ++ax) {
                    EXPECT_LE(std::abs(gap[s][ax]), settle_eps) << "flake " << s << " axis " << ax;
                }
                EXPECT_TRUE(std::isfinite(f.px[s]) && std::isfinite(f.py[s]) &&
                            std::isfinite(f.pz[s]));
            }
            // The rules with a stability limit must have noticed every stiff flake-tick.
            const bool guarded = integ == Integrator::explicit_euler || integ == Integrator::rk4 ||
                                 integ == Integrator::automatic;
            EXPECT_EQ(sim.counters().stiff_flake_ticks, guarded ? ticks * starts.size() : 0u);
        }
    }
}

TEST(HardCaseStiffDrag, MixedStiffnessInOnePoolAroundEveryLimit) {
    // One pool holding flakes just below and above each rule's limit (0.5, 1,
    // 2, 2.5) and far past them: the per-flake switch must not disturb the others.
    const float dt = 1.0f / 60.0f;
    const float as[] = {0.1f, 0.49f, 0.51f, 0.99f, 1.01f, 1.9f,
                        2.1f, 2.49f, 2.51f, 2.9f,  50.0f, 1000.0f};
    for (const Integrator integ : all_integrators) {
        SCOPED_TRACE(integrator_name(integ));
        SimConfig cfg;
        cfg.dt = dt;
        cfg.integrator = integ;
        cfg.bounds = {{-1e6f, -1e6f, -1e6f}, {1e6f, 1e6f, 1e6f}};
        cfg.max_flakes = 16;
        Simulation sim(cfg);
        for (const float a : as) {
            hard::place_flake(sim, {0.0f, 100.0f, 0.0f}, {0.0f, 5.0f, 0.0f}, a / dt, 3);
        }
        std::vector<double> prev(std::size(as));
        const FlakePool& f = flake_pool(sim);
        for (std::size_t s = 0; s < std::size(as); ++s) {
            prev[s] = f.vy[s] - cfg.gravity.y * dt / as[s]; // gap to v_t = g/c
        }
        for (int t = 0; t < 2000; ++t) {
            sim.tick();
            ASSERT_TRUE(hard::healthy(sim));
            for (std::size_t s = 0; s < std::size(as); ++s) {
                const double vt = cfg.gravity.y * dt / as[s];
                const double g = f.vy[s] - vt;
                // Explicit Euler below its limit 1 and RK4 below 2.78 never cross either.
                ASSERT_TRUE(std::abs(g) <= settle_eps_for(as[s]) ||
                            ((g > 0.0) == (prev[s] > 0.0) && std::abs(g) <= std::abs(prev[s])))
                    << "a=" << as[s] << " tick " << t << ": " << prev[s] << " -> " << g;
                prev[s] = g;
            }
        }
        for (std::size_t s = 0; s < std::size(as); ++s) {
            EXPECT_LE(std::abs(prev[s]), settle_eps_for(as[s])) << "a=" << as[s];
        }
    }
}

} // namespace
} // namespace snow
