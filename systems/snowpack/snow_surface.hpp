/// @file snow_surface.hpp
/// @brief A heightfield of settled snow over the top of an object ([WF §1],
/// [ZCL §IV]). Several may exist per object; cells count whole mass units.
#pragma once

#include "ecs/entity.hpp"
#include "ecs/host_memory.hpp"
#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"
#include "systems/core/units.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <snow/defs.hpp>
#include <snow/views.hpp>

namespace snow {

/// Dirty cells are tracked per tile of 2^dirty_tile_shift cells on a side,
/// so redistribution works where snow changed, whatever the surface's size.
inline constexpr std::uint32_t dirty_tile_shift = 3;

/// Inclusive cell box, in surface coordinates; empty when x0 > x1.
struct CellBox {
    std::uint32_t x0 = 1, z0 = 1, x1 = 0, z1 = 0;
    [[nodiscard]] bool empty() const { return x0 > x1 || z0 > z1; }
    /// How many cells the box holds (it must not be empty).
    [[nodiscard]] std::size_t cells() const {
        return static_cast<std::size_t>(x1 - x0 + 1) * (z1 - z0 + 1);
    }
    void include(std::uint32_t x, std::uint32_t z) {
        if (empty()) {
            *this = {x, z, x, z};
            return;
        }
        x0 = x < x0 ? x : x0;
        x1 = x > x1 ? x : x1;
        z0 = z < z0 ? z : z0;
        z1 = z > z1 ? z : z1;
    }
    void include(const CellBox& b) {
        if (!b.empty()) {
            include(b.x0, b.z0);
            include(b.x1, b.z1);
        }
    }
    /// This box grown by one cell on every side, clipped to an nx × nz grid.
    [[nodiscard]] CellBox grown(std::uint32_t nx, std::uint32_t nz) const {
        return {x0 > 0 ? x0 - 1 : 0, z0 > 0 ? z0 - 1 : 0, x1 + 1 < nx ? x1 + 1 : nx - 1,
                z1 + 1 < nz ? z1 + 1 : nz - 1};
    }
};

/// Base level of a cell with nothing under it (a cover's column that lies
/// outside all geometry or under a declared surface): it never catches a
/// flake and its edges are closed, so no snow ever reaches it.
inline constexpr std::int64_t void_level = no_ground_level;

/// How many times denser than fresh snow (SimConfig::air_temperature) the
/// most packed snow is: what bodies, settling and the wind pack at most. Six:
/// fresh snow is at least 68 kg/m³ [HP98], so wind-packed snow (350–400,
/// [CP10]) and a snowball's 400 kg/m³ fit at any air temperature.
inline constexpr std::uint32_t max_packing = 6;

/// The most levels compaction may take off `units` of snow: packed to
/// max_packing times fresh density they still stand ceil(units / max_packing) levels.
[[nodiscard]] constexpr std::uint32_t max_compaction(std::uint32_t units) {
    return units - (units / max_packing + (units % max_packing != 0 ? 1 : 0));
}

/// Bits of SnowSurface::closed: edge towards -x, +x, -z, +z.
inline constexpr std::uint8_t closed_all = 0xF;

/// Component. Heights are compared as integer "levels" in units of
/// `unit_height`, so rolling and smoothing are exact and order-free.
struct SnowSurface {
    float x0 = 0.0f, z0 = 0.0f, cell = 0.05f;
    std::uint32_t nx = 0, nz = 0;
    /// Metres one unit of fresh snow adds to a cell: a level is the volume
    /// of one unit at the run's fresh density, so (snow, depth_levels) is a
    /// cell's exact mass and volume and its density is their ratio.
    float unit_height = 0.0f;
    Vector<std::int64_t> base_level; ///< bare top per cell, in unit_height steps
    /// Every base_level is the same (a level rectangle), so levels differ by
    /// their snow alone; false: they may differ (a slope, a cover's base).
    bool uniform_base = false;
    Vector<std::uint32_t> snow; ///< settled units per cell (row-major, x fastest)
    /// Per cell, the levels by which packed or settled snow stands lower than
    /// its units would at fresh density (docs/cover_and_bodies.md
    /// "Compaction", "Settling"): its mean density is the fresh density ·
    /// snow / depth_levels. Sized by make_surface (a surface built by hand:
    /// empty until a body or settling first compacts snow here). At most
    /// max_compaction(snow[i]); snow falling on it keeps the packed layer, so
    /// the mean is the exact mix of the two.
    Vector<std::uint32_t> compacted;
    std::uint32_t edge_limit_units = 0;
    std::int64_t laplacian_limit_units = 0; ///< cap on 4h - Σ neighbours, in units
    /// Largest stable height step (levels) to a neighbour, the angle of
    /// repose over one cell (SurfaceDef::repose_deg): steeper snow slides
    /// down. 0 = no such rule (only surfaces built by hand in tests).
    std::int64_t talus_units = 0;
    /// A line down the slope slides when its mean load M (kg/m² of plan)
    /// gives M·g·slide_drive > slide_adhesion (Pa): slide_drive is
    /// cos α·(sin α − μ·cos α) for pitch α and friction μ, <= 0 (never)
    /// where friction alone holds the snow or the surface does not spill.
    float slide_drive = 0.0f;
    float slide_adhesion = 0.0f;
    bool slide_along_x = true; ///< the lines run along x (else z) ...
    bool slide_to_high = true; ///< ... to their last cell (else their first): the low edge
    bool spills = true;
    /// Per cell, the edges no snow crosses (closed_all bits): a cover closes
    /// the edges at drops of its base and around void cells. Empty for a
    /// plain rectangle, whose cells are all open to each other.
    Vector<std::uint8_t> closed;
    /// Bumped whenever base_level changes (a cover following its geometry).
    std::uint64_t base_version = 0;
    // Dirty rectangle (inclusive cell bounds): the bounding box of every cell
    // waiting for redistribution; empty when lo > hi.
    std::uint32_t dirty_x0 = 1, dirty_z0 = 1, dirty_x1 = 0, dirty_z1 = 0;
    /// Per tile (row-major, tiles_x() per row): the cells of it waiting for
    /// redistribution. Sized by make_surface (or the first mark_dirty).
    Vector<CellBox> tile_dirty;
    /// The tiles whose tile_dirty box is not empty, in the order first marked.
    Vector<std::uint32_t> dirty_tiles;
    /// Upper bound of every cell's level, raised by mark_dirty(); lets deposit
    /// skip flakes far above the surface. Whoever changes `snow` calls mark_dirty.
    std::int64_t level_bound = 0;

    [[nodiscard]] std::size_t cell_count() const { return snow.size(); }
    [[nodiscard]] std::size_t index(std::uint32_t ix, std::uint32_t iz) const {
        return static_cast<std::size_t>(iz) * nx + ix;
    }
    /// Height of cell i's snow in levels: its units at fresh density less
    /// what compaction took off. Every height of the snow comes from here.
    [[nodiscard]] std::int64_t depth_levels(std::size_t i) const {
        return std::int64_t{snow[i]} - (compacted.empty() ? 0 : std::int64_t{compacted[i]});
    }
    /// Level of cell i's snow top.
    [[nodiscard]] std::int64_t level(std::size_t i) const {
        return base_level[i] + depth_levels(i);
    }
    /// World height (m) of a level, rounded once from double (as every user of
    /// heights compares them).
    [[nodiscard]] float height(std::int64_t lvl) const { return level_height(lvl, unit_height); }
    /// World height (m) of the snow top of cell i.
    [[nodiscard]] float top_y(std::size_t i) const { return height(level(i)); }
    /// Snow depth (m) of cell i.
    [[nodiscard]] float depth(std::size_t i) const { return height(depth_levels(i)); }
    /// Lowers cell i's snow by `levels` without moving a unit (a body packs
    /// it); `levels` <= max_compaction(snow[i]) - compacted[i].
    void compact(std::size_t i, std::uint32_t levels);
    /// After units left cell i: it keeps no more compaction than its units can
    /// hold (what was taken came off the top, fresh snow first).
    void fit_compaction(std::size_t i) {
        if (!compacted.empty()) {
            compacted[i] = std::min(compacted[i], max_compaction(snow[i]));
        }
    }
    /// Cell under world (x, z); false when outside the grid.
    [[nodiscard]] bool cell_at(float x, float z, std::uint32_t& ix, std::uint32_t& iz) const;
    /// Records that cell (ix, iz) changed: grows its tile's dirty box, the
    /// dirty rectangle and level_bound.
    void mark_dirty(std::uint32_t ix, std::uint32_t iz);
    /// The same for cell index i.
    void mark_dirty(std::size_t i) {
        mark_dirty(static_cast<std::uint32_t>(i % nx), static_cast<std::uint32_t>(i / nx));
    }
    /// Forgets every dirty cell (redistribution took them over).
    void clear_dirty();
    [[nodiscard]] std::uint32_t tiles_x() const {
        return (nx + (1u << dirty_tile_shift) - 1) >> dirty_tile_shift;
    }
    [[nodiscard]] std::uint32_t tiles_z() const {
        return (nz + (1u << dirty_tile_shift) - 1) >> dirty_tile_shift;
    }
    /// The dirty tile holding cell (ix, iz).
    [[nodiscard]] std::uint32_t tile_of(std::uint32_t ix, std::uint32_t iz) const {
        return (iz >> dirty_tile_shift) * tiles_x() + (ix >> dirty_tile_shift);
    }
    /// True when no cell waits for redistribution.
    [[nodiscard]] bool dirty_empty() const { return dirty_x0 > dirty_x1 || dirty_z0 > dirty_z1; }
    /// Indices of the existing 4-neighbours of (ix, iz), in the order -x, +x, -z, +z
    /// (cells off the grid are left out); returns how many were written.
    /// Closed edges (SnowSurface::closed) are left out too.
    std::uint32_t neighbours(std::uint32_t ix, std::uint32_t iz, std::size_t (&out)[4]) const {
        const std::size_t i = index(ix, iz);
        const std::uint8_t shut = closed.empty() ? 0 : closed[i];
        std::uint32_t n = 0;
        if (ix > 0 && (shut & 1u) == 0) {
            out[n++] = i - 1;
        }
        if (ix + 1 < nx && (shut & 2u) == 0) {
            out[n++] = i + 1;
        }
        if (iz > 0 && (shut & 4u) == 0) {
            out[n++] = i - nx;
        }
        if (iz + 1 < nz && (shut & 8u) == 0) {
            out[n++] = i + nx;
        }
        return n;
    }
    /// No geometry under cell i: it holds no snow and catches nothing.
    [[nodiscard]] bool is_void(std::size_t i) const { return base_level[i] == void_level; }
    [[nodiscard]] std::uint64_t settled_units() const;
};

class ByteWriter;
class ByteReader;
class StateHasher;
/// A surface's snapshot record: what ticks change (its snow, compaction,
/// cells waiting for smoothing and, for a cover, its base); the placement
/// and settings are the scene's.
void save_state(ByteWriter& out, const SnowSurface& s);
/// Reads a record of save_state into `s`, the same surface as the scene
/// declares it (throws SimulationError naming what is wrong).
void load_state(ByteReader& in, SnowSurface& s);
/// What ticks change in a surface: its snow and its compaction, the cells
/// waiting for smoothing (they decide next tick's work) and the bound the
/// deposit's prefilter uses (a cover's base: its cover's hash_state).
void hash_state(StateHasher& h, const SnowSurface& s);

/// Component on a surface entity: the solid it lies on (null for the ground).

struct SurfaceOf {
    Entity owner;
};

/// Tag component on a solid (collider entity) that owns at least one surface.
struct SnowHolder {};

/// Builds a surface from a definition for snow that lands at `fresh_density`
/// (kg/m³, fresh_snow_density of the run's air temperature); throws
/// SimulationError naming the bad field for invalid values. Its grid has at
/// most max_surface_cells_per_side cells per side (limits.hpp).
[[nodiscard]] SnowSurface
make_surface(const SurfaceDef& def,
             double fresh_density = fresh_snow_density(SimConfig{}.air_temperature));

/// Corners of a surface's bare top as the plane through its corner cells (what
/// the occlusion map rasterises): (x0,z0), (x1,z0), (x1,z1), (x0,z1).
[[nodiscard]] std::array<glm::vec3, 4> surface_base_corners(const SnowSurface& s);

/// `surface.*`: a snow surface's grid and smoothing [WF §3].
inline constexpr FieldRule<SurfaceDef> surface_fields[] = {
    {"x0", &SurfaceDef::x0},
    {"z0", &SurfaceDef::z0},
    {"size_x", &SurfaceDef::size_x, positive},
    {"size_z", &SurfaceDef::size_z, positive},
    {"cell", &SurfaceDef::cell, positive},
    {"base_y", &SurfaceDef::base_y},
    {"slope_x", &SurfaceDef::slope_x},
    {"slope_z", &SurfaceDef::slope_z},
    {"edge_limit", &SurfaceDef::edge_limit, non_negative},
    {"spills", &SurfaceDef::spills},
    {"laplacian_limit", &SurfaceDef::laplacian_limit, positive},
    {"slide_friction", &SurfaceDef::slide_friction, non_negative},
    {"slide_adhesion", &SurfaceDef::slide_adhesion, non_negative},
    {"repose_deg", &SurfaceDef::repose_deg, positive_up_to(max_repose_deg)},
};

[[nodiscard]] Invalid validate(const SurfaceDef& def);

} // namespace snow
