/// @file snow_mesh.hpp
/// @brief The settled snow of one surface as a closed-looking triangle mesh
/// for export: the snow top over every cell that holds snow, with skirts down
/// to the bare base wherever the snow ends (a bare or void neighbour, the
/// grid's border, a drop of a cover's base).
#pragma once

#include "systems/snowpack/snow_surface.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace snow {

/// World-space triangles (counter-clockwise seen from outside), unit normals.
struct SnowMesh {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<std::uint32_t> indices;
    [[nodiscard]] bool empty() const { return indices.empty(); }
};

/// Cells without snow and void cells are left out. The top is smooth within
/// each patch of cells joined by open edges (corner heights average the
/// patch's cells around the corner) and never across a closed edge, so a
/// roof's snow does not smear down to the ground below its eaves.
[[nodiscard]] SnowMesh build_snow_mesh(const SnowSurface& s);

} // namespace snow
