#include "render/passes/surface_tiles.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>

namespace snow {

namespace {

constexpr std::uint64_t hash_multiplier = 0x9E3779B97F4A7C15ull; // odd: every row step invertible

/// A grid whose arrays match its size; anything else is drawn as nothing.
bool well_formed(const SnowSurface& s) {
    const std::size_t n = static_cast<std::size_t>(s.nx) * s.nz;
    return n > 0 && s.snow.size() == n && s.base_level.size() == n;
}

std::uint64_t grid_fingerprint(const SnowSurface& s) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a over the grid description
    for (const std::uint64_t v : {std::uint64_t{s.nx}, std::uint64_t{s.nz},
                                  std::uint64_t{std::bit_cast<std::uint32_t>(s.x0)},
                                  std::uint64_t{std::bit_cast<std::uint32_t>(s.z0)},
                                  std::uint64_t{std::bit_cast<std::uint32_t>(s.cell)},
                                  std::uint64_t{std::bit_cast<std::uint32_t>(s.unit_height)}}) {
        h = (h ^ v) * 1099511628211ull;
    }
    return h;
}

/// Cells of a tile: [x0, x1) × [z0, z1).
struct TileCells {
    std::uint32_t x0, z0, x1, z1;
};

TileCells cells_of(const SnowSurface& s, std::uint32_t tile, std::uint32_t tiles_x) {
    const std::uint32_t tx = tile % tiles_x, tz = tile / tiles_x;
    return {tx * surface_tile_cells, tz * surface_tile_cells,
            std::min(s.nx, (tx + 1) * surface_tile_cells),
            std::min(s.nz, (tz + 1) * surface_tile_cells)};
}

/// Fixed odd 64-bit weights, one per column of a tile row and array.
struct ChecksumWeights {
    std::array<std::uint64_t, surface_tile_cells> snow{}, base{};
    constexpr ChecksumWeights() {
        std::uint64_t x = 0x243F6A8885A308D3ull; // splitmix64 from a fixed seed
        for (std::uint32_t k = 0; k < surface_tile_cells; ++k) {
            for (std::uint64_t* w : {&snow[k], &base[k]}) {
                x += 0x9E3779B97F4A7C15ull;
                std::uint64_t z = x;
                z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
                z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
                *w = (z ^ (z >> 31)) | 1u;
            }
        }
    }
};
constexpr ChecksumWeights checksum_weights;

/// Checksum of the tile's snow depth and base levels (mod 2^64): per row a weighted
/// sum with odd weights (vectorises, no dependency chain), rows chained
/// polynomially. One changed cell always changes it (an odd weight times a
/// non-zero difference is never 0 mod 2^64); several changes cancel only by
/// chance. Memory bound: the renderer reads every cell once per frame.
std::uint64_t tile_checksum(const SnowSurface& s, const TileCells& c) {
    std::uint64_t h = 0;
    const std::uint32_t width = c.x1 - c.x0;
    for (std::uint32_t z = c.z0; z < c.z1; ++z) {
        const std::size_t row = static_cast<std::size_t>(z) * s.nx + c.x0;
        const std::uint32_t* snow = s.snow.data() + row;
        const std::int64_t* base = s.base_level.data() + row;
        std::uint64_t sum = 0;
        for (std::uint32_t x = 0; x < width; ++x) {
            sum += snow[x] * checksum_weights.snow[x] +
                   static_cast<std::uint64_t>(base[x]) * checksum_weights.base[x];
        }
        if (!s.compacted.empty()) { // what is drawn is the depth: units less compaction
            const std::uint32_t* packed = s.compacted.data() + row;
            for (std::uint32_t x = 0; x < width; ++x) {
                sum -= packed[x] * checksum_weights.snow[x];
            }
        }
        h = h * hash_multiplier + sum;
    }
    return h;
}

/// The cells a tile's samples span: its own and the first column and row of
/// its +x and +z neighbours (the last samples of a tile are the first of the
/// next, so neighbouring tiles share their edge).
TileCells reach_of(const SnowSurface& s, const TileCells& c) {
    return {c.x0, c.z0, std::min(c.x1 + 1, s.nx), std::min(c.z1 + 1, s.nz)};
}

/// (lowest bare top, highest snow top) of the cells that carry snow; an empty
/// range (lo > hi) when none does.
glm::vec2 tile_range(const SnowSurface& s, const TileCells& c) {
    std::int64_t lo = std::numeric_limits<std::int64_t>::max();
    std::int64_t hi = std::numeric_limits<std::int64_t>::min();
    for (std::uint32_t z = c.z0; z < c.z1; ++z) {
        for (std::uint32_t x = c.x0; x < c.x1; ++x) {
            const std::size_t i = s.index(x, z);
            if (s.snow[i] != 0) {
                lo = std::min(lo, s.base_level[i]);
                hi = std::max(hi, s.level(i));
            }
        }
    }
    return lo > hi ? glm::vec2(1.0f, 0.0f) : glm::vec2(s.height(lo), s.height(hi));
}

/// True when the bare top jumps like an edge between neighbouring cells.
bool tile_has_edges(const SnowSurface& s, const TileCells& c) {
    const double limit = surface_edge_slope * s.cell / s.unit_height; // in levels
    const std::uint32_t x_end = c.x1, z_end = c.z1;
    const auto jumps = [&](std::size_t a, std::size_t b) {
        return std::abs(static_cast<double>(s.base_level[a] - s.base_level[b])) > limit;
    };
    for (std::uint32_t z = c.z0; z < z_end; ++z) {
        for (std::uint32_t x = c.x0; x < x_end; ++x) {
            const std::size_t i = s.index(x, z);
            if ((x + 1 < x_end && jumps(i, i + 1)) || (z + 1 < z_end && jumps(i, i + s.nx))) {
                return true;
            }
        }
    }
    return false;
}

/// True when the box lies wholly outside one clip plane of `m`.
bool outside_frustum(const glm::mat4& m, const glm::vec3& lo, const glm::vec3& hi) {
    int outside[6] = {0, 0, 0, 0, 0, 0};
    for (int k = 0; k < 8; ++k) {
        const glm::vec4 p((k & 1) != 0 ? hi.x : lo.x, (k & 2) != 0 ? hi.y : lo.y,
                          (k & 4) != 0 ? hi.z : lo.z, 1.0f);
        const glm::vec4 c = m * p;
        outside[0] += c.x < -c.w ? 1 : 0;
        outside[1] += c.x > c.w ? 1 : 0;
        outside[2] += c.y < -c.w ? 1 : 0;
        outside[3] += c.y > c.w ? 1 : 0;
        outside[4] += c.z < -c.w ? 1 : 0;
        outside[5] += c.z > c.w ? 1 : 0;
    }
    return std::any_of(std::begin(outside), std::end(outside), [](int n) { return n == 8; });
}

} // namespace

namespace {

/// The grid quads (by their first sample x, z) for which `keep_quad` holds,
/// then the skirts of the tile edges in `skirts`, segment by segment (grid
/// ids a, b) where `keep_segment` holds.
template <class KeepQuad, class KeepSegment>
void append_patch(std::uint32_t level, std::uint32_t skirts, KeepQuad keep_quad,
                  KeepSegment keep_segment, std::vector<std::uint32_t>& idx) {
    const std::uint32_t n = patch_side(level), seam = n * n;
    for (std::uint32_t z = 0; z + 1 < n; ++z) {
        for (std::uint32_t x = 0; x + 1 < n; ++x) {
            if (keep_quad(x, z)) {
                const std::uint32_t a = z * n + x, b = a + 1, c = a + n, d = c + 1;
                idx.insert(idx.end(), {a, c, b, b, c, d});
            }
        }
    }
    // The perimeter counter-clockwise seen from +y (−x, +z, +x, −z edge), so
    // each skirt quad faces outward.
    const auto ring = [n](std::uint32_t k) {
        const std::uint32_t e = k / (n - 1), j = k % (n - 1);
        return e == 0   ? j * n                   // −x edge, z rising
               : e == 1 ? (n - 1) * n + j         // +z edge, x rising
               : e == 2 ? (n - 1 - j) * n + n - 1 // +x edge, z falling
                        : n - 1 - j;              // −z edge, x falling
    };
    constexpr std::uint32_t ring_edges[4] = {skirt_low_x, skirt_high_z, skirt_high_x, skirt_low_z};
    const std::uint32_t perimeter = 4 * (n - 1);
    for (std::uint32_t k = 0; k < perimeter; ++k) {
        const std::uint32_t t0 = ring(k), t1 = ring((k + 1) % perimeter);
        if ((skirts & ring_edges[k / (n - 1)]) != 0 && keep_segment(t0, t1)) {
            idx.insert(idx.end(), {t0, t0 + seam, t1, t1, t0 + seam, t1 + seam});
        }
    }
}

/// Position in cells from the grid origin of the sample in cell u of an axis
/// of n cells: the cell's centre, the outermost pulled out to the border (as
/// surface.vert places it).
double sample_place(std::uint32_t u, std::uint32_t n) {
    return u == 0 ? 0.0 : (u + 1 >= n ? static_cast<double>(n) : u + 0.5);
}

} // namespace

std::vector<std::uint32_t> patch_indices(std::uint32_t level, std::uint32_t skirts) {
    std::vector<std::uint32_t> idx;
    const auto all = [](std::uint32_t, std::uint32_t) { return true; };
    append_patch(level, skirts, all, all, idx);
    return idx;
}

void edge_patch_indices(const SnowSurface& s, const TileDraw& d, std::vector<std::uint32_t>& out) {
    const std::uint32_t n = patch_side(d.level), step = 1u << d.level, cut = 2 * n * n;
    // Cells and positions of the samples along each axis.
    std::vector<std::uint32_t> cx(n), cz(n);
    std::vector<double> px(n), pz(n);
    for (std::uint32_t k = 0; k < n; ++k) {
        cx[k] = std::min(static_cast<std::uint32_t>(d.first.x) + k * step, s.nx - 1);
        cz[k] = std::min(static_cast<std::uint32_t>(d.first.y) + k * step, s.nz - 1);
        px[k] = sample_place(cx[k], s.nx);
        pz[k] = sample_place(cz[k], s.nz);
    }
    const double limit = surface_edge_slope * s.cell / s.unit_height; // levels per cell of run
    const auto cell = [&](std::uint32_t x, std::uint32_t z) { return s.index(cx[x], cz[z]); };
    // True when the bare top jumps like an edge between grid samples a and b.
    const auto jumps = [&](std::uint32_t ax, std::uint32_t az, std::uint32_t bx, std::uint32_t bz) {
        const double run = std::abs(px[bx] - px[ax]) + std::abs(pz[bz] - pz[az]);
        const auto rise =
            static_cast<double>(s.base_level[cell(ax, az)] - s.base_level[cell(bx, bz)]);
        return std::abs(rise) > limit * run;
    };
    const auto bare = [&](std::uint32_t x, std::uint32_t z) {
        return s.snow[cell(x, z)] == 0 && s.snow[cell(x + 1, z)] == 0 &&
               s.snow[cell(x, z + 1)] == 0 && s.snow[cell(x + 1, z + 1)] == 0;
    };
    const auto bridges = [&](std::uint32_t x, std::uint32_t z) {
        return jumps(x, z, x + 1, z) || jumps(x, z + 1, x + 1, z + 1) || jumps(x, z, x, z + 1) ||
               jumps(x + 1, z, x + 1, z + 1);
    };
    out.clear();
    // Seam and border skirts stop at edges too, or they would hang a curtain
    // along the tile's side from eaves to the ground.
    append_patch(
        d.level, d.skirts,
        [&](std::uint32_t x, std::uint32_t z) { return !bare(x, z) && !bridges(x, z); },
        [&](std::uint32_t a, std::uint32_t b) { return !jumps(a % n, a / n, b % n, b / n); }, out);
    // A quad left out at an edge: each of its sides that does not jump is
    // where the snow on that side ends; hang it to the bare top there.
    for (std::uint32_t z = 0; z + 1 < n; ++z) {
        for (std::uint32_t x = 0; x + 1 < n; ++x) {
            if (bare(x, z) || !bridges(x, z)) {
                continue;
            }
            const std::uint32_t a = z * n + x, b = a + 1, c = a + n, e = c + 1;
            const std::array<std::array<std::uint32_t, 6>, 4> sides = {{
                {x, z, x + 1, z, a, b},
                {x, z + 1, x + 1, z + 1, c, e},
                {x, z, x, z + 1, a, c},
                {x + 1, z, x + 1, z + 1, b, e},
            }};
            for (const auto& side : sides) {
                if (!jumps(side[0], side[1], side[2], side[3])) {
                    const std::uint32_t t0 = side[4], t1 = side[5];
                    out.insert(out.end(), {t0, t0 + cut, t1, t1, t0 + cut, t1 + cut});
                }
            }
        }
    }
}

std::uint32_t patch_level(float distance, float cell, float px_per_metre, float spacing_px) {
    // Spacing of level l: 2^l · cell · px_per_metre / distance pixels.
    const float steps = spacing_px * distance / (cell * px_per_metre);
    if (!(steps >= 2.0f)) { // also NaN
        return 0;
    }
    const auto level = static_cast<std::uint32_t>(std::floor(std::log2(steps)));
    return std::min(level, surface_tile_levels - 1);
}

const std::vector<std::uint32_t>& SurfaceTiles::rescan(const SnowSurface& s) {
    changed_.clear();
    const std::uint64_t grid = well_formed(s) ? grid_fingerprint(s) : 0;
    grid_changed_ = grid != grid_;
    if (grid_changed_) {
        grid_ = grid;
        tiles_x_ = grid != 0 ? (s.nx + surface_tile_cells - 1) / surface_tile_cells : 0;
        tiles_z_ = grid != 0 ? (s.nz + surface_tile_cells - 1) / surface_tile_cells : 0;
        checksum_.assign(static_cast<std::size_t>(tiles_x_) * tiles_z_, 0);
        range_.assign(checksum_.size(), glm::vec2(1.0f, 0.0f));
        edges_.assign(checksum_.size(), 0);
        version_.assign(checksum_.size(), 0);
    }
    for (std::uint32_t t = 0; t < checksum_.size(); ++t) {
        const TileCells c = cells_of(s, t, tiles_x_);
        const std::uint64_t sum = tile_checksum(s, c);
        if (grid_changed_ || sum != checksum_[t]) {
            checksum_[t] = sum;
            changed_.push_back(t);
        }
    }
    // A tile's samples reach the first cells of its +x and +z neighbours, so
    // its height range, edge flag and index list follow theirs too.
    for (const std::uint32_t t : changed_) {
        const std::uint32_t tx = t % tiles_x_, tz = t / tiles_x_;
        for (std::uint32_t dz = 0; dz <= std::min(tz, 1u); ++dz) {
            for (std::uint32_t dx = 0; dx <= std::min(tx, 1u); ++dx) {
                const std::uint32_t u = t - dz * tiles_x_ - dx;
                const TileCells reach = reach_of(s, cells_of(s, u, tiles_x_));
                range_[u] = tile_range(s, reach);
                edges_[u] = tile_has_edges(s, reach) ? 1 : 0;
                ++version_[u];
            }
        }
    }
    return changed_;
}

std::uint64_t SurfaceTiles::select(const SnowSurface& s, const TileView& view,
                                   std::vector<TileDraw>& out) {
    out.clear();
    distance_.assign(range_.size(), -1.0f); // < 0: not drawn
    for (std::uint32_t t = 0; t < range_.size(); ++t) {
        const glm::vec2 range = range_[t];
        if (range.x > range.y) {
            continue; // no snow in the tile: the bare top below shows
        }
        const TileCells c = reach_of(s, cells_of(s, t, tiles_x_));
        const glm::vec3 lo(s.x0 + static_cast<float>(c.x0) * s.cell, range.x,
                           s.z0 + static_cast<float>(c.z0) * s.cell);
        const glm::vec3 hi(s.x0 + static_cast<float>(c.x1) * s.cell, range.y,
                           s.z0 + static_cast<float>(c.z1) * s.cell);
        if (!outside_frustum(view.view_proj, lo, hi)) {
            const glm::vec3 nearest = glm::clamp(view.eye, lo, hi) - view.eye;
            distance_[t] = std::sqrt(glm::dot(nearest, nearest));
        }
    }
    level_.assign(range_.size(), -1);
    std::uint64_t samples = 0;
    for (float spacing = view.spacing_px, widest = 32.0f * view.spacing_px;;
         spacing *= std::numbers::sqrt2_v<float>) {
        samples = 0;
        for (std::uint32_t t = 0; t < range_.size(); ++t) {
            if (distance_[t] >= 0.0f) {
                const std::uint32_t level =
                    patch_level(distance_[t], s.cell, view.px_per_metre, spacing);
                level_[t] = static_cast<std::int32_t>(level);
                samples += static_cast<std::uint64_t>(patch_side(level)) * patch_side(level);
            }
        }
        if (samples <= view.max_samples || spacing >= widest) {
            break;
        }
    }
    for (std::uint32_t t = 0; t < range_.size(); ++t) {
        if (level_[t] < 0) {
            continue;
        }
        const std::uint32_t tx = t % tiles_x_, tz = t / tiles_x_;
        // The grid's border always hangs a skirt; inside, only a level change
        // leaves cracks (a neighbour not drawn is out of sight or bare).
        const auto needs = [&](bool border, std::uint32_t across) {
            return border || (level_[across] >= 0 && level_[across] != level_[t]);
        };
        TileDraw d;
        d.first = {static_cast<int>(tx * surface_tile_cells),
                   static_cast<int>(tz * surface_tile_cells)};
        d.level = static_cast<std::uint32_t>(level_[t]);
        d.skirts = (needs(tx == 0, t - 1) ? skirt_low_x : 0u) |
                   (needs(tx + 1 == tiles_x_, t + 1) ? skirt_high_x : 0u) |
                   (needs(tz == 0, t - tiles_x_) ? skirt_low_z : 0u) |
                   (needs(tz + 1 == tiles_z_, t + tiles_x_) ? skirt_high_z : 0u);
        d.edges = edges_[t] != 0;
        d.distance = distance_[t];
        out.push_back(d);
    }
    std::sort(out.begin(), out.end(), [](const TileDraw& a, const TileDraw& b) {
        return std::tuple(a.edges, a.level, a.skirts, a.distance, a.first.y, a.first.x) <
               std::tuple(b.edges, b.level, b.skirts, b.distance, b.first.y, b.first.x);
    });
    return samples;
}

glm::uvec2 tile_texels(const SnowSurface& s, std::uint32_t tile, std::vector<float>& out) {
    const std::uint32_t tiles_x = (s.nx + surface_tile_cells - 1) / surface_tile_cells;
    const TileCells c = cells_of(s, tile, tiles_x);
    out.clear();
    out.reserve(2u * (c.x1 - c.x0) * (c.z1 - c.z0));
    for (std::uint32_t z = c.z0; z < c.z1; ++z) {
        for (std::uint32_t x = c.x0; x < c.x1; ++x) {
            const std::size_t i = s.index(x, z);
            out.push_back(s.top_y(i));
            out.push_back(s.height(s.base_level[i]));
        }
    }
    return {c.x1 - c.x0, c.z1 - c.z0};
}

} // namespace snow
