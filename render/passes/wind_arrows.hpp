/// @file wind_arrows.hpp
/// @brief A picture of a wind field (docs/wind_field.md) as line segments:
/// arrows on a coarse lattice over the field, as long and as red as the air
/// there is fast. Reads the field only; the wind-field pass draws it.
#pragma once

#include "systems/wind/wind_field.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace snow {

/// Arrows across x and z, and layers up y, at most: 16 × 4 × 16 arrows of
/// three segments each (shaft and two head strokes), 3 072 segments at most.
inline constexpr std::uint32_t wind_arrows_across = 16;
inline constexpr std::uint32_t wind_arrow_layers = 4;
inline constexpr std::uint32_t wind_arrow_segments = 3;

struct WindArrows {
    /// Per vertex x, y, z, r, g, b; two vertices per segment.
    std::vector<float> vertices;
    std::uint32_t arrows = 0;
    float max_speed = 0.0f; ///< m/s of the longest, reddest arrow
};

/// Colour of a speed as a share of the fastest (0..1): blue, green, yellow, red.
[[nodiscard]] glm::vec3 wind_speed_color(float share);

/// Arrows at the cell centres of an evenly spread lattice of at most
/// wind_arrows_across × wind_arrow_layers × wind_arrows_across cells, each
/// along the field's wind there, the fastest 0.9 lattice spacings long;
/// still air (below 1 % of the fastest, as inside obstacles) gets none.
/// Replaces `out`'s contents (its storage is reused).
void wind_arrows(const WindField& f, WindArrows& out);

} // namespace snow
