// collider_grid: the cell index of box and sphere colliders [WF §8].
// Built only when the solids or the surfaces change (source_versions.hpp), at
// the start of the next tick, into the room the call that changed them made
// (reserve_collider_grid): a tick never allocates, and adding many colliders
// one by one does not rebuild it each time.
#include "systems/geometry/collider_grid.hpp"

#include "systems/core/limits.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/geometry/colliders.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

namespace snow {

namespace {

constexpr float neg_inf = -std::numeric_limits<float>::infinity();

using OwnedSurface = ColliderGrid::OwnedSurface;

void owned_surfaces(const World& w, Vector<OwnedSurface>& out) {
    out.clear();
    std::uint32_t order = 0;
    w.each<SurfaceOf, SnowSurface>([&](Entity e, const SurfaceOf& of, const SnowSurface&) {
        if (!of.owner.is_null() && w.has<SnowHolder>(of.owner)) {
            out.emplace_back(of.owner.bits, order, e);
        }
        ++order;
    });
    // Unique keys (order is distinct), so the sort is deterministic.
    std::sort(out.begin(), out.end(), [](const OwnedSurface& a, const OwnedSurface& b) {
        return std::tie(std::get<0>(a), std::get<1>(a)) < std::tie(std::get<0>(b), std::get<1>(b));
    });
}

/// Appends the surfaces of `owner` to grid.holder_surfaces; returns [begin, end).
std::pair<std::uint32_t, std::uint32_t>
take_surfaces(ColliderGrid& grid, const Vector<OwnedSurface>& owned, std::uint32_t owner) {
    const auto lo = std::lower_bound(
        owned.begin(), owned.end(), owner,
        [](const OwnedSurface& s, std::uint32_t bits) { return std::get<0>(s) < bits; });
    const auto begin = static_cast<std::uint32_t>(grid.holder_surfaces.size());
    for (auto it = lo; it != owned.end() && std::get<0>(*it) == owner; ++it) {
        grid.holder_surfaces.push_back(std::get<2>(*it));
    }
    return {begin, static_cast<std::uint32_t>(grid.holder_surfaces.size())};
}

void collect(World& w, ColliderGrid& grid) {
    grid.boxes.clear();
    grid.spheres.clear();
    grid.meshes.clear();
    grid.holder_surfaces.clear();
    owned_surfaces(w, grid.owned);
    const Vector<OwnedSurface>& owned = grid.owned;
    w.each<BoxCollider>([&](Entity e, const BoxCollider& b) {
        const auto [sb, se] = take_surfaces(grid, owned, e.bits);
        grid.boxes.push_back(GridBox{b.box, e.bits, sb, se});
    });
    w.each<SphereCollider>([&](Entity, const SphereCollider& s) {
        grid.spheres.push_back(GridSphere{s.center, s.radius});
    });
    w.each<MeshCollider>([&](Entity e, const MeshCollider&) {
        const auto [sb, se] = take_surfaces(grid, owned, e.bits);
        grid.meshes.push_back(GridMesh{e.bits, sb, se});
    });
    std::sort(grid.meshes.begin(), grid.meshes.end(),
              [](const GridMesh& a, const GridMesh& b) { return a.entity < b.entity; });
}

/// Cells along an extent: as fine as min_cell_size allows (at most
/// max_collider_cells_per_side), so the reach of a cell's neighbourhood stays tight.
std::uint32_t cells_along(float extent) {
    const double n = std::floor(extent / ColliderGrid::min_cell_size);
    return static_cast<std::uint32_t>(
        std::clamp(n, 1.0, static_cast<double>(max_collider_cells_per_side)));
}

/// Calls fn(cell) for every cell the XZ rectangle [x0, x1] × [z0, z1] overlaps.
template <typename Fn>
void for_cells(const ColliderGrid& g, float x0, float x1, float z0, float z1, Fn&& fn) {
    const std::uint32_t i0 = g.cell_x(x0), i1 = g.cell_x(x1);
    const std::uint32_t j0 = g.cell_z(z0), j1 = g.cell_z(z1);
    for (std::uint32_t j = j0; j <= j1; ++j) {
        for (std::uint32_t i = i0; i <= i1; ++i) {
            fn(static_cast<std::size_t>(j) * g.nx + i);
        }
    }
}

/// Calls per_item(cell, item, top) for every cell each collected sphere and
/// box overlaps: spheres first, each item as cell_items holds it.
template <typename Fn>
void visit_items(const ColliderGrid& g, Fn&& per_item) {
    for (std::uint32_t i = 0; i < g.spheres.size(); ++i) {
        const GridSphere& s = g.spheres[i];
        for_cells(g, s.center.x - s.radius, s.center.x + s.radius, s.center.z - s.radius,
                  s.center.z + s.radius, [&](std::size_t c) {
                      per_item(c, i | ColliderGrid::sphere_tag, s.center.y + s.radius);
                  });
    }
    for (std::uint32_t i = 0; i < g.boxes.size(); ++i) {
        const Aabb& b = g.boxes[i].box;
        for_cells(g, b.min.x, b.max.x, b.min.z, b.max.z,
                  [&](std::size_t c) { per_item(c, i, b.max.y); });
    }
}

/// Two passes (count, then fill) so each cell's items are contiguous.
void bin(ColliderGrid& g) {
    const std::size_t cells = static_cast<std::size_t>(g.nx) * g.nz;
    Vector<std::uint32_t>& count = g.count;
    count.assign(cells, 0);
    g.cell_top.assign(cells, neg_inf);
    visit_items(g, [&](std::size_t c, std::uint32_t, float top) {
        ++count[c];
        g.cell_top[c] = std::max(g.cell_top[c], top);
    });
    g.cell_start.assign(cells + 1, 0);
    for (std::size_t c = 0; c < cells; ++c) {
        g.cell_start[c + 1] = g.cell_start[c] + count[c];
    }
    g.cell_items.assign(g.cell_start[cells], 0);
    std::fill(count.begin(), count.end(), 0);
    visit_items(g, [&](std::size_t c, std::uint32_t item, float) {
        g.cell_items[g.cell_start[c] + count[c]++] = item;
    });
}

/// out[c] = the maximum of in over c and its 8 neighbours.
void dilate(const ColliderGrid& g, const Vector<float>& in, Vector<float>& out) {
    out.assign(in.size(), neg_inf);
    for (std::uint32_t j = 0; j < g.nz; ++j) {
        for (std::uint32_t i = 0; i < g.nx; ++i) {
            float top = neg_inf;
            for (std::uint32_t jj = j > 0 ? j - 1 : 0; jj <= std::min(j + 1, g.nz - 1); ++jj) {
                for (std::uint32_t ii = i > 0 ? i - 1 : 0; ii <= std::min(i + 1, g.nx - 1); ++ii) {
                    top = std::max(top, in[static_cast<std::size_t>(jj) * g.nx + ii]);
                }
            }
            out[static_cast<std::size_t>(j) * g.nx + i] = top;
        }
    }
}

/// cell_mesh_reach from mesh triangles and mesh surfaces, cell_reach from
/// those and the box and sphere tops (within the cell, and around it).
void reach(const World& w, ColliderGrid& g) {
    Vector<float>& mesh = g.mesh_top;
    mesh.assign(g.cell_top.size(), neg_inf);
    const auto raise = [&](float x0, float x1, float z0, float z1, float top) {
        for_cells(g, x0, x1, z0, z1, [&](std::size_t c) { mesh[c] = std::max(mesh[c], top); });
    };
    for (const GridMesh& m : g.meshes) {
        const auto& tris = w.get<MeshCollider>(Entity{m.entity}).triangles;
        for (std::size_t i = 0; i + 2 < tris.size(); i += 3) {
            const glm::vec3 &a = tris[i], &b = tris[i + 1], &c = tris[i + 2];
            raise(std::min({a.x, b.x, c.x}), std::max({a.x, b.x, c.x}), std::min({a.z, b.z, c.z}),
                  std::max({a.z, b.z, c.z}), std::max({a.y, b.y, c.y}));
        }
        for (std::uint32_t i = m.surf_begin; i < m.surf_end; ++i) {
            const std::array<glm::vec3, 4> q =
                surface_base_corners(w.get<SnowSurface>(g.holder_surfaces[i]));
            raise(q[0].x, q[2].x, q[0].z, q[2].z, std::max({q[0].y, q[1].y, q[2].y, q[3].y}));
        }
    }
    dilate(g, mesh, g.cell_mesh_reach);
    for (std::size_t c = 0; c < mesh.size(); ++c) {
        mesh[c] = std::max(mesh[c], g.cell_top[c]);
    }
    Vector<float>& around = g.around;
    dilate(g, mesh, around);
    g.cell_reach.resize(2 * mesh.size());
    for (std::size_t c = 0; c < mesh.size(); ++c) {
        g.cell_reach[2 * c] = std::max(g.cell_top[c], g.cell_mesh_reach[c]);
        g.cell_reach[2 * c + 1] = around[c];
    }
    row_tops(g, g.cell_reach, g.row_reach);
}

} // namespace

void row_tops(const ColliderGrid& g, const Vector<float>& reach, Vector<float>& out) {
    out.assign(g.nz, neg_inf);
    const std::size_t row = 2 * static_cast<std::size_t>(g.nx);
    for (std::uint32_t j = 0; j < g.nz; ++j) {
        const auto first = reach.begin() + static_cast<std::ptrdiff_t>(j * row);
        out[j] = *std::max_element(first, first + static_cast<std::ptrdiff_t>(row));
    }
}

namespace {

/// The world's grid, made when missing with its cells laid over the bounds
/// (fixed when the Simulation is made).
ColliderGrid& grid_of(World& w) {
    if (auto* g = w.try_resource<ColliderGrid>()) {
        return *g;
    }
    ColliderGrid& g = w.set_resource<ColliderGrid>();
    const Aabb& bounds = w.resource<SimConfig>().bounds;
    g.x0 = bounds.min.x;
    g.z0 = bounds.min.z;
    const glm::vec3 ext = bounds.size();
    g.nx = cells_along(ext.x);
    g.nz = cells_along(ext.z);
    g.cell_size_x = ext.x / static_cast<float>(g.nx);
    g.cell_size_z = ext.z / static_cast<float>(g.nz);
    g.inv_cell_x = ext.x > 0.0f ? 1.0f / g.cell_size_x : 0.0f;
    g.inv_cell_z = ext.z > 0.0f ? 1.0f / g.cell_size_z : 0.0f;
    return g;
}

} // namespace

const GridMesh* ColliderGrid::find_mesh(std::uint32_t id) const {
    const auto it =
        std::lower_bound(meshes.begin(), meshes.end(), id,
                         [](const GridMesh& m, std::uint32_t bits) { return m.entity < bits; });
    return it != meshes.end() && it->entity == id ? &*it : nullptr;
}

void reserve_collider_grid(World& w) {
    ColliderGrid& g = grid_of(w);
    collect(w, g); // the next rebuild collects the same
    std::size_t items = 0;
    visit_items(g, [&](std::size_t, std::uint32_t, float) { ++items; });
    const std::size_t cells = static_cast<std::size_t>(g.nx) * g.nz;
    g.cell_start.reserve(cells + 1);
    g.cell_items.reserve(items);
    g.count.reserve(cells);
    for (Vector<float>* v : {&g.cell_top, &g.cell_mesh_reach, &g.mesh_top, &g.around}) {
        v->reserve(cells);
    }
    g.cell_reach.reserve(2 * cells);
    g.row_reach.reserve(g.nz);
}

ColliderGrid& update_collider_grid(World& w) {
    ColliderGrid& g = grid_of(w);
    const SourceVersions v = source_versions(w);
    if (!g.built || g.solids_version != v.solids || g.surfaces_version != v.surfaces) {
        collect(w, g);
        bin(g);
        reach(w, g);
        g.solids_version = v.solids;
        g.surfaces_version = v.surfaces;
        g.built = true;
    }
    return g;
}

} // namespace snow
