// cover: builds each snow cover's bare base from the geometry under it and
// follows the geometry when it changes. The base of a column is the highest
// geometry seen straight down there, rasterised as the sky map of [SKY] is;
// columns whose top is a declared surface (a roof, the ground rectangle) or
// that have no geometry are void, so the cover and the declared surfaces
// never hold the same column. When a column's base changes, its snow falls
// as clumps (mass exact) onto whatever is there now.
#include "systems/snowpack/snow_cover.hpp"

#include "systems/api/systems.hpp"
#include "systems/core/limits.hpp"
#include "systems/core/state_bytes.hpp"
#include "systems/geometry/occlusion_raster.hpp"
#include "systems/snowpack/shed.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace snow {

namespace {

/// Height (m) above a raised base at which its former snow reappears, so it lands again.
constexpr float reappear_height = 1.0e-3f;

/// Every cell of `cover` whose centre lies on declared surface `t` where t's
/// bare top is the column's top (within a cell's height): the cover leaves it
/// to the surface.
void yield_to_surface(const SnowSurface& cover, const SnowSurface& t, const Vector<float>& top,
                      Vector<std::uint8_t>& owned) {
    const double c = cover.cell;
    const double tol = std::max(cover.cell, t.cell);
    const auto first = [&](double lo, double origin) {
        return static_cast<std::int64_t>(std::floor((lo - origin) / c));
    };
    const std::int64_t ix0 = std::max<std::int64_t>(0, first(t.x0, cover.x0));
    const std::int64_t iz0 = std::max<std::int64_t>(0, first(t.z0, cover.z0));
    const std::int64_t ix1 =
        std::min<std::int64_t>(cover.nx - 1, first(t.x0 + t.nx * t.cell, cover.x0));
    const std::int64_t iz1 =
        std::min<std::int64_t>(cover.nz - 1, first(t.z0 + t.nz * t.cell, cover.z0));
    for (std::int64_t iz = iz0; iz <= iz1; ++iz) {
        for (std::int64_t ix = ix0; ix <= ix1; ++ix) {
            const auto x = static_cast<float>(cover.x0 + (ix + 0.5) * c);
            const auto z = static_cast<float>(cover.z0 + (iz + 0.5) * c);
            std::uint32_t tx = 0, tz = 0;
            const std::size_t i =
                cover.index(static_cast<std::uint32_t>(ix), static_cast<std::uint32_t>(iz));
            if (t.cell_at(x, z, tx, tz) &&
                t.height(t.base_level[t.index(tx, tz)]) >= top[i] - tol) {
                owned[i] = 0;
            }
        }
    }
}

/// World resource: a rebuild's buffers, with room for the largest cover.
struct CoverScratch {
    OcclusionMap map; ///< the geometry under the cover, one texel per cell
    Vector<std::uint8_t> owned;
    Vector<std::int64_t> target;
};

/// New base level per cell from the geometry now in the world.
void target_base(const World& w, const SnowSurface& s, SnowCover& cover, CoverScratch& scratch) {
    OcclusionMap& m = scratch.map;
    m.x0 = s.x0;
    m.z0 = s.z0;
    m.texel = s.cell;
    m.width = s.nx;
    m.height = s.nz;
    rasterise_geometry(w, m, is_cover);
    Vector<std::uint8_t>& owned = scratch.owned;
    owned.assign(s.cell_count(), 1);
    w.each<SnowSurface>([&](Entity e, const SnowSurface& t) {
        if (!w.has<SnowCover>(e)) {
            yield_to_surface(s, t, m.top_y, owned);
        }
    });
    Vector<std::int64_t>& out = scratch.target;
    out.resize(s.cell_count());
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double level = static_cast<double>(m.top_y[i]) / s.unit_height;
        out[i] = owned[i] != 0 && std::abs(level) <= max_surface_level ? std::llround(level)
                                                                       : void_level;
    }
    cover.column_top = m.top_y; // a copy: both keep their room
}

/// Moves every changed cell to its new base; its snow leaves as clumps first.
/// Returns false when the pool could not take all of it (those cells keep
/// their old base and the rebuild is tried again next tick).
bool apply_base(World& w, SnowSurface& s, const Vector<std::int64_t>& target) {
    FlakePool& pool = w.resource<FlakePool>();
    const float k_over_m = clump_drag(w);
    bool complete = true;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const std::size_t i = s.index(ix, iz);
            if (target[i] == s.base_level[i]) {
                continue;
            }
            if (s.snow[i] > 0) {
                float y = s.top_y(i);
                if (target[i] != void_level) {
                    y = std::max(y, s.height(target[i]) + reappear_height);
                }
                const ClumpStart at{{static_cast<float>(s.x0 + (ix + 0.5) * s.cell), y,
                                     static_cast<float>(s.z0 + (iz + 0.5) * s.cell)},
                                    k_over_m};
                s.snow[i] -= shed_units(pool, s.snow[i], at);
                s.fit_compaction(i);
                if (s.snow[i] > 0) {
                    complete = false;
                    continue;
                }
            }
            s.base_level[i] = target[i];
            s.mark_dirty(ix, iz);
        }
    }
    return complete;
}

/// Closed edges (drops and void), the drop cells spill watches, and a fresh level bound.
void derive_edges(SnowSurface& s, SnowCover& cover) {
    const auto drop = static_cast<std::int64_t>(std::llround(cover.drop_limit / s.unit_height));
    s.closed.assign(s.cell_count(), 0);
    cover.edge_cells.clear();
    cover.edge_side.clear();
    std::int64_t bound = void_level;
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const std::size_t i = s.index(ix, iz);
            const bool here_void = s.is_void(i);
            bound = here_void ? bound : std::max(bound, s.level(i));
            const bool has[4] = {ix > 0, ix + 1 < s.nx, iz > 0, iz + 1 < s.nz};
            const std::size_t nb[4] = {i - 1, i + 1, i - s.nx, i + s.nx};
            int spill_side = -1;
            for (int d = 0; d < 4; ++d) {
                if (!has[d]) {
                    continue;
                }
                const std::size_t j = nb[d];
                const bool shut =
                    here_void || s.is_void(j) || std::abs(s.base_level[i] - s.base_level[j]) > drop;
                s.closed[i] |= shut ? static_cast<std::uint8_t>(1u << d) : 0;
                const bool falls =
                    !(cover.column_top[j] >= s.height(s.base_level[i]) - cover.drop_limit);
                if (!here_void && shut && falls && spill_side < 0) {
                    spill_side = d;
                }
            }
            if (spill_side >= 0) {
                cover.edge_cells.push_back(static_cast<std::uint32_t>(i));
                cover.edge_side.push_back(static_cast<std::uint8_t>(spill_side));
            }
        }
    }
    s.level_bound = std::max(s.level_bound, bound);
    ++s.base_version;
}

} // namespace

bool is_cover(const World& w, Entity e) {
    return w.has<SnowCover>(e);
}

SnowSurface make_cover_surface(const CoverDef& def, double fresh_density) {
    Invalid e = validate(def);
    if (e.empty()) {
        const double along_x = std::round((static_cast<double>(def.max_x) - def.min_x) / def.cell);
        const double along_z = std::round((static_cast<double>(def.max_z) - def.min_z) / def.cell);
        check::number(e, "cover cells (extent / cell)",
                      between(1, static_cast<double>(max_cover_cells)), along_x * along_z);
        // The surface beneath has its own per-side limit; name it in the cover's terms.
        check::number(e, "cover cells along x (extent / cell)", up_to(max_surface_cells_per_side),
                      along_x);
        check::number(e, "cover cells along z (extent / cell)", up_to(max_surface_cells_per_side),
                      along_z);
    }
    throw_if(e);
    SurfaceDef sd;
    sd.x0 = def.min_x;
    sd.z0 = def.min_z;
    sd.size_x = def.max_x - def.min_x;
    sd.size_z = def.max_z - def.min_z;
    sd.cell = def.cell;
    sd.edge_limit = def.edge_limit;
    sd.laplacian_limit = def.laplacian_limit;
    sd.spills = false; // its border is no edge of anything; a cover spills at its drops
    sd.repose_deg = def.repose_deg;
    SnowSurface s = make_surface(sd, fresh_density);
    std::fill(s.base_level.begin(), s.base_level.end(), void_level);
    s.uniform_base = false; // the base follows the geometry (cover_system)
    s.closed.assign(s.cell_count(), closed_all);
    s.level_bound = void_level;
    return s;
}

void prepare_cover(World& w) {
    if (w.count<SnowCover>() == 0) {
        return;
    }
    auto* scratch = w.try_resource<CoverScratch>();
    if (scratch == nullptr) {
        scratch = &w.set_resource<CoverScratch>();
    }
    std::size_t largest = 0;
    w.each<SnowCover>([&](Entity e, SnowCover& cover) {
        const std::size_t cells = w.get<SnowSurface>(e).cell_count();
        largest = std::max(largest, cells);
        cover.column_top.reserve(cells);
        cover.edge_cells.reserve(cells); // at most one per cell
        cover.edge_side.reserve(cells);
    });
    scratch->map.top_y.reserve(largest);
    scratch->map.top_id.reserve(largest);
    scratch->owned.reserve(largest);
    scratch->target.reserve(largest);
}

void cover_system(World& w) {
    prepare_cover(w);
    CoverScratch& scratch = w.resource<CoverScratch>();
    const SourceVersions versions = source_versions(w);
    auto& covers = w.pool<SnowCover>();
    for (std::size_t k = 0; k < covers.size(); ++k) {
        SnowCover& cover = covers.components()[k];
        if (cover.current(versions)) {
            continue;
        }
        SnowSurface& s = w.get<SnowSurface>(covers.entities()[k]);
        target_base(w, s, cover, scratch);
        cover.built = apply_base(w, s, scratch.target);
        cover.built_from = versions;
        derive_edges(s, cover);
    }
}

namespace {

template <typename Io, typename Cover>
void cover_record(Io& io, Cover& c) {
    io(c.built);
    for (auto* v : {&c.built_from.solids, &c.built_from.surfaces, &c.built_from.occlusion}) {
        io(*v);
    }
    io(c.column_top);
    io(c.edge_cells);
    io(c.edge_side);
}

} // namespace

void save_state(ByteWriter& out, const SnowCover& c) {
    cover_record(out, c);
}

void load_state(ByteReader& in, SnowCover& c, std::size_t cells) {
    cover_record(in, c);
    in.require(c.column_top.empty() || c.column_top.size() == cells,
               "has column tops of another size than its surface");
    in.require(c.edge_side.size() == c.edge_cells.size(), "has drop cells without their sides");
    for (std::size_t k = 0; k < c.edge_cells.size(); ++k) {
        in.require(c.edge_cells[k] < cells && (k == 0 || c.edge_cells[k - 1] < c.edge_cells[k]),
                   "has drop cells out of order or past its surface");
        in.require(c.edge_side[k] < 4, "has a drop towards no side");
    }
}

Invalid validate(const CoverDef& def) {
    Invalid e = check_fields("cover", cover_fields, def);
    check::ordered(e, "cover", "min.x", def.min_x, "max.x", def.max_x, true);
    check::ordered(e, "cover", "min.z", def.min_z, "max.z", def.max_z, true);
    return e;
}

void hash_state(StateHasher& h, const SnowCover& c, const SnowSurface& surface, bool stale) {
    ByteWriter out(h);
    out(surface.base_level);
    out(stale);
    if (stale) {
        out(c.column_top);
    }
}

} // namespace snow
