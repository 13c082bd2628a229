// Any glTF (issue 13): .glb with the same hardening as .gltf, files without
// `scenes`, node transforms and primitives as glTF 2.0 says, warnings for
// what snow does not use, and one clear error (exit 2 from snow_run) for a
// broken container. Files are written by the tests themselves, plus the
// exporter-shaped files of assets/testdata/ (scripts/make_test_gltf.py).
#include "systems/api/simulation_internals.hpp"
#include "tests/game/scene/scene_test_files.hpp"
#include "tests/support/run_app.hpp"

#include "systems/geometry/colliders.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace snow {
namespace {

using namespace snow::test;

SceneLoadResult load_glb(const std::string& bytes) {
    return load_scene_memory(bytes, "test.glb");
}

std::string village_glb() {
    return gltf_to_glb(read_text(asset_path("village.gltf")));
}

std::map<std::string, const MeshRenderable*> meshes_by_name(const SceneVisuals& v) {
    std::map<std::string, const MeshRenderable*> out;
    for (const MeshRenderable& m : v.meshes) {
        out[m.name] = &m;
    }
    return out;
}

/// Every warning, one per line, for failure messages.
std::string all_warnings(const SceneLoadResult& r) {
    std::string out;
    for (const std::string& w : r.warnings) {
        out += w + "\n";
    }
    return out;
}

bool has_point(const MeshRenderable& m, glm::vec3 p) {
    return std::any_of(m.positions.begin(), m.positions.end(),
                       [&](const glm::vec3& q) { return glm::length(q - p) < 1e-5f; });
}

// --- .glb --------------------------------------------------------------------

TEST(SceneGlb, VillageAsGlbSimulatesLikeTheGltf) {
    const SceneLoadResult a = load_scene_file(asset_path("village.gltf"));
    const SceneLoadResult b = load_glb(village_glb());
    ASSERT_NE(a.sim, nullptr) << a.error;
    ASSERT_NE(b.sim, nullptr) << b.error;
    EXPECT_TRUE(b.warnings.empty()) << all_warnings(b);
    EXPECT_EQ(b.name, "village");
    EXPECT_EQ(a.visuals.meshes.size(), b.visuals.meshes.size());
    a.sim->run(20);
    b.sim->run(20);
    EXPECT_EQ(a.sim->state_hash(), b.sim->state_hash());

    // From a file too; the folder rule applies to a .glb's external buffers.
    TempDir dir;
    const fs::path p = dir.scene_dir() / "village.glb";
    dir.write(p, village_glb());
    const SceneLoadResult c = load_scene_file(p.string());
    ASSERT_NE(c.sim, nullptr) << c.error;
    c.sim->run(20);
    EXPECT_EQ(c.sim->state_hash(), a.sim->state_hash());
}

TEST(SceneGlb, BrokenHeaderNamesTheField) {
    const std::string ok = village_glb();
    ASSERT_NE(load_glb(ok).sim, nullptr);
    expect_error(load_glb(ok.substr(0, ok.size() - 100)),
                 {"test.glb: glb header.length is " + std::to_string(ok.size()) +
                  " but the file has " + std::to_string(ok.size() - 100) + " bytes (truncated?)"});
    expect_error(load_glb(ok.substr(0, 7)),
                 {"test.glb: glb header needs 12 bytes (the file has 7)"});
    expect_error(load_glb(with_u32(ok, 4, 1)),
                 {"test.glb: glb header.version must be 2 (only glTF 2 is supported; got 1)"});
    expect_error(load_glb(ok + "junk"), {"glb header.length is " + std::to_string(ok.size()) +
                                         " but the file has " + std::to_string(ok.size() + 4)});
    // A file named .glb must be one; bytes from memory without the magic are JSON.
    TempDir dir;
    const fs::path p = dir.scene_dir() / "bad.glb";
    dir.write(p, "glTX" + ok.substr(4));
    expect_error(load_scene_file(p.string()),
                 {"bad.glb: glb header.magic must be \"glTF\" (a .glb file; got 0x58546C67)"});
    expect_error(load_glb("glTX" + ok.substr(4)), {"test.glb: not valid JSON"});
}

TEST(SceneGlb, LyingChunkLengthsAreCaught) {
    const std::string ok = village_glb();
    const std::uint32_t json_length = u32_at(ok, 12);
    // Longer than the file: caught before any byte of the chunk is read.
    expect_error(load_glb(with_u32(ok, 12, 0xFFFFFFF0u)),
                 {"test.glb: glb chunk 0.length is 4294967280 but only " +
                  std::to_string(ok.size() - 20) + " bytes follow its header"});
    // Shorter: the next "chunk header" is JSON text, whose length overruns.
    expect_error(load_glb(with_u32(ok, 12, json_length - 8)), {"test.glb: glb chunk 1.length is"});
    // The BIN chunk's own length lies.
    const std::size_t bin_header = 20 + json_length;
    expect_error(load_glb(with_u32(ok, bin_header, u32_at(ok, bin_header) + 4)),
                 {"glb chunk 1.length is"});
    // A first chunk that is not JSON.
    expect_error(load_glb(with_u32(ok, 16, 0x004E4942)),
                 {"glb chunk 0.type must be 0x4E4F534A (JSON; the first chunk) (got 0x004E4942)"});
    // The header alone: no JSON chunk.
    expect_error(load_glb(with_u32(ok.substr(0, 12), 8, 12)), {"test.glb: glb has no JSON chunk"});
}

TEST(SceneGlb, BinChunkMustHoldTheBuffer) {
    const std::string gltf = mesh_gltf(quad_xyz, quad_indices);
    const std::vector<unsigned char> bin = mesh_bytes(quad_xyz, quad_indices);
    const std::string json_no_uri = replaced(
        gltf, gltf.substr(gltf.find(", \"uri\""), gltf.rfind('"') - gltf.find(", \"uri\"") + 1),
        "");
    ASSERT_NE(load_glb(glb(json_no_uri, bin)).sim, nullptr)
        << load_glb(glb(json_no_uri, bin)).error;
    // buffers[0].byteLength larger than the BIN chunk.
    expect_error(
        load_glb(glb(replaced(json_no_uri, "\"byteLength\": 60}", "\"byteLength\": 64}"), bin)),
        {"test.glb: buffers[0].byteLength is 64 but the .glb's BIN chunk has 60 bytes"});
    // No BIN chunk at all.
    expect_error(load_glb(glb(json_no_uri)),
                 {"buffers[0].uri is required (the file has no .glb BIN chunk"});
    // Only buffers[0] may use the BIN chunk.
    expect_error(
        load_glb(glb(replaced(json_no_uri, "\"buffers\": [", "\"buffers\": [{\"byteLength\": 4}, "),
                     bin)),
        {"buffers[1].uri is required (only buffers[0] may use the .glb's BIN chunk)"});
    // A BIN chunk that does not follow the JSON chunk directly.
    std::string odd = glb(json_no_uri);
    const std::size_t json_end = odd.size();
    std::string extra;
    put_u32(extra, 4);
    put_u32(extra, 0x12345678); // an unknown chunk type: skipped
    extra += "abcd";
    put_u32(extra, static_cast<std::uint32_t>(bin.size()));
    put_u32(extra, 0x004E4942);
    extra.append(bin.begin(), bin.end());
    odd = with_u32(odd + extra, 8, static_cast<std::uint32_t>(json_end + extra.size()));
    expect_error(load_glb(odd),
                 {"glb chunk 2 is a BIN chunk, which must directly follow the JSON chunk"});
    // An unknown chunk after the BIN chunk is skipped, as the spec asks.
    std::string tail = glb(json_no_uri, bin);
    std::string unknown;
    put_u32(unknown, 4);
    put_u32(unknown, 0x12345678);
    unknown += "abcd";
    tail = with_u32(tail + unknown, 8, static_cast<std::uint32_t>(tail.size() + unknown.size()));
    EXPECT_NE(load_glb(tail).sim, nullptr) << load_glb(tail).error;
}

// --- any glTF ----------------------------------------------------------------

/// A glTF around one position buffer (the quad) and the given objects.
std::string quad_file(const std::string& nodes_and_scenes, const std::string& meshes,
                      const std::string& accessors, const std::string& views,
                      const std::vector<unsigned char>& bytes) {
    return R"({"asset": {"version": "2.0"}, )" + nodes_and_scenes + R"(, "meshes": )" + meshes +
           R"(, "accessors": )" + accessors + R"(, "bufferViews": )" + views +
           R"(, "buffers": [{"byteLength": )" + std::to_string(bytes.size()) +
           R"(, "uri": "data:application/octet-stream;base64,)" + base64(bytes) + R"("}]})";
}

const std::string quad_mesh = mesh_gltf(quad_xyz, quad_indices);

/// The one-quad file with its "scene"/"scenes"/"nodes" part replaced.
std::string with_nodes(const std::string& nodes) {
    const std::size_t from = quad_mesh.find("\"scene\"");
    const std::size_t to = quad_mesh.find("\"meshes\"");
    std::string s = quad_mesh;
    s.replace(from, to - from, nodes + ", ");
    return s;
}

TEST(SceneGltf, FileWithoutScenesUsesAllRootNodes) {
    const SceneLoadResult r =
        load_scene_memory(with_nodes(R"("nodes": [{"name": "a", "mesh": 0, "children": [1]},
                                {"name": "b", "mesh": 0, "translation": [0, 1, 0]},
                                {"name": "c", "mesh": 0, "translation": [5, 0, 0]}])"),
                          "roots.gltf");
    ASSERT_NE(r.sim, nullptr) << r.error;
    EXPECT_EQ(r.name, "roots.gltf"); // no scene to name it
    const auto m = meshes_by_name(r.visuals);
    ASSERT_EQ(m.size(), 3u);
    EXPECT_TRUE(has_point(*m.at("b"), {1, 1, 1})); // a child of "a", not a second root
    EXPECT_TRUE(has_point(*m.at("c"), {6, 0, 1}));
    // A node reachable twice (a child of two parents) is still an error.
    expect_error(load_scene_memory(with_nodes(R"("nodes": [{"mesh": 0, "children": [2]},
                                                          {"mesh": 0, "children": [2]},
                                                          {"mesh": 0}])"),
                                   "t.gltf"),
                 {"t.gltf: nodes[2] is reached twice"});
}

TEST(SceneGltf, NodeTransformsComposeAsTheSpecSays) {
    // Parent: T·R·S with R = 90° about +y; child: a column-major matrix moving +5 in z.
    const std::string nodes = R"("scenes": [{"nodes": [0]}], "nodes": [
        {"name": "parent", "translation": [1, 2, 3], "rotation": [0, 0.7071067811865476, 0, 0.7071067811865476],
         "scale": [2, 1, 1], "children": [1]},
        {"name": "child", "mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,5,1]}])";
    const SceneLoadResult r = load_scene_memory(with_nodes(nodes), "t.gltf");
    ASSERT_NE(r.sim, nullptr) << r.error;
    const MeshRenderable& child = *meshes_by_name(r.visuals).at("child");
    // Vertex (1, 0, 0): child → (1, 0, 5); scale → (2, 0, 5); rotate → (5, 0, −2); translate.
    EXPECT_TRUE(has_point(child, {6, 2, 1}));
    EXPECT_TRUE(has_point(child, {1 + 5, 2, 3})); // vertex (0, 0, 0)
    // A matrix must be affine (it must decompose into TRS).
    expect_error(load_scene_memory(with_nodes(R"("scenes": [{"nodes": [0]}], "nodes": [
        {"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,1, 0,0,0,1]}])"),
                                   "t.gltf"),
                 {"t.gltf: nodes[0].matrix must be affine"});
    expect_error(load_scene_memory(with_nodes(R"("scenes": [{"nodes": [0]}], "nodes": [
        {"mesh": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0]}])"),
                                   "t.gltf"),
                 {"nodes[0].matrix must have 16 numbers (got 12)"});
}

TEST(SceneGltf, PrimitivesOfEveryIndexKindAndModesSkipped) {
    // Positions of a quad, then its triangles as u8, u16 and u32 indices, then
    // six vertices for a non-indexed copy.
    std::vector<unsigned char> bytes = mesh_bytes(quad_xyz, {});
    const auto append = [&](const void* p, std::size_t n) {
        const auto* c = static_cast<const unsigned char*>(p);
        bytes.insert(bytes.end(), c, c + n);
        while (bytes.size() % 4 != 0) {
            bytes.push_back(0);
        }
    };
    const std::uint8_t i8[] = {0, 2, 1, 0, 3, 2};
    const std::uint16_t i16[] = {0, 2, 1, 0, 3, 2};
    const std::uint32_t i32[] = {0, 2, 1, 0, 3, 2};
    const float flat[] = {0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0, 1, 1, 0, 1};
    append(i8, sizeof i8);     // at 48
    append(i16, sizeof i16);   // at 56
    append(i32, sizeof i32);   // at 68
    append(flat, sizeof flat); // at 92
    const std::string views =
        R"([{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 6},
        {"buffer": 0, "byteOffset": 56, "byteLength": 12}, {"buffer": 0, "byteOffset": 68, "byteLength": 24},
        {"buffer": 0, "byteOffset": 92, "byteLength": 72}])";
    const std::string accessors =
        R"([{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
        {"bufferView": 1, "componentType": 5121, "count": 6, "type": "SCALAR"},
        {"bufferView": 2, "componentType": 5123, "count": 6, "type": "SCALAR"},
        {"bufferView": 3, "componentType": 5125, "count": 6, "type": "SCALAR"},
        {"bufferView": 4, "componentType": 5126, "count": 6, "type": "VEC3"}])";
    const std::string meshes = R"([{"primitives": [
        {"attributes": {"POSITION": 0}, "indices": 1},
        {"attributes": {"POSITION": 0}, "indices": 2},
        {"attributes": {"POSITION": 0}, "indices": 3, "mode": 4},
        {"attributes": {"POSITION": 4}},
        {"attributes": {"POSITION": 0}, "indices": 2, "mode": 1},
        {"attributes": {"POSITION": 0}, "mode": 0}]}])";
    const SceneLoadResult r = load_scene_memory(
        quad_file(R"("scenes": [{"nodes": [0]}], "nodes": [{"name": "q", "mesh": 0}])", meshes,
                  accessors, views, bytes),
        "prims.gltf");
    ASSERT_NE(r.sim, nullptr) << r.error;
    ASSERT_EQ(r.warnings.size(), 2u) << all_warnings(r);
    EXPECT_TRUE(has_warning(r, "prims.gltf: meshes[0].primitives[4].mode is 1 (LINES); only "
                               "TRIANGLES become geometry, so it is skipped"));
    EXPECT_TRUE(has_warning(r, "meshes[0].primitives[5].mode is 0 (POINTS)"));
    std::size_t count = 0;
    for (const MeshRenderable& m : r.visuals.meshes) {
        ++count;
        ASSERT_EQ(m.indices.size(), 6u) << m.name;
        // Every primitive is the same up-facing quad, whatever its index kind.
        const glm::vec3 a = m.positions[m.indices[0]], b = m.positions[m.indices[1]],
                        c = m.positions[m.indices[2]];
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f) << m.name;
    }
    EXPECT_EQ(count, 4u);
    // A role needs triangles: a node whose only primitive is skipped has none.
    const std::string lines_only = quad_file(
        R"("scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "extras": {"snow": {"collider": "box"}}}])",
        R"([{"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "mode": 1}]}])",
        accessors, views, bytes);
    expect_error(load_scene_memory(lines_only, "t.gltf"),
                 {"nodes[0].extras.snow declares a surface, collider or body, but the node has no "
                  "triangle mesh"});
}

TEST(SceneGltf, RequiredExtensions) {
    const auto requiring = [](const std::string& ext) {
        return load_scene_memory(
            replaced(quad_mesh, "\"scene\": 0",
                     "\"extensionsRequired\": [\"" + ext + "\"], \"scene\": 0"),
            "t.gltf");
    };
    expect_error(requiring("KHR_draco_mesh_compression"),
                 {"t.gltf: extensionsRequired[0] is \"KHR_draco_mesh_compression\", which the "
                  "loader does not support"});
    expect_error(requiring("EXT_meshopt_compression"), {"extensionsRequired[0]"});
    const SceneLoadResult unlit = requiring("KHR_materials_unlit");
    ASSERT_NE(unlit.sim, nullptr) << unlit.error;
    EXPECT_TRUE(has_warning(unlit, "extensionsRequired[0] \"KHR_materials_unlit\" is not "
                                   "supported; the scene is drawn without it"));
    EXPECT_NE(requiring("KHR_lights_punctual").sim, nullptr);
}

// --- files as other tools write them (assets/testdata) ----------------------

TEST(SceneTestData, ExporterStyleGlbLoadsWithItsHierarchy) {
    const SceneLoadResult r = load_scene_file(test_data_path("tool_export.glb"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    EXPECT_EQ(r.name, "Scene");
    // The crate's LINES primitive is the only thing skipped; its PNG is never decoded.
    ASSERT_EQ(r.warnings.size(), 1u) << all_warnings(r);
    EXPECT_TRUE(has_warning(r, "meshes[1].primitives[1].mode is 1 (LINES)"));
    const World& w = world_of(*r.sim);
    const auto m = meshes_by_name(r.visuals);
    ASSERT_EQ(m.size(), 4u); // Ground, Crate, Tree (trunk), Tree#1 (crown)
    EXPECT_EQ(w.count<Emitter>() + w.count<SnowSurface>() + w.count<BoxCollider>(), 0u);
    // The crate: yard (1, 0, −1) + crate (0, 0.5, 0), turned 45° about y and
    // 1.5 deep: its top face is at y = 1.
    float top = -1e9f;
    for (const glm::vec3& p : m.at("Crate")->positions) {
        top = std::max(top, p.y);
    }
    EXPECT_NEAR(top, 1.0f, 1e-5f);
    // The tree sits at yard + (−3, 0, 2); the crown's apex is 3.5 m up.
    EXPECT_TRUE(has_point(*m.at("Tree#1"), {-2.0f, 3.5f, 1.0f}));
    EXPECT_NEAR(m.at("Tree")->color.r, 0.4f, 1e-6f);
    // The crate's wood is the PNG in a bufferView of the BIN chunk (16 x 16).
    ASSERT_NE(m.at("Crate")->texture, nullptr);
    EXPECT_EQ(m.at("Crate")->texture->height, 16);
    EXPECT_EQ(m.at("Crate")->texcoords.size(), m.at("Crate")->positions.size());
    EXPECT_NEAR(m.at("Ground")->color.g, 0.5f, 1e-6f);
    r.sim->run(10);
    EXPECT_TRUE(r.sim->mass().balanced());
}

TEST(SceneTestData, PlainGltfWithoutScenesOrExtras) {
    const SceneLoadResult r = load_scene_file(test_data_path("plain.gltf"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    EXPECT_EQ(r.name, "plain");
    EXPECT_TRUE(r.warnings.empty()) << all_warnings(r);
    const auto m = meshes_by_name(r.visuals);
    ASSERT_EQ(m.size(), 2u);
    // The slab's bark comes from textures/bark.png beside the file (6 x 6).
    ASSERT_NE(m.at("slab")->texture, nullptr);
    EXPECT_EQ(m.at("slab")->texture->width, 6);
    EXPECT_EQ(m.at("slab")->texcoords.size(), m.at("slab")->positions.size());
    EXPECT_EQ(m.at("ramp")->texture, nullptr);
    // The slab's matrix moves it by (0.5, 1, −0.5); it is 4 × 0.2 × 3 m.
    EXPECT_TRUE(has_point(*m.at("slab"), {2.5f, 1.1f, 1.0f}));
    // The non-indexed ramp: six vertices, in order.
    EXPECT_EQ(m.at("ramp")->indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
    EXPECT_TRUE(has_point(*m.at("ramp"), {5.0f, 1.0f, 0.0f}));
    // Default bounds come from the geometry.
    EXPECT_NEAR(r.sim->config().bounds.max.y, 1.1f + 4.0f, 1e-5f);
}

TEST(SceneTestData, FilesMatchTheirGenerator) {
    const std::string cmd =
        "python3 " + std::string(SNOW_SOURCE_DIR) + "/scripts/make_test_gltf.py --check 2>&1";
    const int status = std::system(cmd.c_str());
    if (WIFEXITED(status) && WEXITSTATUS(status) == 127) {
        GTEST_SKIP() << "python3 is not installed";
    }
    EXPECT_EQ(status, 0) << "assets/testdata is stale: run python3 scripts/make_test_gltf.py";
}

// --- snow_run: one clear error, exit 2 ---------------------------------------

TEST(SceneGlb, SnowRunExitsWith2OnABrokenGlb) {
    TempDir dir;
    const std::string ok = village_glb();
    const fs::path good = dir.scene_dir() / "village.glb";
    const fs::path cut = dir.scene_dir() / "cut.glb";
    const fs::path lie = dir.scene_dir() / "lie.glb";
    dir.write(good, ok);
    dir.write(cut, ok.substr(0, ok.size() / 2));
    dir.write(lie, with_u32(ok, 12, 0xFFFFFFF0u));
    const AppRun g = run_app("game/snow_run", "--ticks 5 --scene " + good.string());
    EXPECT_EQ(g.status, 0) << g.out;
    const AppRun c = run_app("game/snow_run", "--ticks 5 --scene " + cut.string());
    EXPECT_EQ(c.status, 2);
    EXPECT_NE(c.out.find("cut.glb: glb header.length is"), std::string::npos) << c.out;
    const AppRun l = run_app("game/snow_run", "--ticks 5 --scene " + lie.string());
    EXPECT_EQ(l.status, 2);
    EXPECT_NE(l.out.find("lie.glb: glb chunk 0.length is 4294967280"), std::string::npos) << l.out;
}

} // namespace
} // namespace snow
