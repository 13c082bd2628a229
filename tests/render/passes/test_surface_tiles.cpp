// The CPU half of the tiled snow heightfield (render/passes/surface_tiles.hpp): patch
// index lists with skirts, the level for a distance, per-tile change
// detection, culling and the texels a tile uploads.
#include "render/passes/surface_tiles.hpp"
#include "tests/render/render_fixture.hpp"
#include <snow/render.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <map>
#include <set>
#include <tuple>
#include <utility>

namespace snow::test {
namespace {

TEST(SurfaceTiles, PatchIndicesCoverTheGridAndTheAskedSkirts) {
    for (std::uint32_t level = 0; level < surface_tile_levels; ++level) {
        const std::uint32_t n = patch_side(level);
        const std::size_t grid = static_cast<std::size_t>(n - 1) * (n - 1) * 6;
        for (std::uint32_t skirts = 0; skirts <= skirt_all; ++skirts) {
            const std::vector<std::uint32_t> idx = patch_indices(level, skirts);
            const auto edges = static_cast<std::size_t>(std::popcount(skirts));
            ASSERT_EQ(idx.size(), grid + edges * (n - 1) * 6) << level << " " << skirts;
            std::set<std::uint32_t> used(idx.begin(), idx.begin() + static_cast<long>(grid));
            EXPECT_EQ(used.size(), static_cast<std::size_t>(n) * n) << "every grid sample is drawn";
            EXPECT_EQ(*used.rbegin(), n * n - 1);
            // Skirt: each quad joins two samples of an asked edge to their copies (id + n²).
            for (std::size_t k = grid; k < idx.size(); k += 6) {
                const std::uint32_t t0 = idx[k], t1 = idx[k + 2];
                EXPECT_LT(t0, n * n);
                EXPECT_EQ(idx[k + 1], t0 + n * n);
                EXPECT_EQ(idx[k + 5], t1 + n * n);
                const std::uint32_t x0 = t0 % n, z0 = t0 / n, x1 = t1 % n, z1 = t1 / n;
                const std::uint32_t edge = x0 == 0 && x1 == 0           ? skirt_low_x
                                           : x0 == n - 1 && x1 == n - 1 ? skirt_high_x
                                           : z0 == 0 && z1 == 0         ? skirt_low_z
                                           : z0 == n - 1 && z1 == n - 1 ? skirt_high_z
                                                                        : 0u;
                EXPECT_NE(edge & skirts, 0u) << "a segment of an asked edge";
            }
        }
    }
    EXPECT_EQ(patch_side(0), surface_tile_cells + 1);
    EXPECT_EQ(patch_side(surface_tile_levels - 1), 2u);
}

TEST(SurfaceTiles, LevelGrowsWithDistanceAndStaysInRange) {
    const float ppm = 514.7f, cell = 0.05f, px = 8.0f; // 480 px high, 50° lens
    EXPECT_EQ(patch_level(0.0f, cell, ppm, px), 0u);
    EXPECT_EQ(patch_level(3.0f, cell, ppm, px), 0u);
    std::uint32_t previous = 0;
    for (float d = 0.5f; d < 500.0f; d *= 1.1f) {
        const std::uint32_t level = patch_level(d, cell, ppm, px);
        EXPECT_GE(level, previous);
        EXPECT_LT(level, surface_tile_levels);
        // The chosen spacing is at most the target (unless level 0 is already wider).
        const float spacing = static_cast<float>(1u << level) * cell * ppm / d;
        EXPECT_TRUE(spacing <= px * 1.0001f || level == 0) << d;
        previous = level;
    }
    EXPECT_EQ(previous, surface_tile_levels - 1);
    EXPECT_EQ(patch_level(std::nanf(""), cell, ppm, px), 0u);
}

SnowSurface big_surface() {
    SnowSurface s = flat_surface(-10.0f, -10.0f, 20.0f, 16.0f, 0.1f, 1.0f); // 200 × 160 cells
    for (std::size_t i = 0; i < s.snow.size(); ++i) {
        s.snow[i] = 10 + static_cast<std::uint32_t>(i % 7);
    }
    return s;
}

TEST(SurfaceTiles, RescanReportsOnlyTheTilesThatChanged) {
    SnowSurface s = big_surface();
    SurfaceTiles tiles;
    const std::uint32_t tx = 7, tz = 5; // ceil(200/32), ceil(160/32)
    EXPECT_EQ(tiles.rescan(s).size(), tx * tz);
    EXPECT_TRUE(tiles.grid_changed());
    EXPECT_EQ(tiles.tiles_x(), tx);
    EXPECT_EQ(tiles.tiles_z(), tz);
    EXPECT_TRUE(tiles.rescan(s).empty());
    EXPECT_FALSE(tiles.grid_changed());

    s.snow[s.index(40, 70)] += 1; // tile (1, 2)
    const std::vector<std::uint32_t> snow_changed = tiles.rescan(s);
    EXPECT_EQ(snow_changed, std::vector<std::uint32_t>{2 * tx + 1});
    // A unit moving to the next cell inside the tile, and one back elsewhere, still shows.
    s.snow[s.index(40, 70)] -= 1;
    s.snow[s.index(41, 70)] += 1;
    s.snow[s.index(43, 71)] -= 1;
    s.snow[s.index(42, 71)] += 1;
    EXPECT_EQ(tiles.rescan(s).size(), 1u);
    s.base_level[s.index(199, 159)] += 5; // the last, partial tile
    EXPECT_EQ(tiles.rescan(s), std::vector<std::uint32_t>{tx * tz - 1});
    EXPECT_FALSE(tiles.grid_changed());

    s.x0 += 1.0f; // the grid moved: everything is new
    EXPECT_EQ(tiles.rescan(s).size(), tx * tz);
    EXPECT_TRUE(tiles.grid_changed());
    s.snow.pop_back(); // malformed: nothing to draw
    EXPECT_TRUE(tiles.rescan(s).empty());
    EXPECT_TRUE(tiles.grid_changed());
    EXPECT_EQ(tiles.tiles_x(), 0u);
}

TEST(SurfaceTiles, HeightRangeCoversTheSnowOfTheTile) {
    SnowSurface s = big_surface();
    s.base_level[s.index(3, 4)] -= 100; // 0.2 m lower bare top
    s.snow[s.index(5, 6)] = 1000;       // 2 m of snow
    SurfaceTiles tiles;
    static_cast<void>(tiles.rescan(s));
    const glm::vec2 r = tiles.height_range(0);
    EXPECT_NEAR(r.x, 0.8f, 1e-5f);
    EXPECT_NEAR(r.y, 3.0f, 1e-5f);
    // A tile without snow has an empty range and is never drawn.
    std::fill(s.snow.begin(), s.snow.end(), 0u);
    static_cast<void>(tiles.rescan(s));
    EXPECT_GT(tiles.height_range(0).x, tiles.height_range(0).y);
    ViewCamera cam;
    cam.position = {0.0f, 8.0f, 12.0f};
    cam.look_at({0.0f, 1.0f, 0.0f});
    TileView view;
    view.view_proj = cam.projection(4.0f / 3.0f) * cam.view();
    view.eye = cam.position;
    std::vector<TileDraw> draws{TileDraw{}};
    tiles.select(s, view, draws);
    EXPECT_TRUE(draws.empty());
    // Snow in the first column of tile 1 is reached by tile 0's last samples
    // too: both are drawn (tile 0's last quads lead up to it), tile 2 is not.
    s.snow[s.index(32, 10)] = 50;
    static_cast<void>(tiles.rescan(s));
    EXPECT_LE(tiles.height_range(0).x, tiles.height_range(0).y);
    EXPECT_LE(tiles.height_range(1).x, tiles.height_range(1).y);
    EXPECT_GT(tiles.height_range(2).x, tiles.height_range(2).y);
}

TEST(SurfaceTiles, EdgeFlagsFollowJumpsOfTheBareTopIntoTheNextTile) {
    SnowSurface s = big_surface(); // 0.1 m cells: a jump over 0.2 m between cells is an edge
    SurfaceTiles tiles;
    static_cast<void>(tiles.rescan(s));
    const std::uint32_t tx = tiles.tiles_x();
    for (std::uint32_t t = 0; t < tiles.tiles_x() * tiles.tiles_z(); ++t) {
        EXPECT_FALSE(tiles.has_edges(t));
    }
    // A 1 m step between cell columns 63 and 64: tile column 1 samples column
    // 64 (its last samples are the next tile's first), tile column 2 starts on it.
    for (std::uint32_t z = 0; z < s.nz; ++z) {
        for (std::uint32_t x = 64; x < s.nx; ++x) {
            s.base_level[s.index(x, z)] += 500;
        }
    }
    static_cast<void>(tiles.rescan(s));
    for (std::uint32_t t = 0; t < tiles.tiles_x() * tiles.tiles_z(); ++t) {
        EXPECT_EQ(tiles.has_edges(t), t % tx == 1) << "tile " << t;
    }
    // A gentle slope (0.1 m per cell) is no edge; the step, gone again, clears the flags.
    for (std::uint32_t z = 0; z < s.nz; ++z) {
        for (std::uint32_t x = 0; x < s.nx; ++x) {
            s.base_level[s.index(x, z)] = 500 + 50 * static_cast<std::int64_t>(x);
        }
    }
    static_cast<void>(tiles.rescan(s));
    for (std::uint32_t t = 0; t < tiles.tiles_x() * tiles.tiles_z(); ++t) {
        EXPECT_FALSE(tiles.has_edges(t)) << "tile " << t;
    }
}

TEST(SurfaceTiles, SelectCullsAndCoarsensWithDistance) {
    SnowSurface s = flat_surface(-100.0f, -100.0f, 200.0f, 200.0f, 0.25f, 0.0f); // 800² cells
    std::fill(s.snow.begin(), s.snow.end(), 50u);
    SurfaceTiles tiles;
    static_cast<void>(tiles.rescan(s));
    ViewCamera cam;
    cam.position = {0.0f, 3.0f, 0.0f};
    cam.look_at({0.0f, 0.0f, -20.0f}); // looking along −z
    TileView view;
    view.view_proj = cam.projection(4.0f / 3.0f) * cam.view();
    view.eye = cam.position;
    view.px_per_metre = 514.7f;
    view.spacing_px = 8.0f;
    std::vector<TileDraw> draws;
    const std::uint64_t samples = tiles.select(s, view, draws);
    std::size_t drawn = 0;
    std::uint32_t max_level = 0;
    std::set<std::pair<int, int>> seen;
    for (std::size_t k = 0; k < draws.size(); ++k) {
        const TileDraw& d = draws[k];
        ++drawn;
        EXPECT_TRUE(seen.emplace(d.first.x, d.first.y).second) << "each tile once";
        if (k > 0) {
            const TileDraw& p = draws[k - 1];
            EXPECT_LE(std::tuple(p.edges, p.level, p.skirts),
                      std::tuple(d.edges, d.level, d.skirts))
                << "tiles drawn alike are adjacent";
        }
        const float z = s.z0 + (static_cast<float>(d.first.y) + 16.0f) * s.cell;
        EXPECT_LT(z, 12.0f) << "tiles behind the camera are culled";
        const float x = s.x0 + (static_cast<float>(d.first.x) + 16.0f) * s.cell;
        const float dist = std::hypot(x, z);
        // Level l starts where 2^l cells project to 8 px: 16 m · 2^l here.
        if (d.level == 0) {
            EXPECT_LT(dist, 40.0f) << "only near tiles at full detail";
        }
        if (dist > 80.0f) {
            EXPECT_GE(d.level, 2u) << "far tiles are coarse";
        }
        max_level = std::max(max_level, d.level);
        EXPECT_FALSE(d.edges) << "a flat grid has no edge";
    }
    // Skirts exactly where a drawn neighbour has another level (or at the border).
    std::map<std::pair<int, int>, std::uint32_t> level_at;
    for (const TileDraw& d : draws) {
        level_at[{d.first.x, d.first.y}] = d.level;
    }
    const int t = static_cast<int>(surface_tile_cells);
    for (const TileDraw& d : draws) {
        const auto differs = [&](int dx, int dz) {
            const auto it = level_at.find({d.first.x + dx * t, d.first.y + dz * t});
            return it != level_at.end() && it->second != d.level;
        };
        EXPECT_EQ((d.skirts & skirt_low_x) != 0, d.first.x == 0 || differs(-1, 0));
        EXPECT_EQ((d.skirts & skirt_high_x) != 0,
                  d.first.x + t >= static_cast<int>(s.nx) || differs(1, 0));
        EXPECT_EQ((d.skirts & skirt_low_z) != 0, d.first.y == 0 || differs(0, -1));
        EXPECT_EQ((d.skirts & skirt_high_z) != 0,
                  d.first.y + t >= static_cast<int>(s.nz) || differs(0, 1));
    }
    EXPECT_GT(drawn, 10u);
    EXPECT_LT(drawn, tiles.tiles_x() * tiles.tiles_z() / 2) << "most of the grid is culled";
    EXPECT_GE(max_level, 2u) << "the farthest tiles, over 100 m away";
    std::uint64_t counted = 0;
    for (const TileDraw& d : draws) {
        counted += static_cast<std::uint64_t>(patch_side(d.level)) * patch_side(d.level);
    }
    EXPECT_EQ(samples, counted);

    // A sample budget widens the spacing until the tiles fit it: coarser levels, fewer samples.
    view.max_samples = static_cast<std::uint32_t>(samples / 4);
    std::vector<TileDraw> budget;
    const std::uint64_t fewer = tiles.select(s, view, budget);
    EXPECT_LE(fewer, view.max_samples);
    EXPECT_EQ(budget.size(), draws.size()) << "the same tiles, only coarser";
    std::map<std::pair<int, int>, std::uint32_t> coarse;
    for (const TileDraw& d : budget) {
        coarse[{d.first.x, d.first.y}] = d.level;
    }
    for (const TileDraw& d : draws) {
        EXPECT_GE((coarse[{d.first.x, d.first.y}]), d.level);
    }
}

TEST(SurfaceTiles, TexelsHoldSnowTopAndBareTopOfEachCell) {
    SnowSurface s = flat_surface(0.0f, 0.0f, 4.0f, 3.6f, 0.1f, 1.0f); // 40 × 36 cells
    s.snow[s.index(33, 35)] = 100;                                    // in tile (1, 1)
    std::vector<float> texels;
    const glm::uvec2 size = tile_texels(s, 3, texels); // tile (1, 1): cells 32..39 × 32..35
    EXPECT_EQ(size, glm::uvec2(8, 4));
    ASSERT_EQ(texels.size(), 2u * 8u * 4u);
    const std::size_t at = 2 * (3 * 8 + 1); // row 35 − 32, column 33 − 32
    EXPECT_NEAR(texels[at], 1.2f, 1e-5f);
    EXPECT_NEAR(texels[at + 1], 1.0f, 1e-5f);
    EXPECT_NEAR(texels[0], 1.0f, 1e-5f);
}

} // namespace
} // namespace snow::test
