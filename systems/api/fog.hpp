/// @file fog.hpp
/// @brief Fog settings ([PE], [SKY]). Declared by a scene or absent;
/// absent means no fog code is compiled or run.
#pragma once

#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace snow {

enum class FogMode : std::uint8_t {
    exponential, ///< e^(−density·z), [SKY]
    half_life,   ///< 0.5^(d/D), [PE]
    layered,     ///< ∫ density(y) via table E(y), [PE]
};

/// A Gaussian (or Gabor, when frequency > 0) fog puff, [PE].
struct FogPuff {
    glm::vec3 center{0.0f};
    float sigma = 1.0f;
    float density = 0.5f;
    glm::vec3 frequency{0.0f}; ///< Gabor wave vector (rad/m); zero = plain Gaussian
    float phase = 0.0f;
};

/// World resource.
struct Fog {
    FogMode mode = FogMode::exponential;
    glm::vec3 color{0.75f, 0.78f, 0.82f};
    float density = 0.04f;       ///< exponential: 1/m
    float half_distance = 30.0f; ///< half_life: D (m)
    float layer_bottom = 0.0f;   ///< layered: density is zero below ..
    float layer_top = 3.0f;      ///< .. and above
    float layer_density = 0.15f; ///< layered: peak density (1/m)
    std::vector<FogPuff> puffs;
};

/// `fog.*` (the mode is a choice; puffs have their own table; layer_bottom
/// <= layer_top is checked by validate()).
inline constexpr FieldRule<Fog> fog_fields[] = {
    {"color", &Fog::color},
    {"density", &Fog::density, non_negative},
    {"half_distance", &Fog::half_distance, positive},
    {"layer_bottom", &Fog::layer_bottom},
    {"layer_top", &Fog::layer_top},
    {"layer_density", &Fog::layer_density, non_negative},
};
/// `fog.puffs[i].*`.
inline constexpr FieldRule<FogPuff> fog_puff_fields[] = {
    {"center", &FogPuff::center},
    {"sigma", &FogPuff::sigma, positive},
    {"density", &FogPuff::density, non_negative},
    {"frequency", &FogPuff::frequency},
    {"phase", &FogPuff::phase},
};

[[nodiscard]] Invalid validate(const Fog& f);

} // namespace snow
