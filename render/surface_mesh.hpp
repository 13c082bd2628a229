/// @file surface_mesh.hpp
/// @brief A SnowSurface as a triangle mesh: heightfield over the cell corners
/// with normals from the depth field, plus an apron down to the bare top
/// [WF §6]. CPU only.
#pragma once

#include "systems/snow_surface.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace snow {

/// Floats per surface vertex: position (3), normal (3), snow depth (1).
inline constexpr std::size_t surface_vertex_floats = 7;

/// Fills `vertices` with the heightfield over the cell corners followed by the
/// apron, and (when `indices` is not null) the matching triangle list.
/// Corner heights average the adjacent cells; normals come from central
/// differences of those heights. Exposed for tests.
void build_surface_mesh(const SnowSurface& surface, std::vector<float>& vertices,
                        std::vector<std::uint32_t>* indices);

/// Cheap 64-bit fingerprint of what the surface mesh depends on (grid, snow).
[[nodiscard]] std::uint64_t surface_fingerprint(const SnowSurface& surface);

} // namespace snow
