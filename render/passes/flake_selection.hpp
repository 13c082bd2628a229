/// @file flake_selection.hpp
/// @brief Which flakes a frame draws: alive, inside the view frustum and, with
/// level of detail, a stable fraction of the distant ones. CPU only.
#pragma once

#include "systems/flakes/flake_pool.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace snow {

/// How flakes are selected for drawing.
struct FlakeSelection {
    glm::mat4 view_proj{1.0f};
    glm::vec3 eye{0.0f};
    float size_scale = 1.0f;
    bool lod = false;
    float lod_distance = 0.0f;
};

/// Writes (x, y, z, drawn diameter) of each alive flake inside the view frustum
/// into `out` (4 floats each, out.size() ≥ 4 × pool capacity), slot order;
/// what follows the returned count is scratch.
/// With lod, a flake at distance d > lod_distance is kept only when its slot's
/// fixed hash falls under (lod_distance / d)², so thinning never flickers.
/// Returns the number written. Exposed for tests and benchmarks.
[[nodiscard]] std::uint32_t select_flakes(const FlakePool& pool, const FlakeSelection& sel,
                                          std::vector<float>& out);

} // namespace snow
