/// @file collider_grid.hpp
/// @brief A uniform XZ grid over the simulation bounds that lists the box and
/// sphere colliders overlapping each cell, so a flake is tested only against
/// the colliders near it (the cell index [WF §8] proposes). Rebuilt from
/// the World whenever the solids or the surfaces change (source_versions.hpp);
/// it is a World resource so the cache lives and dies with its World.
#pragma once

#include "ecs/entity.hpp"
#include "ecs/host_memory.hpp"
#include "ecs/world.hpp"
#include "systems/core/source_versions.hpp"
#include "systems/geometry/geometry.hpp"

#include <cstdint>
#include <tuple>

namespace snow {

/// A box collider as the collision pass reads it.
struct GridBox {
    Aabb box;
    std::uint32_t entity = 0;     ///< Entity::bits of the collider
    std::uint32_t surf_begin = 0; ///< its surfaces: holder_surfaces[surf_begin, surf_end)
    std::uint32_t surf_end = 0;   ///< empty unless the entity has SnowHolder
};

/// A sphere collider as the collision pass reads it.
struct GridSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;
};

/// A mesh collider: only its identity and surfaces (its shape lives in the occlusion map).
struct GridMesh {
    std::uint32_t entity = 0;
    std::uint32_t surf_begin = 0;
    std::uint32_t surf_end = 0;
};

/// World resource. Cells are as fine as min_cell_size allows (at most
/// max_collider_cells_per_side per axis, limits.hpp). Cell lists are compressed rows: the items of
/// cell c are cell_items[cell_start[c], cell_start[c + 1]); an item is a box
/// index, or a sphere index with sphere_tag set. Spheres come first in each cell.
struct ColliderGrid {
    static constexpr std::uint32_t sphere_tag = 0x80000000u;
    static constexpr float min_cell_size = 0.25f; ///< m; smaller cells mark too many paths long

    bool built = false;
    std::uint64_t solids_version = 0;   ///< SourceVersions::solids it was built from
    std::uint64_t surfaces_version = 0; ///< SourceVersions::surfaces it was built from
    float x0 = 0.0f, z0 = 0.0f;
    float inv_cell_x = 1.0f, inv_cell_z = 1.0f;   ///< cells per metre
    float cell_size_x = 1.0f, cell_size_z = 1.0f; ///< m
    std::uint32_t nx = 1, nz = 1;
    Vector<std::uint32_t> cell_start; ///< nx·nz + 1 offsets
    Vector<std::uint32_t> cell_items;
    Vector<float> cell_top; ///< highest box/sphere top over the cell (-inf if none)
    /// Highest mesh top (triangles and mesh surfaces) over the cell or its 8
    /// neighbours.
    Vector<float> cell_mesh_reach;
    /// What the collision prefilter reads, two floats per cell c: at 2c the
    /// highest top a path that starts and ends in c can meet (the boxes and
    /// spheres over c, cell_mesh_reach[c]); at 2c + 1 the highest top of any
    /// collider over c or its 8 neighbours, for a path that moved less than a
    /// cell per tick but may have come from one of them. A flake whose path
    /// stays above the one that applies meets nothing.
    Vector<float> cell_reach;
    /// Per row of cells, the highest of cell_reach over it (row_tops()): a
    /// path that ends in the row meets nothing above this.
    Vector<float> row_reach;
    Vector<GridBox> boxes;
    Vector<GridSphere> spheres;
    Vector<GridMesh> meshes;        ///< sorted by entity bits (looked up from top_id)
    Vector<Entity> holder_surfaces; ///< surface entities, grouped by owner
    /// A rebuild's own buffers, kept (it runs inside a tick): (owner bits,
    /// creation order, surface) of every surface on a SnowHolder solid, the
    /// items per cell, and the mesh tops before and after dilation.
    using OwnedSurface = std::tuple<std::uint32_t, std::uint32_t, Entity>;
    Vector<OwnedSurface> owned;
    Vector<std::uint32_t> count;
    Vector<float> mesh_top, around;

    /// Cell column of world x, clamped into the grid (NaN gives 0).
    [[nodiscard]] std::uint32_t cell_x(float x) const {
        return clamp_cell((x - x0) * inv_cell_x, nx);
    }
    /// Cell row of world z, clamped into the grid (NaN gives 0).
    [[nodiscard]] std::uint32_t cell_z(float z) const {
        return clamp_cell((z - z0) * inv_cell_z, nz);
    }
    /// The mesh whose entity bits are `id`, or nullptr.
    [[nodiscard]] const GridMesh* find_mesh(std::uint32_t id) const;

  private:
    // Branch-free (selects only) so the collision pre-pass vectorises.
    [[nodiscard]] static std::uint32_t clamp_cell(float u, std::uint32_t n) {
        const float last = static_cast<float>(n - 1);
        u = u > 0.0f ? u : 0.0f; // NaN compares false: cell 0
        u = u < last ? u : last;
        return static_cast<std::uint32_t>(static_cast<std::int32_t>(u));
    }
};

/// `out[j]` = the highest of a reach table in ColliderGrid::cell_reach's
/// layout (two floats per cell) over row j's cells: one bound for a block of
/// flakes whose paths end within a few rows, read instead of a table entry
/// per flake.
void row_tops(const ColliderGrid& g, const Vector<float>& reach, Vector<float>& out);

/// Returns the World's ColliderGrid (created if missing), rebuilt first if
/// the solids or the surfaces changed since it was built (SimConfig::bounds
/// is fixed when the Simulation is made).
ColliderGrid& update_collider_grid(World& w);
/// Gives the World's ColliderGrid room for a rebuild from the colliders and
/// surfaces it holds now (a cheap count, no rebuild): the rebuild at the
/// next tick then allocates nothing.
void reserve_collider_grid(World& w);

} // namespace snow
