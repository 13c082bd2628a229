// SnowSurface construction and cell queries. Heights are integer levels of
// `unit_height` so deposit and smoothing compare and move snow exactly.
#include "systems/snowpack/snow_surface.hpp"

#include "systems/core/state_bytes.hpp"
#include "systems/core/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace snow {

namespace {

/// Cells along one side: size / cell rounded, checked against the grid limits.
std::uint32_t cells_per_side(Invalid& err, const char* field, double size, double cell) {
    const double n = size / cell;
    if (!(n >= 0.5)) {
        check::fail(err, field, ">= 1", n);
    } else if (n >= max_surface_cells_per_side + 0.5) {
        check::fail(err, field, "<= " + std::to_string(max_surface_cells_per_side), n);
    }
    return err.empty() ? static_cast<std::uint32_t>(std::llround(n)) : 0;
}

} // namespace

SnowSurface make_surface(const SurfaceDef& def, double fresh_density) {
    Invalid e = validate(def);
    const double cell = def.cell;
    const double unit_height = unit_kg / (fresh_density * cell * cell);
    if (e.empty() && !(std::isfinite(unit_height) && unit_height > 0.0)) {
        check::fail(e, "surface.cell", "large enough for a finite snow unit height", cell);
    }
    std::uint32_t nx = 0, nz = 0;
    if (e.empty()) {
        nx = cells_per_side(e, "surface.size_x / surface.cell (cells per side)", def.size_x, cell);
        nz = cells_per_side(e, "surface.size_z / surface.cell (cells per side)", def.size_z, cell);
    }
    if (e.empty()) {
        // A plane's extremes are at its corners; all levels must stay exact integers.
        const double reach = std::abs(static_cast<double>(def.base_y)) +
                             std::abs(static_cast<double>(def.slope_x)) * nx * cell +
                             std::abs(static_cast<double>(def.slope_z)) * nz * cell;
        check::number(e, "surface.base_y and slopes (in snow units of this cell size)",
                      up_to(max_surface_level), reach / unit_height);
    }
    throw_if(e);

    SnowSurface s;
    s.x0 = def.x0;
    s.z0 = def.z0;
    s.cell = def.cell;
    s.nx = nx;
    s.nz = nz;
    s.unit_height = static_cast<float>(unit_height);
    s.spills = def.spills;
    const std::size_t n = static_cast<std::size_t>(nx) * nz;
    s.base_level.resize(n);
    s.snow.assign(n, 0);
    s.compacted.assign(n, 0); // settling packs every cell in time: sized here, no tick allocates
    for (std::uint32_t iz = 0; iz < nz; ++iz) {
        for (std::uint32_t ix = 0; ix < nx; ++ix) {
            const double y =
                def.base_y + def.slope_x * ((ix + 0.5) * cell) + def.slope_z * ((iz + 0.5) * cell);
            s.base_level[s.index(ix, iz)] = std::llround(y / unit_height);
        }
    }
    s.level_bound = *std::max_element(s.base_level.begin(), s.base_level.end());
    s.uniform_base = s.level_bound == *std::min_element(s.base_level.begin(), s.base_level.end());
    // Every tile is listed at most once: no tick allocates for marking.
    s.tile_dirty.assign(static_cast<std::size_t>(s.tiles_x()) * s.tiles_z(), CellBox{});
    s.dirty_tiles.reserve(s.tile_dirty.size());
    // A limit beyond what a cell can hold never triggers: clamp instead of overflowing.
    const auto depth_units = [&](float metres) {
        const double levels = std::round(metres / unit_height);
        return static_cast<std::uint32_t>(
            std::min(levels, static_cast<double>(std::numeric_limits<std::uint32_t>::max())));
    };
    s.edge_limit_units = depth_units(def.edge_limit);
    // Weight along the slope minus friction, per unit of plan load and g.
    // Squares of floats are exact in double and sqrt is correctly rounded:
    // std::hypot's double code differs between x86-64 and aarch64 glibc
    // (docs/toolchain.md "libm").
    const double tan2 = double{def.slope_x} * def.slope_x + double{def.slope_z} * def.slope_z;
    const double tan_pitch = std::sqrt(tan2);
    const double cos_pitch = 1.0 / std::sqrt(1.0 + tan2);
    const double drive = cos_pitch * cos_pitch * (tan_pitch - def.slide_friction);
    s.slide_drive = def.spills && drive > 0.0 ? static_cast<float>(drive) : 0.0f;
    s.slide_adhesion = def.slide_adhesion;
    s.slide_along_x = std::abs(def.slope_x) >= std::abs(def.slope_z);
    s.slide_to_high = (s.slide_along_x ? def.slope_x : def.slope_z) < 0.0f;
    // [WF §3]: (4h - Σh_nb)/dx² <= L  <=>  4h - Σh_nb <= L·dx² metres, in levels.
    const double lap = std::round(def.laplacian_limit * cell * cell / unit_height);
    s.laplacian_limit_units = static_cast<std::int64_t>(std::clamp(lap, 1.0, max_surface_level));
    // The steepest step between neighbours the snow keeps [NSA]; never 0 (0 = no rule).
    const double talus = std::tan(def.repose_deg * std::numbers::pi / 180.0) * cell;
    s.talus_units = std::max<std::int64_t>(1, std::llround(talus / s.unit_height));
    return s;
}

std::array<glm::vec3, 4> surface_base_corners(const SnowSurface& s) {
    // Plane through the corner cells' centres, extended to the grid's edges.
    const auto base = [&](std::uint32_t ix, std::uint32_t iz) {
        return static_cast<double>(s.base_level[s.index(ix, iz)]) * s.unit_height;
    };
    const double cell = s.cell;
    const double h00 = base(0, 0);
    const double gx = s.nx > 1 ? (base(s.nx - 1, 0) - h00) / ((s.nx - 1) * cell) : 0.0;
    const double gz = s.nz > 1 ? (base(0, s.nz - 1) - h00) / ((s.nz - 1) * cell) : 0.0;
    const double x0 = s.x0, z0 = s.z0, x1 = x0 + s.nx * cell, z1 = z0 + s.nz * cell;
    const auto at = [&](double x, double z) {
        const double y = h00 + (x - x0 - 0.5 * cell) * gx + (z - z0 - 0.5 * cell) * gz;
        return glm::vec3{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
    };
    return {at(x0, z0), at(x1, z0), at(x1, z1), at(x0, z1)};
}

bool SnowSurface::cell_at(float x, float z, std::uint32_t& ix, std::uint32_t& iz) const {
    const float fx = (x - x0) / cell;
    const float fz = (z - z0) / cell;
    // Written so NaN compares false and lands outside.
    if (!(fx >= 0.0f && fz >= 0.0f && fx < static_cast<float>(nx) && fz < static_cast<float>(nz))) {
        return false;
    }
    ix = std::min(static_cast<std::uint32_t>(fx), nx - 1);
    iz = std::min(static_cast<std::uint32_t>(fz), nz - 1);
    return true;
}

void SnowSurface::mark_dirty(std::uint32_t ix, std::uint32_t iz) {
    if (dirty_empty()) {
        dirty_x0 = dirty_x1 = ix;
        dirty_z0 = dirty_z1 = iz;
    } else {
        dirty_x0 = std::min(dirty_x0, ix);
        dirty_x1 = std::max(dirty_x1, ix);
        dirty_z0 = std::min(dirty_z0, iz);
        dirty_z1 = std::max(dirty_z1, iz);
    }
    const std::size_t tiles = static_cast<std::size_t>(tiles_x()) * tiles_z();
    if (tile_dirty.size() != tiles) { // a surface not made by make_surface
        tile_dirty.assign(tiles, CellBox{});
        dirty_tiles.clear();
        dirty_tiles.reserve(tiles);
    }
    const std::uint32_t t = tile_of(ix, iz);
    if (tile_dirty[t].empty()) {
        dirty_tiles.push_back(t);
    }
    tile_dirty[t].include(ix, iz);
    level_bound = std::max(level_bound, level(index(ix, iz)));
}

void SnowSurface::compact(std::size_t i, std::uint32_t levels) {
    if (levels == 0) {
        return; // a surface nothing packed keeps no per-cell compaction at all
    }
    if (compacted.empty()) {
        compacted.assign(snow.size(), 0);
    }
    compacted[i] += levels;
}

void SnowSurface::clear_dirty() {
    for (const std::uint32_t t : dirty_tiles) {
        tile_dirty[t] = CellBox{};
    }
    dirty_tiles.clear();
    dirty_x0 = dirty_z0 = 1;
    dirty_x1 = dirty_z1 = 0;
}

std::uint64_t SnowSurface::settled_units() const {
    std::uint64_t sum = 0;
    for (const std::uint32_t u : snow) {
        sum += u;
    }
    return sum;
}

namespace {

template <typename Io, typename Surface>
void surface_record(Io& io, Surface& s) {
    io(s.base_level);
    io(s.uniform_base);
    io(s.closed);
    io(s.snow);
    io(s.compacted);
    for (auto* v : {&s.dirty_x0, &s.dirty_z0, &s.dirty_x1, &s.dirty_z1}) {
        io(*v);
    }
    io(s.tile_dirty);
    io(s.dirty_tiles);
    io(s.level_bound);
}

/// A box is empty or lies inside `limit` (which it must, to be read by redistribute).
bool box_inside(const CellBox& b, const CellBox& limit) {
    return b.empty() ||
           (b.x0 >= limit.x0 && b.x1 <= limit.x1 && b.z0 >= limit.z0 && b.z1 <= limit.z1);
}

/// The shapes and bounds a run keeps (cells, tiles, levels), so no later
/// read leaves an array.
void check_surface(const ByteReader& in, const SnowSurface& s) {
    in.require(s.nx > 0 && s.nz > 0, "belongs to a surface without cells");
    const std::size_t cells = static_cast<std::size_t>(s.nx) * s.nz;
    const std::size_t tiles = static_cast<std::size_t>(s.tiles_x()) * s.tiles_z();
    in.require(s.snow.size() == cells && s.base_level.size() == cells,
               "has another number of cells than the scene's surface");
    in.require(s.compacted.empty() || s.compacted.size() == cells,
               "has a compaction of another size");
    in.require(s.closed.empty() || s.closed.size() == cells, "has closed edges of another size");
    in.require(s.tile_dirty.size() == tiles,
               "has another number of tiles than the scene's surface");
    constexpr std::int64_t level_limit = std::int64_t{1} << 40;
    std::int64_t highest = std::numeric_limits<std::int64_t>::min();
    for (std::size_t i = 0; i < cells; ++i) {
        in.require(s.is_void(i) ||
                       (s.base_level[i] > -level_limit && s.base_level[i] < level_limit),
                   "has a base level out of range");
        in.require(s.compacted.empty() || s.compacted[i] <= max_compaction(s.snow[i]),
                   "has snow packed below its own mass");
        in.require(s.closed.empty() || s.closed[i] <= closed_all, "has an unknown edge flag");
        highest = s.is_void(i) ? highest : std::max(highest, s.level(i));
    }
    in.require(cells == 0 || s.level_bound >= highest, "has a level bound below its snow");
    in.require(box_inside(CellBox{s.dirty_x0, s.dirty_z0, s.dirty_x1, s.dirty_z1},
                          CellBox{0, 0, s.nx - 1, s.nz - 1}),
               "has dirty cells outside the surface");
    Vector<bool> listed(tiles, false);
    for (const std::uint32_t t : s.dirty_tiles) {
        in.require(t < tiles && !listed[t] && !s.tile_dirty[t].empty(),
                   "lists a dirty tile twice, past the surface or clean");
        listed[t] = true;
    }
    for (std::uint32_t t = 0; t < tiles; ++t) {
        const std::uint32_t tx = (t % s.tiles_x()) << dirty_tile_shift;
        const std::uint32_t tz = (t / s.tiles_x()) << dirty_tile_shift;
        const CellBox tile{tx, tz, std::min(s.nx - 1, tx + (1u << dirty_tile_shift) - 1),
                           std::min(s.nz - 1, tz + (1u << dirty_tile_shift) - 1)};
        in.require(listed[t] != s.tile_dirty[t].empty() && box_inside(s.tile_dirty[t], tile),
                   "has a dirty tile box outside its tile or unlisted");
    }
}

} // namespace

void save_state(ByteWriter& out, const SnowSurface& s) {
    surface_record(out, s);
}

void load_state(ByteReader& in, SnowSurface& s) {
    surface_record(in, s);
    check_surface(in, s);
    s.dirty_tiles.reserve(s.tile_dirty.size()); // mark_dirty never allocates
}

Invalid validate(const SurfaceDef& def) {
    Invalid e = check_fields("surface", surface_fields, def);
    return e;
}

void hash_state(StateHasher& h, const SnowSurface& s) {
    ByteWriter out(h);
    out(s.snow);
    if (!s.compacted.empty()) { // never compacted: the hash is what it was before compaction
        out(s.compacted);
    }
    for (const std::uint32_t v : {s.dirty_x0, s.dirty_z0, s.dirty_x1, s.dirty_z1}) {
        out(v);
    }
    out(s.tile_dirty);
    out(s.dirty_tiles);
    out(s.level_bound);
}

} // namespace snow
