/// @file surface_tiles.hpp
/// @brief The CPU half of drawing a SnowSurface as a tiled, displaced
/// heightfield [WF §6]: which tiles changed since the last frame (a
/// per-tile checksum, since the simulation clears its own dirty marks every
/// tick), their height ranges for culling, the texels to upload, and each
/// visible tile's level of detail. Reads the surface, never writes it.
#pragma once

#include "systems/snowpack/snow_surface.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace snow {

/// Cells per side of a drawn tile.
inline constexpr std::uint32_t surface_tile_cells = 32;
/// Levels of detail: a level-l tile samples every 2^l-th cell (1 … 32).
inline constexpr std::uint32_t surface_tile_levels = 6;

/// Vertices per side of a level-l patch.
[[nodiscard]] constexpr std::uint32_t patch_side(std::uint32_t level) {
    return (surface_tile_cells >> level) + 1;
}

/// Skirt bits of a patch: which of its edges hang a skirt.
inline constexpr std::uint32_t skirt_low_x = 1;
inline constexpr std::uint32_t skirt_high_x = 2;
inline constexpr std::uint32_t skirt_low_z = 4;
inline constexpr std::uint32_t skirt_high_z = 8;
inline constexpr std::uint32_t skirt_all = 15;

/// Vertex ids of a patch, for the vertex shader: id < side² is the grid
/// sample (id % side, id / side); side² + id its copy hung a little below the
/// bare top (tile seams, and exactly to it on the grid's border); 2·side² + id
/// its copy hung to the bare top (the cut at an edge of the bare top).
inline constexpr std::uint32_t patch_copies = 3;

/// Index list of a level-l patch drawn from vertex ids alone: the grid as
/// triangles counter-clockwise from +y, then a skirt on each tile edge in
/// `skirts`: every segment joined to its hanging copies. Exposed for tests.
[[nodiscard]] std::vector<std::uint32_t> patch_indices(std::uint32_t level, std::uint32_t skirts);

/// Level for a tile whose nearest point is `distance` metres away: the
/// coarsest whose sample spacing still projects to at most `spacing_px`
/// (px_per_metre: pixels one metre covers at 1 m).
[[nodiscard]] std::uint32_t patch_level(float distance, float cell, float px_per_metre,
                                        float spacing_px);

/// How the tiles of one frame are chosen.
struct TileView {
    glm::mat4 view_proj{1.0f};
    glm::vec3 eye{0.0f};
    float px_per_metre = 1.0f;               ///< viewport height / (2 tan(fov/2))
    float spacing_px = 4.0f;                 ///< RenderSettings::surface_spacing_px
    std::uint32_t max_samples = 0xFFFFFFFFu; ///< RenderSettings::surface_samples
};

/// One tile to draw.
struct TileDraw {
    glm::ivec2 first{0}; ///< its first cell (x, z)
    std::uint32_t level = 0;
    /// Edges that need a skirt: on the grid's border, or where the tile
    /// across is drawn at another level (the cracks of level changes).
    std::uint32_t skirts = 0;
    /// The bare top jumps like an edge (eaves) somewhere in the tile: its
    /// fragments are cut to the snow slab of their column.
    bool edges = false;
    float distance = 0.0f; ///< from the eye to the tile's nearest point (m)

    [[nodiscard]] bool same_draw(const TileDraw& o) const {
        return level == o.level && skirts == o.skirts && edges == o.edges;
    }
};

/// A bare top rising faster than this (m per m) from a cell to the next is an
/// edge, not a slope (eaves, a box's rim, a sphere's side); surface.vert uses
/// the same constant.
inline constexpr float surface_edge_slope = 2.0f;

/// Per-surface tile bookkeeping of the renderer.
class SurfaceTiles {
  public:
    /// Rescans the surface: returns the tiles (index tz · tiles_x + tx) whose
    /// cells changed since the last call; every tile on the first call and
    /// whenever the grid itself (size, origin, cell, unit height) changed.
    const std::vector<std::uint32_t>& rescan(const SnowSurface& s);
    /// True when the last rescan saw a new grid (the texture must be remade).
    [[nodiscard]] bool grid_changed() const { return grid_changed_; }
    [[nodiscard]] std::uint32_t tiles_x() const { return tiles_x_; }
    [[nodiscard]] std::uint32_t tiles_z() const { return tiles_z_; }
    /// Lowest bare top and highest snow top (m) of the cells with snow that a
    /// tile's samples span (its own, the first of its +x, +z neighbours), as
    /// last scanned; empty (x > y) when none has snow: the tile is not drawn.
    [[nodiscard]] glm::vec2 height_range(std::uint32_t tile) const { return range_[tile]; }

    /// True when the bare top jumps like an edge inside the tile or toward
    /// the first cells of its +x, +z neighbours (which its samples reach).
    [[nodiscard]] bool has_edges(std::uint32_t tile) const { return edges_[tile] != 0; }
    /// Grows whenever what the tile's edge_patch_indices depend on changed
    /// (its cells or the first cells of its +x, +z neighbours); restarts on a
    /// new grid.
    [[nodiscard]] std::uint32_t version(std::uint32_t tile) const { return version_[tile]; }

    /// Every tile with snow inside the view frustum, sorted so that tiles
    /// drawn alike (TileDraw::same_draw) are adjacent, each run near to far
    /// (the early depth test then skips what nearer snow hides). Levels come
    /// from the distance at view.spacing_px, widened by √2 until the grid
    /// samples of all tiles fit view.max_samples (or at most 32 times).
    /// Returns the grid samples drawn.
    std::uint64_t select(const SnowSurface& s, const TileView& view, std::vector<TileDraw>& out);

  private:
    std::uint64_t grid_ = 0;
    bool grid_changed_ = false;
    std::uint32_t tiles_x_ = 0, tiles_z_ = 0;
    std::vector<std::uint64_t> checksum_;
    std::vector<glm::vec2> range_;
    std::vector<std::uint8_t> edges_;
    std::vector<std::uint32_t> version_;
    std::vector<std::uint32_t> changed_;
    std::vector<std::int32_t> level_; ///< select(): per tile, its level or −1 (not drawn)
    std::vector<float> distance_;     ///< select(): per tile, its distance or −1 (not drawn)
};

/// Index list of a tile with edges (TileDraw::edges): patch_indices, less the
/// quads whose corners' bare tops jump like an edge (a curtain from eaves down
/// to the ground) or carry no snow at all; the sides of a left-out quad that do
/// not jump hang a skirt to the bare top, so the snow ends in a clean cut.
void edge_patch_indices(const SnowSurface& s, const TileDraw& d, std::vector<std::uint32_t>& out);

/// Texels of tile `tile` (index tz · tiles_x + tx): (snow top, bare top) in
/// metres per cell, row-major over the tile's cells inside the grid. Returns
/// the tile's size in cells.
glm::uvec2 tile_texels(const SnowSurface& s, std::uint32_t tile, std::vector<float>& out);

} // namespace snow
