/// @file fence_drift.hpp
/// @brief Snow blowing at a fence: a fetch of fresh snow upwind, bare ground
/// round a fence of height H across the wind, a steady wind through a field
/// that lets air through the fence by its porosity [Wil85], in a 1 m slice
/// of a long fence (the field is a tunnel: its sides are walls the air slides
/// along). What the tests hold to: a porous fence slows the air in its lee,
/// and over hours of drifting (fast-forwarded) grows drifts on both sides of
/// it; with no fence the snow passes (docs/wind_field.md "Porous fences").
#pragma once

#include <vector>

namespace snow {

/// One run. The fence stands at x = 0 across the whole width; the fetch,
/// `fetch` H long, starts `upwind` − 1 H upwind of it; the ground reaches
/// from `upwind` H upwind to `downwind` H downwind.
struct FenceDrift {
    float porosity = 0.5f;     ///< the fence's open share; 1 = no fence
    float wind = 8.0f;         ///< the free wind along +x (m/s)
    float seconds = 60.0f;     ///< how long the snow blows, after the air settles
    float upwind = 16.0f;      ///< H
    float downwind = 24.0f;    ///< H
    float fetch = 9.0f;        ///< H of snow, from `upwind` − 1 H downwind
    float fast_forward = 1.0f; ///< WindTransportDef::fast_forward
    /// The fetch is topped up to its depth before every field step, as a
    /// long snow field upwind would feed the wind: the run can reach an
    /// equilibrium.
    bool endless_fetch = false;
    /// Seconds (after the air settled) at which the drifts' shape is taken.
    std::vector<float> shape_at;
};

/// Drifts' shape at one time, in fence heights: where the snow stands at
/// least 2 cm (H/50) above where it stood, from the fence out.
struct DriftShape {
    float seconds = 0.0f;
    double lee_length = 0.0, lee_depth = 0.0;           ///< behind the fence
    double windward_length = 0.0, windward_depth = 0.0; ///< before it, to the fetch
};

/// What a run gives; distances in fence heights H (1 m), masses per metre
/// of width.
struct FenceDriftResult {
    /// Mean wind along x half a height above the ground, 2 H to 6 H behind
    /// the fence, over the same upwind of the fence at −10 H.
    double lee_wind_over_free = 0.0;
    /// Snow gained (kg/m) from the fence to 15 H behind it, and from 5 H
    /// upwind of it to the fence.
    double lee_gain = 0.0;
    double windward_gain = 0.0;
    /// Snow the fetch lost (kg/m), top-ups included: what the wind carried in all.
    double fetch_loss = 0.0;
    bool balanced = true;           ///< the ledger held every tick
    std::vector<DriftShape> shapes; ///< one per FenceDrift::shape_at
};

/// A run towards Tabler's drifts [Tab80]: 10 m/s over an endless fetch 70 H
/// long, the ground 100 H upwind to 45 H downwind, the drifting 5000 times
/// as fast as the air (WindTransportDef::fast_forward), `seconds` long.
[[nodiscard]] FenceDrift towards_equilibrium(float seconds);

[[nodiscard]] FenceDriftResult fence_drift(const FenceDrift& run);

} // namespace snow
