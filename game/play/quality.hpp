/// @file quality.hpp
/// @brief Quality presets of snow_game: simulation settings picked from the
/// accuracy study's Pareto front (docs/accuracy.md "Presets"), plus renderer
/// level of detail (not part of that study).
#pragma once

#include <snow/render.hpp>
#include <snow/scene.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace snow {

struct QualityPreset {
    std::string_view name;
    float dt;                           ///< simulation tick (s)
    Integrator integrator;              ///< cheapest whose drift stays under half a cell
    float cell_scale;                   ///< multiplies every surface's cell edge
    std::uint32_t occlusion_resolution; ///< sky-map texels per side
    float lod_distance;                 ///< renderer: flakes beyond are thinned (m)
    FlakeLod lod;
};

// From docs/accuracy.md (scripts/accuracy.sh, run of 2026-12-02 03:25 UTC):
// low, medium and high are the cheapest studied settings within 2, 1.5 and
// 1.2 times the depth field's sampling noise (low ticking at >= 30 Hz, the
// others at >= 60 Hz; low and medium with the scene's cells or coarser), each
// with the cheapest integrator whose drift stays under half a cell.
// Smoothing iterations are not set: the cap never bound in the study.
inline constexpr std::array<QualityPreset, 3> quality_presets{{
    {"low", 1.0f / 30.0f, Integrator::semi_implicit_euler, 2.0f, 128, 8.0f, FlakeLod::always},
    {"medium", 1.0f / 60.0f, Integrator::semi_implicit_euler, 1.0f, 256, 12.0f,
     FlakeLod::automatic},
    {"high", 1.0f / 60.0f, Integrator::semi_implicit_euler, 0.5f, 256, 30.0f, FlakeLod::never},
}};

/// Index of the named preset, if it exists.
[[nodiscard]] std::optional<std::size_t> find_quality(std::string_view name);

/// Fills the simulation overrides the user left unset with the preset's.
inline void apply_quality(const QualityPreset& q, SceneOverrides& o) {
    o.dt = o.dt.value_or(q.dt);
    o.integrator = o.integrator.value_or(q.integrator);
    o.cell_scale = o.cell_scale.value_or(q.cell_scale);
    o.occlusion_resolution = o.occlusion_resolution.value_or(q.occlusion_resolution);
}

} // namespace snow
