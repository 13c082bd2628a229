/// @file render_settings.hpp
/// @brief Renderer knobs; the defaults suit the project's scenes.
#pragma once

#include "systems/sky/occlusion.hpp"

#include <glm/vec3.hpp>

#include <cstdint>

namespace snow {

/// When distant flakes are thinned (level of detail).
enum class FlakeLod : std::uint8_t {
    automatic, ///< only on a software rasteriser (llvmpipe, softpipe)
    always,
    never,
};

struct RenderSettings {
    glm::vec3 snow_color{0.94f, 0.96f, 1.0f};
    /// How white exposed, sky-facing meshes get, 0..1 ([SKY] snow blend).
    float mesh_snow = 1.0f;
    /// A fragment counts as seen from the sky if y >= occlusion top_y − this (m).
    float exposure_tolerance = occlusion_tolerance;
    /// Snow cover thinner than this (m) is not drawn; the bare top shows.
    float min_snow_depth = 0.002f;
    /// Level of detail of snow surfaces: a tile samples every 2^l-th cell, the
    /// coarsest level whose samples lie at most this many pixels apart ...
    float surface_spacing_px = 4.0f;
    /// ... widened (by √2 steps) until a surface draws at most this many
    /// heightfield samples per frame (llvmpipe is bound by its triangles).
    std::uint32_t surface_samples = 20000;
    /// Falloff k of point lights: intensity / (1 + k·d²), d in metres.
    float light_falloff = 0.01f;

    /// Sprites are drawn this many times the flake's physical diameter.
    float flake_scale = 3.0f;
    float flake_min_px = 1.5f; ///< smaller sprites are enlarged and made fainter
    float flake_max_px = 48.0f;
    float flake_alpha = 0.9f;
    /// Flake alpha is multiplied by e^(−d / fade): far flakes are fainter [SKY].
    float flake_fade_distance = 40.0f;
    FlakeLod flake_lod = FlakeLod::automatic;
    /// Beyond this distance (m) only a fraction (lod_distance / d)² of flakes is drawn.
    float lod_distance = 12.0f;

    /// Draw the world's wind field (if it has one) as arrows coloured by speed.
    bool show_wind_field = false;

    /// glFinish after each pass so per-pass times include GPU work (slower).
    bool timing_mode = false;
};

} // namespace snow
