/// @file quality.hpp
/// @brief Quality presets of snow_game: simulation overrides plus renderer
/// level of detail. The numbers come from docs/accuracy.md.
#pragma once

#include "game/scene_loader.hpp"
#include "render/render_settings.hpp"

#include <array>
#include <optional>
#include <string_view>

namespace snow {

struct QualityPreset {
    std::string_view name;
    float dt;              ///< simulation tick (s)
    float lod_distance;    ///< renderer: flakes beyond are thinned (m)
    FlakeLod lod;
};

inline constexpr std::array<QualityPreset, 3> quality_presets{{
    {"low", 1.0f / 30.0f, 8.0f, FlakeLod::always},
    {"medium", 1.0f / 60.0f, 12.0f, FlakeLod::automatic},
    {"high", 1.0f / 120.0f, 30.0f, FlakeLod::never},
}};

/// Index of the named preset, if it exists.
[[nodiscard]] std::optional<std::size_t> find_quality(std::string_view name);

} // namespace snow
