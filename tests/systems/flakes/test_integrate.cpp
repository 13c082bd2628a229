#include "systems/api/simulation_internals.hpp"
#include "systems/flakes/integrator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace snow {
namespace {

/// A simulation with one flake at `p` moving at `v` with drag c = k/m, no emitter.
struct OneFlake {
    Simulation sim;
    explicit OneFlake(const SimConfig& cfg, float c, glm::vec3 p = {0, 5, 0}, glm::vec3 v = {})
        : sim(cfg) {
        EXPECT_EQ(sim.place_flake({p, v, c, 0.01f, 1}), 0u);
    }
    [[nodiscard]] glm::vec3 vel() const {
        const FlakePool& f = flake_pool(sim);
        return {f.vx[0], f.vy[0], f.vz[0]};
    }
};

SimConfig tall_box(Integrator i, float dt) {
    SimConfig c;
    c.integrator = i;
    c.dt = dt;
    c.bounds = {{-1e6f, -1e6f, -1e6f}, {1e6f, 1e6f, 1e6f}};
    c.max_flakes = 4;
    return c;
}

TEST(Integrate, EveryRuleReachesTerminalVelocityTowardsWind) {
    for (const Integrator i : {Integrator::explicit_euler, Integrator::semi_implicit_euler,
                               Integrator::exponential, Integrator::rk4, Integrator::automatic}) {
        OneFlake one(tall_box(i, 1.0f / 60.0f), 9.81f); // terminal fall speed 1 m/s
        Wind still_base;
        still_base.base = still_base.current = {3.0f, 0.0f, 0.0f};
        still_base.walk = 0.0f;
        one.sim.set_wind(still_base);
        one.sim.run(600);
        const glm::vec3 v = one.vel();
        EXPECT_NEAR(v.x, 3.0f, 1e-3f) << integrator_name(i);
        EXPECT_NEAR(v.y, -1.0f, 1e-3f) << integrator_name(i);
        EXPECT_EQ(one.sim.counters().stiff_flake_ticks, 0u) << integrator_name(i);
    }
}

TEST(Integrate, ExplicitEulerMatchesSeedFormula) {
    // One step by hand: v += (g + c(w − v))·dt, then p += v·dt ([ZCL eqs. 1–3]).
    OneFlake one(tall_box(Integrator::explicit_euler, 0.1f), 2.0f, {0, 5, 0}, {0, 0, 0});
    one.sim.tick();
    const float v = 0.0f + (-9.81f + 2.0f * (0.0f - 0.0f)) * 0.1f;
    EXPECT_FLOAT_EQ(flake_pool(one.sim).vy[0], v);
    EXPECT_FLOAT_EQ(flake_pool(one.sim).py[0], 5.0f + v * 0.1f);
}

TEST(Integrate, StiffFlakesAreGuardedAndCounted) {
    // c·dt = 50: explicit Euler alone would give NaN within a few hundred steps.
    OneFlake one(tall_box(Integrator::explicit_euler, 0.25f), 200.0f, {0, 5, 0}, {5, 0, 0});
    float prev_vy = 0.0f;
    for (int t = 0; t < 200; ++t) {
        one.sim.tick();
        const float vy = one.vel().y;
        ASSERT_TRUE(std::isfinite(vy));
        if (t > 0) {
            EXPECT_NEAR(vy, prev_vy, 1e-6f); // at terminal velocity: no oscillation
        }
        prev_vy = vy;
    }
    EXPECT_NEAR(one.vel().y, -9.81f / 200.0f, 1e-5f);
    EXPECT_NEAR(one.vel().x, 0.0f, 1e-6f);
    EXPECT_EQ(one.sim.counters().stiff_flake_ticks, 200u);
}

TEST(Integrate, ExponentialIsExactForConstantWind) {
    const float c = 3.0f, dt = 0.05f;
    OneFlake one(tall_box(Integrator::exponential, dt), c, {0, 100, 0}, {0, 2, 0});
    one.sim.run(40);
    double p = 0, v = 0;
    integrate::exact_at(p, v, 100.0, 2.0, c, -9.81, 0.0, 40 * dt);
    EXPECT_NEAR(flake_pool(one.sim).py[0], p, 1e-4);
    EXPECT_NEAR(flake_pool(one.sim).vy[0], v, 1e-5);
}

TEST(Integrate, Rk4IsFarMoreAccurateThanEuler) {
    const float c = 4.0f, dt = 1.0f / 15.0f;
    double p = 0, v = 0;
    integrate::exact_at(p, v, 100.0, 0.0, c, -9.81, 0.0, 30 * dt);
    double err[2];
    int k = 0;
    for (const Integrator i : {Integrator::explicit_euler, Integrator::rk4}) {
        OneFlake one(tall_box(i, dt), c, {0, 100, 0}, {0, 0, 0});
        one.sim.run(30);
        err[k++] = std::abs(flake_pool(one.sim).py[0] - p);
    }
    EXPECT_LT(err[1] * 100.0, err[0]);
}

} // namespace
} // namespace snow
