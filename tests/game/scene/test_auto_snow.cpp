// Snow on a plain scene (issue 13): with SceneOverrides::auto_snow, or
// `extras.snow.auto` in the file, a model without any snow extras gets mesh
// colliders, an occlusion camera, a snow cover, an emitter and a camera, and
// its snow settles on the meshes' tops with the usual promises (exact mass,
// thread- and save/restore-independent hashes). Without it nothing changes.
#include "systems/api/simulation_internals.hpp"
#include "tests/game/scene/scene_test_files.hpp"
#include "tests/support/run_app.hpp"

#include "systems/geometry/colliders.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace snow {
namespace {

using namespace snow::test;

/// The two exporter-shaped files of assets/testdata: their nodes with a mesh,
/// and a base height (m) under a raised mesh top: the crate's (y = 1) and the
/// slab's (1.1).
struct PlainFile {
    const char* name;
    std::size_t mesh_nodes;
    float raised_top;
};
constexpr PlainFile plain_files[] = {{"tool_export.glb", 3, 0.9f}, {"plain.gltf", 2, 0.9f}};

/// 20 Hz keeps the fall from the top of the bounds to the meshes short.
constexpr float test_dt = 0.05f;
constexpr int test_ticks = 160;

SceneOverrides auto_overrides(unsigned threads = 1) {
    SceneOverrides o;
    o.auto_snow = true;
    o.dt = test_dt;
    o.threads = threads;
    return o;
}

std::vector<CoverId> covers(const Simulation& sim) {
    std::vector<CoverId> out;
    world_of(sim).each<SnowCover>(
        [&](Entity e, const SnowCover&) { out.push_back(id_of<CoverId>(e)); });
    return out;
}

/// True when some cover cell whose bare base is above `y` holds snow.
bool snow_on_a_top_above(const Simulation& sim, float y) {
    bool found = false;
    world_of(sim).each<SnowCover, SnowSurface>([&](Entity, const SnowCover&, const SnowSurface& s) {
        for (std::size_t i = 0; i < s.cell_count(); ++i) {
            found = found || (!s.is_void(i) && s.snow[i] > 0 && s.height(s.base_level[i]) > y);
        }
    });
    return found;
}

/// `path` with `snow` added as `extras.snow` of its first scene (or of
/// `asset` when `at_asset`), saved into `dir` beside the buffers it needs.
fs::path with_auto_extra(const TempDir& dir, const std::string& name, bool at_asset,
                         const std::string& snow = R"({"auto": true})") {
    const std::string bytes = read_text(test_data_path(name));
    const bool is_glb_file = bytes.rfind("glTF", 0) == 0;
    std::string json_text = bytes;
    std::vector<unsigned char> bin;
    if (is_glb_file) { // header, then JSON and BIN chunks (glTF 2.0 §4.4)
        const auto u32 = [&](std::size_t at) {
            std::uint32_t v = 0;
            std::memcpy(&v, bytes.data() + at, 4);
            return v;
        };
        const std::uint32_t json_length = u32(12);
        json_text = bytes.substr(20, json_length);
        const std::size_t bin_at = 20 + json_length;
        bin.assign(bytes.begin() + static_cast<std::ptrdiff_t>(bin_at + 8),
                   bytes.begin() + static_cast<std::ptrdiff_t>(bin_at + 8 + u32(bin_at)));
    }
    nlohmann::json doc = nlohmann::json::parse(json_text);
    nlohmann::json& owner = at_asset ? doc["asset"] : doc["scenes"][0];
    owner["extras"]["snow"] = nlohmann::json::parse(snow);
    const fs::path out = dir.scene_dir() / name;
    dir.write(out, is_glb_file ? glb(doc.dump(), bin) : doc.dump());
    if (!is_glb_file) { // its buffer and its texture beside it
        fs::copy_file(test_data_path("plain.bin"), dir.scene_dir() / "plain.bin",
                      fs::copy_options::overwrite_existing);
        fs::create_directories(dir.scene_dir() / "textures");
        fs::copy_file(test_data_path("textures/bark.png"), dir.scene_dir() / "textures/bark.png",
                      fs::copy_options::overwrite_existing);
    }
    return out;
}

TEST(AutoSnow, PlainFilesCatchSnowOnTheirMeshTops) {
    for (const PlainFile& f : plain_files) {
        SCOPED_TRACE(f.name);
        const SceneLoadResult r = load_scene_file(test_data_path(f.name), auto_overrides());
        ASSERT_NE(r.sim, nullptr) << r.error;
        const World& w = world_of(*r.sim);
        EXPECT_EQ(w.count<MeshCollider>(), f.mesh_nodes);
        EXPECT_EQ(w.count<Emitter>(), 1u);
        ASSERT_NE(w.try_resource<OcclusionCamera>(), nullptr);
        ASSERT_EQ(covers(*r.sim).size(), 1u);
        for (int t = 0; t < test_ticks; ++t) {
            r.sim->tick();
            const MassReport m = r.sim->mass();
            ASSERT_TRUE(m.balanced())
                << "tick " << t << ": " << m.spawned << " != " << m.airborne << " + " << m.settled
                << " + " << m.carried << " + " << m.removed;
        }
        const SnowSurface& cover = snow_surface(*r.sim, covers(*r.sim)[0]);
        EXPECT_GT(cover.settled_units(), 0u);
        EXPECT_TRUE(snow_on_a_top_above(*r.sim, f.raised_top));
        EXPECT_EQ(r.sim->nonfinite_count(), 0u);
    }
}

TEST(AutoSnow, CoverSpansTheFootprintAndTheCameraFramesIt) {
    const SceneLoadResult r = load_scene_file(test_data_path("tool_export.glb"), auto_overrides());
    ASSERT_NE(r.sim, nullptr) << r.error;
    // The ground is 12 × 12 m around the origin: 0.05 m cells, 240 per side.
    const SnowSurface& cover = snow_surface(*r.sim, covers(*r.sim)[0]);
    EXPECT_FLOAT_EQ(cover.x0, -6.0f);
    EXPECT_FLOAT_EQ(cover.z0, -6.0f);
    EXPECT_FLOAT_EQ(cover.cell, 0.05f);
    EXPECT_EQ(cover.nx, 240u);
    EXPECT_EQ(cover.nz, 240u);
    // Bounds: the meshes' (tree apex at 3.5 m) plus the default margin and headroom.
    EXPECT_FLOAT_EQ(r.sim->config().bounds.max.y, 3.5f + 4.0f);
    EXPECT_FLOAT_EQ(r.sim->config().bounds.min.x, -7.0f);
    const CameraDef& cam = r.visuals.camera;
    EXPECT_GT(cam.position.z, 6.0f); // in front of the yard
    EXPECT_GT(cam.position.y, 3.5f); // above it
    EXPECT_NEAR(cam.target.x, 0.0f, 1e-5f);
    EXPECT_NEAR(cam.target.y, 1.75f, 1e-5f);
}

TEST(AutoSnow, LargeFootprintKeepsTheCoverUnder1024CellsASide) {
    // One 300 × 120 m quad: cells of 0.3 m (300 / 1024 = 0.293, rounded up
    // to whole centimetres), 1000 × 400 of them.
    std::vector<float> big = quad_xyz;
    for (std::size_t i = 0; i < big.size(); i += 3) {
        big[i] *= 300.0f;
        big[i + 2] *= 120.0f;
    }
    const SceneLoadResult r =
        load_scene_memory(mesh_gltf(big, quad_indices), "big.gltf", auto_overrides());
    ASSERT_NE(r.sim, nullptr) << r.error;
    const SnowSurface& cover = snow_surface(*r.sim, covers(*r.sim)[0]);
    EXPECT_FLOAT_EQ(cover.cell, 0.3f);
    EXPECT_EQ(cover.nx, 1000u);
    EXPECT_EQ(cover.nz, 400u);
    // The emitter never asks for more flakes than about half the pool holds.
    float rate = 0.0f;
    world_of(*r.sim).each<Emitter>([&](Entity, const Emitter& e) { rate = e.rate; });
    const float fall_seconds = r.sim->config().bounds.size().y / 1.0f;
    EXPECT_LE(rate * fall_seconds, 0.5f * static_cast<float>(r.sim->config().max_flakes) + 1.0f);
    EXPECT_GT(rate, 0.0f);
}

TEST(AutoSnow, SameHashForOneAndTwoThreadsAndAfterRestore) {
    for (const PlainFile& f : plain_files) {
        SCOPED_TRACE(f.name);
        const SceneLoadResult one = load_scene_file(test_data_path(f.name), auto_overrides(1));
        const SceneLoadResult two = load_scene_file(test_data_path(f.name), auto_overrides(2));
        ASSERT_NE(one.sim, nullptr) << one.error;
        ASSERT_NE(two.sim, nullptr) << two.error;
        one.sim->run(test_ticks / 2);
        two.sim->run(test_ticks / 2);
        ASSERT_EQ(one.sim->state_hash(), two.sim->state_hash());
        const auto snap = save_snapshot(*one.sim);
        one.sim->run(test_ticks / 2);
        two.sim->run(test_ticks / 2);
        const std::uint64_t end = one.sim->state_hash();
        EXPECT_EQ(end, two.sim->state_hash());
        EXPECT_GT(one.sim->mass().settled, 0u);
        restore_snapshot(*one.sim, *snap);
        one.sim->run(test_ticks / 2);
        EXPECT_EQ(one.sim->state_hash(), end);
    }
}

TEST(AutoSnow, WithoutItThePlainFilesHaveNoSnow) {
    for (const PlainFile& f : plain_files) {
        SCOPED_TRACE(f.name);
        const SceneLoadResult r = load_scene_file(test_data_path(f.name));
        ASSERT_NE(r.sim, nullptr) << r.error;
        const World& w = world_of(*r.sim);
        EXPECT_TRUE(covers(*r.sim).empty());
        EXPECT_EQ(w.count<MeshCollider>() + w.count<Emitter>(), 0u);
        EXPECT_EQ(w.try_resource<OcclusionCamera>(), nullptr);
        EXPECT_EQ(r.visuals.camera.position, CameraDef{}.position);
        // The override set to false is the same as not asking.
        SceneOverrides off;
        off.auto_snow = false;
        const SceneLoadResult o = load_scene_file(test_data_path(f.name), off);
        ASSERT_NE(o.sim, nullptr) << o.error;
        EXPECT_EQ(o.sim->state_hash(), r.sim->state_hash());
    }
}

TEST(AutoSnow, FileExtraDoesWhatTheOverrideDoes) {
    TempDir dir;
    SceneOverrides only_dt;
    only_dt.dt = test_dt;
    for (const PlainFile& f : plain_files) {
        // plain.gltf has no `scenes`: only the asset level applies to it.
        for (const bool at_asset : {true, false}) {
            if (!at_asset && std::string(f.name) == "plain.gltf") {
                continue;
            }
            SCOPED_TRACE(std::string(f.name) + (at_asset ? " asset" : " scene"));
            fs::remove_all(dir.scene_dir());
            fs::create_directories(dir.scene_dir());
            const SceneLoadResult by_file =
                load_scene_file(with_auto_extra(dir, f.name, at_asset).string(), only_dt);
            const SceneLoadResult by_flag =
                load_scene_file(test_data_path(f.name), auto_overrides());
            ASSERT_NE(by_file.sim, nullptr) << by_file.error;
            ASSERT_NE(by_flag.sim, nullptr) << by_flag.error;
            ASSERT_EQ(covers(*by_file.sim).size(), 1u);
            by_file.sim->run(test_ticks);
            by_flag.sim->run(test_ticks);
            EXPECT_EQ(by_file.sim->state_hash(), by_flag.sim->state_hash());
            EXPECT_GT(by_file.sim->mass().settled, 0u);
            // The override turns the file's request off.
            SceneOverrides off = only_dt;
            off.auto_snow = false;
            const SceneLoadResult no =
                load_scene_file(with_auto_extra(dir, f.name, at_asset).string(), off);
            ASSERT_NE(no.sim, nullptr) << no.error;
            EXPECT_TRUE(covers(*no.sim).empty());
        }
    }
}

TEST(AutoSnow, DeclaredPartsKeepTheirOwnDeclaration) {
    const SceneLoadResult plain = load_scene_file(asset_path("village.gltf"));
    SceneOverrides o;
    o.auto_snow = true;
    const SceneLoadResult with = load_scene_file(asset_path("village.gltf"), o);
    ASSERT_NE(plain.sim, nullptr) << plain.error;
    ASSERT_NE(with.sim, nullptr) << with.error;
    // The village declares its emitter, occlusion camera, cover and camera,
    // which stay as they are; its two porch posts, meshes without a role,
    // become mesh colliders. Its declared roles stay too.
    const World& a = world_of(*plain.sim);
    const World& b = world_of(*with.sim);
    EXPECT_EQ(b.count<MeshCollider>(), a.count<MeshCollider>() + 2);
    EXPECT_EQ(b.count<BoxCollider>(), a.count<BoxCollider>());
    EXPECT_EQ(b.count<SphereCollider>(), a.count<SphereCollider>());
    EXPECT_EQ(b.count<SnowSurface>(), a.count<SnowSurface>());
    EXPECT_EQ(b.count<Emitter>(), 1u);
    b.each<Emitter>([&](Entity, const Emitter& e) {
        a.each<Emitter>([&](Entity, const Emitter& declared) { EXPECT_EQ(e.rate, declared.rate); });
    });
    ASSERT_EQ(covers(*with.sim).size(), 1u);
    EXPECT_EQ(snow_surface(*with.sim, covers(*with.sim)[0]).cell,
              snow_surface(*plain.sim, covers(*plain.sim)[0]).cell);
    EXPECT_EQ(b.resource<OcclusionCamera>().resolution, a.resource<OcclusionCamera>().resolution);
    EXPECT_EQ(with.visuals.camera.position, plain.visuals.camera.position);
    with.sim->run(60);
    EXPECT_TRUE(with.sim->mass().balanced());

    // A scene declaring only a cover and an emitter keeps both; its bare mesh
    // still becomes a collider and it gets the occlusion camera.
    const std::string scene =
        replaced(mesh_gltf(quad_xyz, quad_indices), R"("scenes": [{"nodes": [0]}])",
                 R"("scenes": [{"nodes": [0], "extras": {"snow": {"auto": true,
            "cover": {"min": [0, 0], "max": [1, 1], "cell": 0.1},
            "emitter": {"rate": 123}}}}])");
    const SceneLoadResult r = load_scene_memory(scene, "own.gltf");
    ASSERT_NE(r.sim, nullptr) << r.error;
    const SnowSurface& cover = snow_surface(*r.sim, covers(*r.sim)[0]);
    EXPECT_FLOAT_EQ(cover.cell, 0.1f);
    EXPECT_EQ(covers(*r.sim).size(), 1u);
    world_of(*r.sim).each<Emitter>([](Entity, const Emitter& e) { EXPECT_EQ(e.rate, 123.0f); });
    EXPECT_EQ(world_of(*r.sim).count<MeshCollider>(), 1u);
    EXPECT_NE(world_of(*r.sim).try_resource<OcclusionCamera>(), nullptr);
}

TEST(AutoSnow, BadCombinationsNameTheField) {
    // Not a boolean, at either level.
    const std::string quad = mesh_gltf(quad_xyz, quad_indices);
    expect_error(load_scene_memory(replaced(quad, R"("scenes": [{"nodes": [0]}])",
                                            R"("scenes": [{"nodes": [0],
                                                "extras": {"snow": {"auto": "yes"}}}])"),
                                   "t.gltf"),
                 {"t.gltf: scenes[0].extras.snow.auto must be true or false (got string)"});
    expect_error(
        load_scene_memory(replaced(quad, R"("version": "2.0"})",
                                   R"("version": "2.0", "extras": {"snow": {"auto": 1}}})"),
                          "t.gltf"),
        {"t.gltf: asset.extras.snow.auto must be true or false (got integer)"});
    // The asset level holds nothing else.
    expect_error(
        load_scene_memory(replaced(quad, R"("version": "2.0"})",
                                   R"("version": "2.0", "extras": {"snow": {"cover": {}}}})"),
                          "t.gltf"),
        {"t.gltf: asset.extras.snow", "cover"});
    // Nothing to snow on: no triangle mesh at all.
    const std::string empty =
        R"({"asset": {"version": "2.0"}, "scenes": [{"nodes": [0]}], "nodes": [{"name": "empty"}]})";
    expect_error(load_scene_memory(empty, "e.gltf", auto_overrides()),
                 {"e.gltf: auto_snow (command-line override) asks for snow on the scene's meshes, "
                  "but the scene has no triangle mesh"});
    expect_error(
        load_scene_memory(replaced(empty, R"("version": "2.0"})",
                                   R"("version": "2.0", "extras": {"snow": {"auto": true}}})"),
                          "e.gltf"),
        {"e.gltf: asset.extras.snow.auto asks for snow on the scene's meshes"});
    // What auto snow makes is named by it: a 300 m cover of 0.3 m cells made
    // ten times finer by the cell_scale override is over the cover's limit.
    std::vector<float> big = quad_xyz;
    for (float& v : big) {
        v *= 300.0f;
    }
    SceneOverrides fine = auto_overrides();
    fine.cell_scale = 0.1f;
    expect_error(load_scene_memory(mesh_gltf(big, quad_indices), "big.gltf", fine),
                 {"big.gltf: auto_snow (command-line override): cover cells (extent / cell) "
                  "must be <= 16777216"});
    // A footprint under one cell: a 1 cm quad.
    std::vector<float> tiny = quad_xyz;
    for (float& v : tiny) {
        v *= 0.01f;
    }
    expect_error(load_scene_memory(mesh_gltf(tiny, quad_indices), "tiny.gltf", auto_overrides()),
                 {"tiny.gltf: auto_snow (command-line override) needs a footprint of at least one "
                  "0.05 m cell each way"});
}

// --- the apps ----------------------------------------------------------------

TEST(AutoSnow, SnowRunReportsTheCover) {
    const AppRun r = run_app("game/snow_run",
                             "--auto-snow --dt 0.05 --ticks 160 --report json --scene " +
                                 test_data_path("tool_export.glb"),
                             "", false);
    ASSERT_EQ(r.status, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j["mass"]["balanced"].get<bool>());
    bool cover = false;
    for (const auto& s : j["surfaces"]) {
        if (s["kind"] == "cover") {
            cover = true;
            EXPECT_GT(s["settled_units"].get<std::uint64_t>(), 0u);
            EXPECT_GT(s["max_depth_m"].get<double>(), 0.0);
        }
    }
    EXPECT_TRUE(cover) << r.out;
    // Without the flag the same file reports no surface at all.
    const AppRun plain =
        run_app("game/snow_run",
                "--ticks 5 --report json --scene " + test_data_path("tool_export.glb"), "", false);
    ASSERT_EQ(plain.status, 0) << plain.out;
    EXPECT_TRUE(nlohmann::json::parse(plain.out)["surfaces"].empty());
}

TEST(AutoSnow, AppsExitWith2ForASceneWithoutMeshes) {
    TempDir dir;
    const fs::path empty = dir.scene_dir() / "empty.gltf";
    dir.write(empty, R"({"asset": {"version": "2.0"}, "nodes": [{"name": "nothing"}]})");
    for (const std::string app :
         {"game/snow_run --ticks 1", "game/snow_game --headless --frames 1"}) {
        SCOPED_TRACE(app);
        const AppRun r =
            run_app(app, "--auto-snow --scene " + empty.string(), "MESA_SHADER_CACHE_DISABLE=true");
        EXPECT_EQ(r.status, 2) << r.out;
        EXPECT_NE(r.out.find("empty.gltf: auto_snow (command-line override) asks for snow on "
                             "the scene's meshes"),
                  std::string::npos)
            << r.out;
    }
}

} // namespace
} // namespace snow
