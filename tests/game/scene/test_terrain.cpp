// A terrain from a 16-bit height map (scenes[s].extras.snow.world,
// docs/world.md): its mesh and collider span the extent and height range,
// a flake lands on it at the sample's height, and every bad input is one
// error naming the field, with no simulation.
#include "tests/game/scene/png_bytes.hpp"
#include "tests/game/scene/scene_test_files.hpp"
#include "tests/support/run_app.hpp"

#include "systems/api/simulation_internals.hpp"
#include "systems/geometry/colliders.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace snow::test {
namespace {

constexpr const char* heightmap_field = "scenes[0].extras.snow.world.heightmap";

/// A scene with only a terrain: `world` is the JSON of `extras.snow.world`.
std::string terrain_gltf(const std::string& world) {
    return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [],
        "extras": {"snow": {
          "simulation": {"dt": 0.016666666666666666, "max_flakes": 16,
                         "bounds": {"min": [-20, 0, -15], "max": [20, 25, 15]}},
          "world": )" +
           world + "}}}]}";
}

/// 5 × 4 samples over 40 × 30 m, 10 to 20 m high: grey 0 and 65535 both occur.
const std::vector<std::uint16_t> samples{
    0,     8000,  16000, 24000, 32000, //
    4000,  12000, 20000, 28000, 36000, //
    8000,  16000, 24000, 32000, 40000, //
    12000, 20000, 28000, 36000, 65535,
};
const std::string good_world = R"({"heightmap": "h.png", "extent": [40, 30], "height": [10, 20]})";

struct Scene {
    TempDir dir;
    std::string path;
    SceneLoadResult load(const std::string& world, const std::string& png,
                         const SceneOverrides& o = {}) {
        path = (dir.scene_dir() / "t.gltf").string();
        dir.write(path, terrain_gltf(world));
        if (!png.empty()) {
            dir.write(dir.scene_dir() / "h.png", png);
        }
        return load_scene_file(path, o);
    }
};

/// Height (m) of sample (i, j) of `samples`.
double sample_height(std::uint32_t i, std::uint32_t j) {
    return 10.0 + 10.0 * samples[j * 5 + i] / 65535.0;
}

TEST(Terrain, MeshAndColliderSpanTheExtentAndHeightRange) {
    Scene s;
    const SceneLoadResult r = s.load(good_world, height_png(5, 4, samples));
    ASSERT_NE(r.sim, nullptr) << r.error;
    const auto mesh =
        std::ranges::find(r.visuals.meshes, std::string("terrain"), &MeshRenderable::name);
    ASSERT_NE(mesh, r.visuals.meshes.end());
    EXPECT_EQ(mesh->positions.size(), 20u);
    EXPECT_EQ(mesh->normals.size(), 20u);
    EXPECT_EQ(mesh->indices.size(), 4u * 3u * 2u * 3u);
    // Row 0 at minimum z, column 0 at minimum x.
    EXPECT_EQ(mesh->positions[0], glm::vec3(-20.0f, 10.0f, -15.0f));
    EXPECT_EQ(mesh->positions[19], glm::vec3(20.0f, 20.0f, 15.0f));
    for (const glm::vec3& n : mesh->normals) {
        EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
        EXPECT_GT(n.y, 0.0f);
    }
    const auto& world = world_of(*r.sim);
    std::size_t colliders = 0;
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
    world.each<MeshCollider>([&](Entity, const MeshCollider& m) {
        ++colliders;
        EXPECT_EQ(m.triangles.size(), 4u * 3u * 2u * 3u);
        for (const glm::vec3& p : m.triangles) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    });
    EXPECT_EQ(colliders, 1u);
    EXPECT_EQ(lo, glm::vec3(-20.0f, 10.0f, -15.0f));
    EXPECT_EQ(hi, glm::vec3(20.0f, 20.0f, 15.0f));
}

TEST(Terrain, TrianglesFaceUp) {
    Scene s;
    const SceneLoadResult r = s.load(good_world, height_png(5, 4, samples));
    ASSERT_NE(r.sim, nullptr) << r.error;
    const MeshRenderable& m = r.visuals.meshes.back();
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f) << "triangle " << t / 3;
    }
}

TEST(Terrain, AFlakeLandsAtTheSampleHeight) {
    // Sample (2, 1) at x = 0, z = -5; its neighbours differ by under 1.3 m
    // over 10 m, so the sky map's texel (40 m / 256) moves the top by a few cm.
    Scene s;
    SceneLoadResult r = s.load(good_world, height_png(5, 4, samples));
    ASSERT_NE(r.sim, nullptr) << r.error;
    const double h = sample_height(2, 1);
    ASSERT_TRUE(r.sim->place_flake(
        {{0.0f, static_cast<float>(h) + 0.5f, -5.0f}, {0.0f, -1.0f, 0.0f}, 9.81f, 0.005f, 10}));
    float last_y = 0.0f;
    for (int t = 0; t < 600 && r.sim->flakes().alive > 0; ++t) {
        const FlakesView f = r.sim->flakes();
        for (std::size_t k = 0; k < f.slots(); ++k) {
            if (f.mass_units[k] != 0) {
                last_y = f.y[k];
            }
        }
        r.sim->tick();
    }
    EXPECT_EQ(r.sim->flakes().alive, 0u) << "the flake never met the terrain";
    // The last height seen is above the top and less than one tick's fall
    // (1/60 m at 1 m/s) plus the texel's share of the slope above it.
    EXPECT_GE(last_y, h - 0.05);
    EXPECT_LE(last_y, h + 0.05);
}

TEST(Terrain, DefaultBoundsCoverTheTerrain) {
    Scene s;
    const std::string gltf = R"({"heightmap": "h.png", "extent": [40, 30], "height": [10, 20]})";
    s.dir.write(s.dir.scene_dir() / "h.png", height_png(5, 4, samples));
    const std::string path = (s.dir.scene_dir() / "d.gltf").string();
    s.dir.write(path, R"({"asset": {"version": "2.0"}, "scenes": [{"extras": {"snow": {"world": )" +
                          gltf + "}}}]}");
    const SceneLoadResult r = load_scene_file(path);
    ASSERT_NE(r.sim, nullptr) << r.error;
    const Aabb b = r.sim->config().bounds;
    EXPECT_EQ(b.min, glm::vec3(-21.0f, 9.0f, -16.0f));
    EXPECT_EQ(b.max, glm::vec3(21.0f, 24.0f, 16.0f));
}

TEST(Terrain, CountsInTheWorkBudget) {
    Scene s;
    SceneOverrides o;
    o.budget.collider_triangles = 10;
    expect_error(s.load(good_world, height_png(5, 4, samples), o),
                 {heightmap_field, "24 mesh collider triangles", "collider_triangles"});
}

TEST(TerrainValley, LoadsItsKilometresOfTerrainUnderTheVillage) {
    const SceneLoadResult r = load_scene_file(asset_path("valley.gltf"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    const auto terrain =
        std::ranges::find(r.visuals.meshes, std::string("terrain"), &MeshRenderable::name);
    ASSERT_NE(terrain, r.visuals.meshes.end());
    EXPECT_EQ(terrain->positions.size(), 257u * 257u);
    glm::vec3 lo(std::numeric_limits<float>::infinity()), hi(-lo);
    for (const glm::vec3& p : terrain->positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    EXPECT_EQ(lo.x, -2000.0f);
    EXPECT_EQ(hi.z, 2000.0f);
    EXPECT_GT(lo.y, 0.0f); // inside the declared [0, 400] m, hills well above the floor
    EXPECT_LT(hi.y, 400.0f);
    EXPECT_GT(hi.y - lo.y, 200.0f);
    // The houses stand on the terrace: their walls' bottoms at the terrain there.
    const auto walls =
        std::ranges::find(r.visuals.meshes, std::string("house 0 walls"), &MeshRenderable::name);
    ASSERT_NE(walls, r.visuals.meshes.end());
    float wall_bottom = std::numeric_limits<float>::infinity();
    for (const glm::vec3& p : walls->positions) {
        wall_bottom = std::min(wall_bottom, p.y);
    }
    const glm::vec3 at = walls->positions.front();
    float nearest = std::numeric_limits<float>::infinity(), ground = 0.0f;
    for (const glm::vec3& p : terrain->positions) {
        const float d = glm::length(glm::vec2(p.x - at.x, p.z - at.z));
        if (d < nearest) {
            nearest = d;
            ground = p.y;
        }
    }
    EXPECT_NEAR(wall_bottom, ground, 1e-3f);
}

TEST(TerrainValley, AssetsAreUpToDate) {
    const int status = std::system(
        ("python3 " + std::string(SNOW_SOURCE_DIR) + "/scripts/make_assets.py --check 2>&1")
            .c_str());
    EXPECT_EQ(status, 0) << "assets/scenes is stale: run python3 scripts/make_assets.py";
}

// --- bad input: one error naming the field, no simulation ---------------------

TEST(TerrainErrors, MissingFile) {
    Scene s;
    expect_error(s.load(good_world, ""), {heightmap_field, "'h.png'", "not a file"});
}

TEST(TerrainErrors, FileOutsideTheFolder) {
    Scene s;
    expect_error(s.load(R"({"heightmap": "../h.png", "extent": [40, 30], "height": [10, 20]})",
                        height_png(5, 4, samples)),
                 {heightmap_field, "must not leave the scene's folder"});
}

TEST(TerrainErrors, NotAPng) {
    Scene s;
    expect_error(s.load(good_world, "P2 5 4 65535\n"), {heightmap_field, "is not a PNG"});
}

TEST(TerrainErrors, BrokenPng) {
    Scene s;
    std::string png = height_png(5, 4, samples);
    png.resize(40);
    expect_error(s.load(good_world, png), {heightmap_field, "is not a valid PNG"});
}

TEST(TerrainErrors, NotSixteenBitGrey) {
    const std::vector<unsigned char> grey8(20, 7), rgb16(5 * 4 * 6, 7), grey_alpha16(5 * 4 * 4, 7);
    const std::pair<std::string, std::string> cases[] = {
        {png_bytes(5, 4, 8, 0, grey8), "(got 8-bit grey)"},
        {png_bytes(5, 4, 16, 2, rgb16), "(got RGB)"},
        {png_bytes(5, 4, 16, 4, grey_alpha16), "(got grey with alpha)"},
    };
    for (const auto& [png, got] : cases) {
        Scene s;
        expect_error(s.load(good_world, png), {heightmap_field, "must be a 16-bit grey PNG", got});
    }
}

TEST(TerrainErrors, TooFewOrTooManySamples) {
    Scene small;
    expect_error(small.load(good_world, height_png(1, 3, {1, 2, 3})),
                 {heightmap_field, "is 1 x 3 samples", "at least 2 x 2"});
    // Refused from the header alone: no pixel data is ever decoded.
    Scene large;
    expect_error(large.load(good_world, png_bytes(8193, 8192, 16, 0, {})),
                 {heightmap_field, "is 8193 x 8192 samples", "at most 67108864"});
}

TEST(TerrainErrors, BadExtent) {
    const std::pair<std::string, std::string> cases[] = {
        {"[0, 30]", "extent[0] must be in (0, 64000] (got 0)"},
        {"[40, -1]", "extent[1] must be in (0, 64000] (got -1)"},
        {"[64001, 30]", "extent[0] must be in (0, 64000] (got 64001)"},
        // JSON has no NaN or infinity: a spelled-out one is a string.
        {"[40, \"NaN\"]", "extent[1] must be a number (got string)"},
        {"[40]", "extent must be [x, z] (got 1 numbers)"},
        {"40", "extent must be an array"},
    };
    for (const auto& [extent, message] : cases) {
        Scene s;
        expect_error(
            s.load(R"({"heightmap": "h.png", "extent": )" + extent + R"(, "height": [10, 20]})",
                   height_png(5, 4, samples)),
            {"scenes[0].extras.snow.world." + message});
    }
}

TEST(TerrainErrors, BadHeightRange) {
    const std::pair<std::string, std::string> cases[] = {
        {"[20, 10]", "height max must be >= min (got [20, 10])"},
        {"[10, \"NaN\"]", "height[1] must be a number (got string)"},
        {"[-1e39, 10]", "height[0] must be in [-100000, 100000] (got -1e+39)"},
        {"[10, 20, 30]", "height must be [min, max] (got 3 numbers)"},
    };
    for (const auto& [height, message] : cases) {
        Scene s;
        expect_error(
            s.load(R"({"heightmap": "h.png", "extent": [40, 30], "height": )" + height + "}",
                   height_png(5, 4, samples)),
            {"scenes[0].extras.snow.world." + message});
    }
}

TEST(TerrainErrors, MissingAndUnknownFields) {
    Scene a;
    expect_error(a.load(R"({"extent": [40, 30], "height": [10, 20]})", ""),
                 {heightmap_field, "is required"});
    Scene b;
    expect_error(b.load(R"({"heightmap": "h.png", "extent": [40, 30], "height": [10, 20],
                            "origin": [0, 0]})",
                        ""),
                 {"scenes[0].extras.snow.world", "origin"});
}

TEST(TerrainErrors, FromMemoryNoFileIsRead) {
    const SceneLoadResult r = load_scene_memory(terrain_gltf(good_world), "mem.gltf");
    expect_error(r, {"mem.gltf: ", heightmap_field, "loaded from memory"});
}

TEST(TerrainErrors, SnowRunExitsTwo) {
    Scene s;
    (void)s.load(good_world, height_png(1, 3, {1, 2, 3}));
    const AppRun r = run_app("game/snow_run", "--scene " + s.path + " --ticks 1");
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find(heightmap_field), std::string::npos) << r.out;
}

} // namespace
} // namespace snow::test
