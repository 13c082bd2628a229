/// @file integrator.hpp
/// @brief One-axis update rules for gravity + linear drag towards the wind:
/// dv/dt = g + c·(w − v), dp/dt = v, with c = k/m ([WF §3]; note the paper
/// prints k(v − v_wind), whose sign would accelerate flakes, so we use k(w − v)).
/// The axes are independent, so a flake is three calls. All inline and
/// branch-free so the SoA loops vectorise; the same functions serve the
/// integrate system, the accuracy benchmark and the tests.
#pragma once

#include <cmath>

namespace snow::integrate {

/// Explicit Euler as in [ZCL eqs. 1–3]: v += a·dt, then p += v·dt.
/// Oscillates for c·dt > 1 and diverges past 2 (docs/design.md "Numerical stability").
inline void explicit_euler(float& p, float& v, float c, float g, float w, float dt) {
    const float a = g + c * (w - v);
    v = v + a * dt;
    p = p + v * dt;
}

/// Drag taken implicitly (Box2D-style damping): never overshoots the wind.
inline void semi_implicit_euler(float& p, float& v, float c, float g, float w, float dt) {
    v = (v + dt * (g + c * w)) / (1.0f + c * dt);
    p = p + v * dt;
}

/// Exact solution over one step for constant g and w:
/// v → v_t + (v − v_t)·e^(−c·dt), v_t = w + g/c; p integrates that exactly.
/// c = 0 has its own branch (free fall).
inline void exponential(float& p, float& v, float c, float g, float w, float dt) {
    if (c <= 0.0f) {
        p = p + v * dt + 0.5f * g * dt * dt;
        v = v + g * dt;
        return;
    }
    const float vt = w + g / c;
    const float decay = std::exp(-c * dt);
    const float gap = v - vt;
    p = p + vt * dt + gap * (1.0f - decay) / c;
    v = vt + gap * decay;
}

/// Classical RK4 on (p, v); stable for c·dt below about 2.78.
inline void rk4(float& p, float& v, float c, float g, float w, float dt) {
    const auto acc = [&](float vel) { return g + c * (w - vel); };
    const float h = 0.5f * dt;
    const float v1 = v, a1 = acc(v1);
    const float v2 = v + h * a1, a2 = acc(v2);
    const float v3 = v + h * a2, a3 = acc(v3);
    const float v4 = v + dt * a3, a4 = acc(v4);
    p = p + (dt / 6.0f) * (v1 + 2.0f * v2 + 2.0f * v3 + v4);
    v = v + (dt / 6.0f) * (a1 + 2.0f * a2 + 2.0f * a3 + a4);
}

/// Largest c·dt each rule takes without a guard; beyond it a flake is
/// switched to the exact update (explicit Euler: no oscillation past 1).
inline constexpr float explicit_limit = 1.0f;
inline constexpr float rk4_limit = 2.5f;
inline constexpr float automatic_limit = 0.5f;

/// Closed-form state at time t from (p0, v0): the reference for accuracy.
inline void exact_at(double& p, double& v, double p0, double v0, double c, double g, double w,
                     double t) {
    if (c <= 0.0) {
        p = p0 + v0 * t + 0.5 * g * t * t;
        v = v0 + g * t;
        return;
    }
    const double vt = w + g / c;
    const double decay = std::exp(-c * t);
    p = p0 + vt * t + (v0 - vt) * (1.0 - decay) / c;
    v = vt + (v0 - vt) * decay;
}

} // namespace snow::integrate
