/// @file snow_cover.hpp
/// @brief A snow cover: a heightfield of snow over whatever geometry lies
/// under it. Its bare base in each column is the highest geometry seen from
/// above there (the sky map of [SKY]), so snow gains depth on meshes,
/// spheres, boxes and terrain without hand-declared rectangles.
#pragma once

#include "ecs/entity.hpp"
#include "ecs/host_memory.hpp"
#include "ecs/world.hpp"
#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"
#include "systems/core/source_versions.hpp"

#include <cstdint>

#include <snow/defs.hpp>

namespace snow {

struct SnowSurface;

/// Component beside the SnowSurface of a cover entity: what its base was
/// built from and the cells at drops, where spill looks.
struct SnowCover {
    float drop_limit = 0.15f;
    /// False until a rebuild took all of the base to the geometry (and again
    /// while one could not: the flake pool was full).
    bool built = false;
    /// The source versions the base was last built from; only solids and
    /// surfaces matter (a cover follows the geometry, not the camera).
    SourceVersions built_from;
    /// The base follows the current solids and surfaces.
    [[nodiscard]] bool current(const SourceVersions& now) const {
        return built && built_from.solids == now.solids && built_from.surfaces == now.surfaces;
    }
    /// Per cell, the highest geometry of the column (m); -inf where none.
    /// Kept so a void cell's neighbours know how far the ground drops.
    Vector<float> column_top;
    /// Cells (ascending) with a neighbour lower by more than drop_limit (or
    /// with no geometry at all): spill sheds their excess across that edge.
    Vector<std::uint32_t> edge_cells;
    /// Per edge cell, the direction its spill leaves by (0 -x, 1 +x, 2 -z, 3 +z).
    Vector<std::uint8_t> edge_side;
};

class ByteWriter;
class ByteReader;
/// A cover's snapshot record: what its base was built from, its column tops
/// and its drop cells (its snow and base are its surface's record).
void save_state(ByteWriter& out, const SnowCover& c);
/// Reads a record of save_state into `c`, whose surface has `cells` cells.
void load_state(ByteReader& in, SnowCover& c, std::size_t cells);
class StateHasher;
/// A cover's base (`surface`'s base_level) is state: it follows the geometry
/// only as far as the flake pool takes the snow it sheds, so it is hashed
/// whole. Its column tops are a pure function of the sources while it is
/// current, so they are hashed only while it is `stale`; its closed edges and
/// drop cells are functions of those two.
void hash_state(StateHasher& h, const SnowCover& c, const SnowSurface& surface, bool stale);

/// True for a cover's entity (its surface is snow over the geometry, not geometry).
[[nodiscard]] bool is_cover(const World& w, Entity e);

/// Builds a cover's surface for snow that lands at `fresh_density` (kg/m³;
/// every cell void until the cover system first builds its base); throws
/// SimulationError naming the bad field for invalid values.
[[nodiscard]] SnowSurface make_cover_surface(const CoverDef& def, double fresh_density);

/// `cover.*` [ZCL]; max > min per axis is checked by validate().
inline constexpr FieldRule<CoverDef> cover_fields[] = {
    {"min.x", &CoverDef::min_x},
    {"min.z", &CoverDef::min_z},
    {"max.x", &CoverDef::max_x},
    {"max.z", &CoverDef::max_z},
    {"cell", &CoverDef::cell, positive},
    {"edge_limit", &CoverDef::edge_limit, non_negative},
    {"drop_limit", &CoverDef::drop_limit, positive},
    {"laplacian_limit", &CoverDef::laplacian_limit, positive},
    {"repose_deg", &CoverDef::repose_deg, positive_up_to(max_repose_deg)},
};

[[nodiscard]] Invalid validate(const CoverDef& def);

} // namespace snow
