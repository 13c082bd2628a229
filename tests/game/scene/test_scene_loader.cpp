// Scene loading: the project's scenes load with the declared roles, and every
// kind of bad input gives one error naming the file and the field, no Simulation.
#include "systems/api/simulation_internals.hpp"
#include "tests/game/scene/scene_test_files.hpp"

#include "systems/geometry/colliders.hpp"

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace snow {
namespace {

using namespace snow::test;

SceneLoadResult load_text(const std::string& text, const SceneOverrides& o = {}) {
    return load_scene_memory(text, "test.gltf", o);
}

Entity surface_owner(const World& w, const SnowSurface& target) {
    Entity owner = null_entity;
    w.each<SnowSurface, SurfaceOf>([&](Entity, const SnowSurface& s, const SurfaceOf& of) {
        if (&s == &target) {
            owner = of.owner;
        }
    });
    return owner;
}

// ---------------------------------------------------------------------------

TEST(SceneLoader, VillageHasTheDeclaredRolesAndBounds) {
    const SceneLoadResult r = load_scene_file(asset_path("village.gltf"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    EXPECT_TRUE(r.error.empty());
    EXPECT_EQ(r.name, "village");
    const World& w = world_of(*r.sim);
    EXPECT_EQ(w.count<BoxCollider>(), 4u);    // walls, porch, garage, fence
    EXPECT_EQ(w.count<SphereCollider>(), 3u); // snowman
    EXPECT_EQ(w.count<MeshCollider>(), 2u);   // roof sides
    EXPECT_EQ(w.count<SnowSurface>(), 6u);    // ground, 2 roof sides, porch, garage, the cover
    EXPECT_EQ(w.count<SnowCover>(), 1u);
    EXPECT_EQ(w.count<Body>(), 1u);          // the walker
    EXPECT_EQ(r.visuals.meshes.size(), 12u); // every node but the walker (drawn as a body)
    EXPECT_EQ(r.visuals.lights.size(), 3u);
    EXPECT_EQ(w.count<Emitter>(), 1u);
    EXPECT_TRUE(w.has_resource<Wind>());
    EXPECT_TRUE(r.visuals.fog.has_value());
    EXPECT_TRUE(w.has_resource<OcclusionCamera>());
    EXPECT_FALSE(r.visuals.spectral.has_value());
    EXPECT_EQ(r.visuals.camera.position,
              glm::vec3(1.0f, 6.0f, 17.0f)); // the scene's own, not the default

    const SimConfig& c = r.sim->config();
    EXPECT_FLOAT_EQ(c.dt, 1.0f / 60.0f);
    EXPECT_EQ(c.max_flakes, 50000u);
    EXPECT_EQ(c.seed, 2u);
    EXPECT_EQ(c.bounds.min, glm::vec3(-10.0f, -0.5f, -10.0f));
    EXPECT_EQ(c.bounds.max, glm::vec3(10.0f, 12.0f, 10.0f));
    EXPECT_EQ(w.resource<Wind>().base, glm::vec3(2.0f, 0.0f, 0.0f));

    // Extents come from the node meshes in world space (hierarchy and rotation applied).
    int garage = 0, fence = 0, walls = 0;
    w.each<BoxCollider>([&](Entity, const BoxCollider& b) {
        const auto near = [](glm::vec3 a, glm::vec3 e) {
            return glm::all(glm::lessThan(glm::abs(a - e), glm::vec3(1e-5f)));
        };
        garage += near(b.box.min, {3, 0, -3}) && near(b.box.max, {7, 2.5f, 0});
        fence += near(b.box.min, {-8.05f, 0, -6}) && near(b.box.max, {-7.95f, 1, 4});
        walls += near(b.box.min, {-5.5f, 0, -3}) && near(b.box.max, {-0.5f, 3, 1});
    });
    EXPECT_EQ(garage, 1);
    EXPECT_EQ(fence, 1);
    EXPECT_EQ(walls, 1);
    std::vector<float> radii;
    w.each<SphereCollider>([&](Entity, const SphereCollider& s) {
        radii.push_back(s.radius);
        EXPECT_NEAR(s.center.x, 2.0f, 1e-5f);
        EXPECT_NEAR(s.center.z, 4.0f, 1e-5f);
    });
    ASSERT_EQ(radii.size(), 3u);
    EXPECT_NEAR(radii[0], 0.6f, 1e-5f);
    EXPECT_NEAR(radii[1], 0.42f, 1e-5f);
    EXPECT_NEAR(radii[2], 0.28f, 1e-5f);

    // Surface owners: the ground has none, roofs lie on mesh colliders, porch and garage on boxes.
    int on_nothing = 0, on_mesh = 0, on_box = 0, sloped = 0;
    w.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        if (w.has<SnowCover>(e)) {
            return; // follows the geometry: tests/systems/snowpack/test_cover.cpp
        }
        const Entity owner = surface_owner(w, s);
        on_nothing += owner.is_null();
        on_mesh += !owner.is_null() && w.has<MeshCollider>(owner);
        on_box += !owner.is_null() && w.has<BoxCollider>(owner);
        sloped += std::abs(s.top_y(0) - s.top_y(s.cell_count() - 1)) > 1.0f;
        if (owner.is_null()) {
            EXPECT_EQ(s.nx, 200u);
            EXPECT_EQ(s.nz, 200u);
            EXPECT_NEAR(s.top_y(0), 0.0f, 1e-3f);
        }
    });
    EXPECT_EQ(on_nothing, 1);
    EXPECT_EQ(on_mesh, 2);
    EXPECT_EQ(on_box, 2);
    EXPECT_EQ(sloped, 2);

    // [WF §5]: white above the house, blue nearer the camera, yellow on the right.
    int white = 0, blue = 0, yellow = 0;
    for (const PointLight& l : r.visuals.lights) {
        white += l.color == glm::vec3(1.0f) && l.position.y > 8.0f;
        blue += l.color.b > l.color.r && l.position.z > 5.0f;
        yellow += l.color.r > l.color.b && l.position.x > 8.0f;
    }
    EXPECT_EQ(white + blue + yellow, 3);
    EXPECT_EQ(white, 1);
    EXPECT_EQ(blue, 1);
}

TEST(SceneLoader, MeshRenderablesAreWorldSpaceWithUnitNormalsAndMaterialColour) {
    const SceneLoadResult r = load_scene_file(asset_path("village.gltf"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    int garages = 0;
    for (const MeshRenderable& m : r.visuals.meshes) {
        ASSERT_EQ(m.positions.size(), m.normals.size()) << m.name;
        ASSERT_EQ(m.indices.size() % 3, 0u) << m.name;
        for (const std::uint32_t i : m.indices) {
            ASSERT_LT(i, m.positions.size()) << m.name;
        }
        for (const glm::vec3& n : m.normals) {
            EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f) << m.name;
        }
        if (m.name == "garage") {
            ++garages;
            EXPECT_NEAR(m.color.r, 0.62f, 1e-6f);
            float top = -1e9f;
            for (const glm::vec3& p : m.positions) {
                top = std::max(top, p.y);
            }
            EXPECT_NEAR(top, 2.5f, 1e-5f);
        }
    }
    EXPECT_EQ(garages, 1);
}

TEST(SceneLoader, MinimalSceneCreatesOnlyWhatItDeclares) {
    const SceneLoadResult r = load_scene_file(asset_path("minimal.gltf"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    const World& w = world_of(*r.sim);
    EXPECT_FALSE(w.has_resource<Wind>());
    EXPECT_FALSE(r.visuals.fog.has_value());
    EXPECT_FALSE(w.has_resource<OcclusionCamera>());
    EXPECT_FALSE(r.visuals.spectral.has_value());
    EXPECT_EQ(w.count<BoxCollider>() + w.count<SphereCollider>() + w.count<MeshCollider>(), 0u);
    EXPECT_TRUE(r.visuals.lights.empty());
    EXPECT_EQ(w.count<SnowSurface>(), 1u);
    EXPECT_EQ(w.count<Emitter>(), 1u);
    // Default bounds: the ground's (10 × 0.2 × 10 m) grown by the margin and headroom.
    const Aabb& b = r.sim->config().bounds;
    EXPECT_NEAR(b.min.x, -6.0f, 1e-5f);
    EXPECT_NEAR(b.min.y, -1.2f, 1e-5f);
    EXPECT_NEAR(b.max.y, 4.0f, 1e-5f);
    EXPECT_NEAR(b.max.z, 6.0f, 1e-5f);
    r.sim->run(30);
    EXPECT_TRUE(r.sim->mass().balanced());
    EXPECT_EQ(r.sim->nonfinite_count(), 0u);
}

TEST(SceneLoader, VillageEffectsAddsSpectralLayeredFogGustsAndAWindField) {
    const SceneLoadResult r = load_scene_file(asset_path("village_effects.gltf"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    const World& w = world_of(*r.sim);
    ASSERT_TRUE(r.visuals.spectral.has_value());
    EXPECT_EQ(r.visuals.spectral->size_xy, 64u);
    ASSERT_TRUE(r.visuals.fog.has_value());
    EXPECT_EQ(r.visuals.fog->mode, FogMode::layered);
    ASSERT_EQ(r.visuals.fog->puffs.size(), 1u);
    EXPECT_FLOAT_EQ(r.visuals.fog->puffs[0].sigma, 1.5f);
    EXPECT_FLOAT_EQ(w.resource<Wind>().gust_strength, 3.0f);
    // The buildings shape the wind, and the wind moves snow (docs/wind_field.md).
    ASSERT_TRUE(w.has_resource<WindField>());
    const WindField& f = w.resource<WindField>();
    EXPECT_EQ(f.n[0], 64u);
    EXPECT_EQ(f.n[1], 16u);
    EXPECT_EQ(f.n[2], 64u);
    EXPECT_EQ(f.def.update_every, 4u);
    ASSERT_TRUE(f.transport.has_value());
    EXPECT_FLOAT_EQ(f.transport->roughness, 0.001f);
}

TEST(SceneLoader, MemoryLoadOfEmbeddedSceneMatchesFileLoad) {
    const SceneLoadResult a = load_scene_file(asset_path("village.gltf"));
    const SceneLoadResult b =
        load_scene_memory(read_text(asset_path("village.gltf")), "builtin:village");
    ASSERT_NE(a.sim, nullptr) << a.error;
    ASSERT_NE(b.sim, nullptr) << b.error;
    a.sim->run(20);
    b.sim->run(20);
    EXPECT_EQ(a.sim->state_hash(), b.sim->state_hash());
}

TEST(SceneLoader, OverridesReplaceSceneSettingsAndThreadsDoNotChangeTheResult) {
    SceneOverrides o;
    o.seed = 99;
    o.dt = 0.01f;
    o.integrator = Integrator::rk4;
    o.max_flakes = 3000;
    o.threads = 2;
    const SceneLoadResult r2 = load_scene_file(asset_path("village.gltf"), o);
    ASSERT_NE(r2.sim, nullptr) << r2.error;
    const SimConfig& c = r2.sim->config();
    EXPECT_EQ(c.seed, 99u);
    EXPECT_FLOAT_EQ(c.dt, 0.01f);
    EXPECT_EQ(c.integrator, Integrator::rk4);
    EXPECT_EQ(c.max_flakes, 3000u);
    EXPECT_EQ(c.threads, 2u);
    o.threads = 1;
    const SceneLoadResult r1 = load_scene_file(asset_path("village.gltf"), o);
    ASSERT_NE(r1.sim, nullptr) << r1.error;
    r1.sim->run(40);
    r2.sim->run(40);
    EXPECT_EQ(r1.sim->state_hash(), r2.sim->state_hash());
    EXPECT_TRUE(r1.sim->mass().balanced());
}

TEST(SceneLoader, BadOverrideIsReportedAsSuch) {
    SceneOverrides o;
    o.dt = -1.0f;
    expect_error(load_scene_file(asset_path("minimal.gltf"), o),
                 {"minimal.gltf", "override", "simulation.dt must be > 0"});
}

// --- bad input: one clear error naming file and field, no simulation ---------

TEST(SceneLoaderErrors, MissingFile) {
    expect_error(load_scene_file(asset_path("no_such_scene.gltf")),
                 {"no_such_scene.gltf", "no such file"});
}

TEST(SceneLoaderErrors, NotJsonNotGltf) {
    expect_error(load_text("this is { not json"), {"test.gltf: not valid JSON", "line 1"});
    expect_error(load_text(R"({"hello": 1})"), {"test.gltf: not a glTF file"});
    expect_error(load_text("[1, 2]"), {"not a glTF file", "got array"});
    expect_error(load_text(R"({"asset": {"version": "1.0"}})"),
                 {"test.gltf: asset.version must be \"2.0\"", "got \"1.0\""});
    expect_error(load_text(R"({"asset": {"version": 2}})"),
                 {"asset.version must be a string (got integer)"});
    expect_error(load_text(R"({"asset": {"version": "2.0"}, "nodes": {}})"),
                 {"test.gltf: nodes must be an array (got object)"});
    expect_error(load_text(R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": -1}]})"),
                 {"test.gltf: nodes[0].mesh must be in [0, 18446744073709551615] (got -1)"});
    expect_error(load_text(R"({"asset": {"version": "2.0"}, "scene": 0})"),
                 {"scene refers to scene 0, but the file has no scenes"});
}

TEST(SceneLoader, AssetOnlyFileIsAnEmptyScene) {
    // Valid glTF with no scenes and no nodes: nothing to instance, no effects.
    const SceneLoadResult r = load_text(R"({"asset": {"version": "2.0"}})");
    ASSERT_NE(r.sim, nullptr) << r.error;
    EXPECT_TRUE(r.visuals.meshes.empty());
    EXPECT_EQ(world_of(*r.sim).count<Emitter>(), 0u);
    EXPECT_EQ(r.name, "test.gltf");
}

TEST(SceneLoaderErrors, HostileSizesAndNesting) {
    expect_error(load_text(std::string(max_scene_bytes + 1, ' ')), {"test.gltf", "at most"});
    expect_error(load_text(std::string(100000, '[') + std::string(100000, ']')),
                 {"nests deeper than"});
}

TEST(SceneLoaderErrors, TruncatedBuffer) {
    // Keep only the first 48 bytes of the village's buffer: its views now overrun it.
    std::string text = read_text(asset_path("village.gltf"));
    const std::string tag = "base64,";
    const std::size_t start = text.find(tag) + tag.size();
    const std::size_t end = text.find('"', start);
    text.replace(start, end - start, text.substr(start, 64));
    const std::size_t len = text.rfind("\"byteLength\"", start);
    const std::size_t num = text.find(':', len) + 2;
    text.replace(num, text.find(',', num) - num, "48");
    expect_error(load_text(text), {"test.gltf: bufferViews[", "exceeds its buffer's 48 bytes"});
    // A declared length the data does not have.
    expect_error(load_text(replaced(mesh_gltf(quad_xyz, quad_indices), "\"byteLength\": 60,",
                                    "\"byteLength\": 6000,")),
                 {"test.gltf: buffers[0].byteLength is 6000 but its data: URI holds 60 bytes"});
    expect_error(load_text(replaced(mesh_gltf(quad_xyz, quad_indices), "base64,", "base64,*")),
                 {"test.gltf: buffers[0].uri is not valid base64 (character 0 of the data)"});
    expect_error(load_text(replaced(mesh_gltf(quad_xyz, quad_indices), ";base64,", ",")),
                 {"buffers[0].uri must be a base64 data URI"});
}

TEST(SceneLoaderErrors, AccessorOutOfRange) {
    const std::string ok = mesh_gltf(quad_xyz, quad_indices);
    ASSERT_NE(load_text(ok).sim, nullptr) << load_text(ok).error;
    expect_error(load_text(replaced(ok, "\"count\": 4,", "\"count\": 400,")),
                 {"test.gltf: accessors[0] needs bytes", "bufferViews[0]"});
    expect_error(load_text(replaced(ok, "\"POSITION\": 0", "\"POSITION\": 7")),
                 {"meshes[0].primitives[0].attributes.POSITION refers to accessor 7"});
    expect_error(load_text(replaced(ok, "\"byteOffset\": 48,", "\"byteOffset\": 4800,")),
                 {"bufferViews[1] range"});
    expect_error(load_text(replaced(ok, "\"componentType\": 5126", "\"componentType\": 5120")),
                 {"accessors[0].componentType must be 5126"});
    // An index beyond the vertex count.
    expect_error(load_text(mesh_gltf(quad_xyz, {0, 2, 9})),
                 {"meshes[0].primitives[0].indices element 2 is 9"});
    // An index count that is not whole triangles.
    expect_error(load_text(mesh_gltf(quad_xyz, {0, 1, 2, 3})), {"multiple of 3"});
}

TEST(SceneLoaderErrors, NonFiniteVertex) {
    std::vector<float> xyz = quad_xyz;
    xyz[4] = std::numeric_limits<float>::quiet_NaN();
    expect_error(load_text(mesh_gltf(xyz, quad_indices)),
                 {"test.gltf: accessors[0] element 1 is not finite"});
    xyz[4] = std::numeric_limits<float>::infinity();
    expect_error(load_text(mesh_gltf(xyz, quad_indices)), {"accessors[0] element 1"});
}

TEST(SceneLoaderErrors, SurfaceValues) {
    const std::string cell0 =
        mesh_gltf(quad_xyz, quad_indices, R"(, "extras": {"snow": {"surface": {"cell": 0}}})");
    const SceneLoadResult r = load_text(cell0);
    expect_error(r, {});
    EXPECT_EQ(r.error, "test.gltf: nodes[0].extras.snow.surface.cell must be > 0 (got 0)");
    expect_error(load_text(mesh_gltf(quad_xyz, quad_indices,
                                     R"(, "extras": {"snow": {"surface": {"cell": -0.5}}})")),
                 {"nodes[0].extras.snow.surface.cell must be > 0 (got -0.5)"});
    // 10^9 cells per side.
    expect_error(load_text(mesh_gltf(quad_xyz, quad_indices,
                                     R"(, "extras": {"snow": {"surface": {"cell": 1e-9}}})")),
                 {"nodes[0].extras.snow.surface.cell gives 1e+09 cells per side"});
    expect_error(load_text(mesh_gltf(quad_xyz, quad_indices,
                                     R"(, "extras": {"snow": {"surface": {"edge_limit": -1}}})")),
                 {"nodes[0].extras.snow.surface.edge_limit must be >= 0"});
}

TEST(SceneLoaderErrors, WrongExtrasTypesAndUnknownFields) {
    const auto with = [](const std::string& extras) {
        return load_text(mesh_gltf(quad_xyz, quad_indices, ", \"extras\": " + extras));
    };
    expect_error(with(R"({"snow": []})"), {"nodes[0].extras.snow must be an object (got array)"});
    expect_error(with(R"({"snow": {"surface": {"cell": "fine"}}})"),
                 {"nodes[0].extras.snow.surface.cell must be a number (got string)"});
    expect_error(with(R"({"snow": {"surface": 3}})"),
                 {"nodes[0].extras.snow.surface must be an object (got integer)"});
    expect_error(
        with(R"({"snow": {"collider": 5}})"),
        {"nodes[0].extras.snow.collider must be one of \"box\", \"sphere\", \"mesh\", \"capsule\" "
         "(got integer)"});
    expect_error(with(R"({"snow": {"collider": "cone"}})"), {"(got \"cone\")"});
    expect_error(with(R"({"snow": {"surface": {"spills": 1}}})"),
                 {"surface.spills must be true or false"});
    expect_error(with(R"({"snow": {"surface": {"celll": 0.1}}})"),
                 {"nodes[0].extras.snow.surface has an unknown field 'celll'"});
    // The rectangle comes from the mesh, not from the surface's fields.
    expect_error(with(R"({"snow": {"surface": {"x0": 1}}})"),
                 {"nodes[0].extras.snow.surface has an unknown field 'x0'"});
    expect_error(with(R"({"snow": {"surface": {"cell": 1e39}}})"),
                 {"surface.cell must be a finite number within float range (got 1e+39)"});
    // A body's compaction: a fraction, and only on a body.
    for (const char* bad : {"-0.1", "1.5", "\"half\""}) {
        expect_error(
            with(std::string(R"({"snow": {"collider": "capsule", "compaction": )") + bad + "}}"),
            {"nodes[0].extras.snow.compaction must be"});
    }
    expect_error(with(R"({"snow": {"collider": "box", "compaction": 0.5}})"),
                 {"nodes[0].extras.snow.compaction is for moving bodies only"});
    // A fence's porosity: [0, 1), and only on a box that stands still.
    for (const char* bad : {"-0.1", "1", "\"half\""}) {
        expect_error(with(std::string(R"({"snow": {"collider": "box", "porosity": )") + bad + "}}"),
                     {"nodes[0].extras.snow.porosity must be"});
    }
    expect_error(with(R"({"snow": {"collider": "sphere", "porosity": 0.5}})"),
                 {"nodes[0].extras.snow.porosity is for box colliders that stand still"});
    const SceneLoadResult fence = with(R"({"snow": {"collider": "box", "porosity": 0.5}})");
    ASSERT_NE(fence.sim, nullptr) << fence.error;
    world_of(*fence.sim).each<BoxCollider>([](Entity, const BoxCollider& b) {
        EXPECT_EQ(b.porosity, 0.5f);
    });
    const SceneLoadResult packing =
        with(R"({"snow": {"collider": "capsule", "on_ground": true, "compaction": 0.5}})");
    ASSERT_NE(packing.sim, nullptr) << packing.error;
    world_of(*packing.sim).each<Body>([](Entity, const Body& b) { EXPECT_EQ(b.compaction, 0.5f); });
    // Extras that are not ours are ignored.
    EXPECT_NE(with(R"({"author": "someone", "snow": {}})").sim, nullptr);
}

TEST(SceneLoaderErrors, SceneSettingsNameTheirField) {
    const std::string minimal = read_text(asset_path("minimal.gltf"));
    expect_error(load_text(replaced(minimal, "\"size_min\": 0.001", "\"size_min\": -0.01")),
                 {"test.gltf: scenes[0].extras.snow.emitter.size_min must be > 0 (got -0.01)"});
    expect_error(load_text(replaced(minimal, "\"max_flakes\": 5000", "\"max_flakes\": 1000000000")),
                 {"scenes[0].extras.snow.simulation.max_flakes must be <= 16777216"});
    expect_error(load_text(replaced(minimal, "\"max_flakes\": 5000", "\"max_flakes\": 2.5")),
                 {"simulation.max_flakes must be an integer (got 2.5)"});
    expect_error(load_text(replaced(minimal, "\"seed\": 1", "\"seed\": -1")),
                 {"simulation.seed must be in [0, 18446744073709551615] (got -1)"});
    expect_error(load_text(replaced(minimal, "\"seed\": 1", "\"smoothing_iterations\": 8")),
                 {"simulation has an unknown field 'smoothing_iterations'"});
    expect_error(load_text(replaced(minimal, "\"seed\": 1", "\"integrator\": \"leapfrog\"")),
                 {"simulation.integrator must be one of"});
    expect_error(load_text(replaced(minimal, "\"dt\": 0.016666666666666666", "\"dt\": 0")),
                 {"simulation.dt must be > 0"});
    expect_error(load_text(replaced(minimal, "\"seed\": 1",
                                    "\"bounds\": {\"min\": [0, 0, 0], \"max\": [1, -1, 1]}")),
                 {"simulation.bounds.max.y must be >= simulation.bounds.min.y"});
    const std::string village = read_text(asset_path("village.gltf"));
    expect_error(load_text(replaced(village, "\"resolution\": 256", "\"resolution\": 1000000000")),
                 {"scenes[0].extras.snow.occlusion.resolution must be <= 4096"});
    expect_error(load_text(replaced(village, "\"density\": 0.02", "\"density\": -0.02")),
                 {"scenes[0].extras.snow.fog.density must be >= 0"});
    expect_error(load_text(replaced(village, "\"mode\": \"exponential\"", "\"mode\": \"thick\"")),
                 {"scenes[0].extras.snow.fog.mode must be"});
    expect_error(load_text(replaced(village, "\"walk\": 0.2", "\"walk\": \"gentle\"")),
                 {"scenes[0].extras.snow.wind.walk must be a number (got string)"});
    // The wind's running state is not a setting.
    expect_error(load_text(replaced(village, "\"walk\": 0.2", "\"current\": [1, 0, 0]")),
                 {"scenes[0].extras.snow.wind has an unknown field 'current'"});
    expect_error(load_text(replaced(village, "\"fov_y_deg\": 50.0", "\"fov_y_deg\": 0")),
                 {"scenes[0].extras.snow.camera.fov_y_deg must be in (0, 170] (got 0)"});
    expect_error(load_text(replaced(village, "\"far_plane\": 200.0", "\"far_plane\": 0.01")),
                 {"scenes[0].extras.snow.camera.far_plane must be > near_plane (got 0.01)"});
    expect_error(load_text(replaced(village, "\"fov_y_deg\": 50.0", "\"lens\": 35")),
                 {"scenes[0].extras.snow.camera has an unknown field 'lens'"});
    expect_error(load_text(replaced(village, "\"type\": \"point\"", "\"type\": \"directional\"")),
                 {"extensions.KHR_lights_punctual.lights[0].type must be \"point\""});
    expect_error(load_text(replaced(village, "\"light\": 2", "\"light\": 3")),
                 {"KHR_lights_punctual.light must be in [0, 2] (got 3)"});
    const std::string sunny = read_text(asset_path("village_effects.gltf"));
    expect_error(
        load_text(replaced(sunny, "\"direction\": [-0.7, 0.45, -0.3]", "\"direction\": [0, 0, 0]")),
        {"scenes[0].extras.snow.sun.direction must be of length > 0 (got 0)"});
    expect_error(load_text(replaced(sunny, "\"intensity\": 4.0", "\"intensity\": -1")),
                 {"scenes[0].extras.snow.sun.intensity must be >= 0"});
    expect_error(load_text(replaced(sunny, "\"intensity\": 4.0", "\"elevation\": 30")),
                 {"scenes[0].extras.snow.sun has an unknown field 'elevation'"});
}

TEST(SceneLoaderErrors, BrokenGraphsAndPrimitives) {
    const std::string ok = mesh_gltf(quad_xyz, quad_indices);
    expect_error(load_text(replaced(ok, "\"mesh\": 0", "\"mesh\": 0, \"children\": [0]")),
                 {"test.gltf: nodes[0] is reached twice"});
    expect_error(load_text(replaced(ok, "\"nodes\": [0]", "\"nodes\": [5]")),
                 {"scenes[0].nodes[0] must name one of the file's 1 nodes (got 5)"});
    expect_error(load_text(replaced(ok, "\"mesh\": 0", "\"mesh\": 0, \"scale\": [1, 0, 1]")),
                 {"singular"});
    expect_error(load_text(replaced(ok, "\"mesh\": 0", "\"mesh\": 0, \"rotation\": [0, 0, 0, 2]")),
                 {"nodes[0].rotation must be a unit quaternion"});
    expect_error(load_text(replaced(ok, "\"mesh\": 0", "\"mesh\": 0, \"translation\": [1, 2]")),
                 {"nodes[0].translation must have 3 numbers (got 2)"});
    expect_error(load_text(replaced(ok, "\"mesh\": 0", "\"mesh\": 0, \"scale\": [1e39, 1, 1]")),
                 {"not finite in float"});
    // A role on a node without geometry.
    const std::string two_nodes =
        replaced(replaced(ok, "\"nodes\": [{\"mesh\": 0}]",
                          R"("nodes": [{"mesh": 0}, {"extras": {"snow": {"collider": "box"}}}])"),
                 "\"nodes\": [0]", "\"nodes\": [0, 1]");
    expect_error(
        load_text(two_nodes),
        {"nodes[1].extras.snow declares a surface, collider or body, but the node has no triangle "
         "mesh"});
}

TEST(SceneLoaderErrors, MirroredNodeKeepsOutwardWinding) {
    const std::string text = replaced(mesh_gltf(quad_xyz, quad_indices), "\"mesh\": 0",
                                      "\"mesh\": 0, \"scale\": [-1, 1, 1]");
    const SceneLoadResult r = load_text(text);
    ASSERT_NE(r.sim, nullptr) << r.error;
    ASSERT_EQ(r.visuals.meshes.size(), 1u);
    for (const MeshRenderable& m : r.visuals.meshes) {
        // The quad faces up (+y); after mirroring in x it must still face up.
        const glm::vec3 a = m.positions[m.indices[0]], b = m.positions[m.indices[1]],
                        c = m.positions[m.indices[2]];
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f);
        EXPECT_GT(m.normals[0].y, 0.99f); // computed (the file has no NORMAL)
    }
}

TEST(SceneLoaderErrors, FileAccessStaysInsideTheSceneFolder) {
    TempDir dir;
    const std::vector<unsigned char> bytes = mesh_bytes(quad_xyz, quad_indices);
    const std::string bin(bytes.begin(), bytes.end());
    dir.write(dir.scene_dir() / "quad.bin", bin);
    dir.write(dir.root() / "outside.bin", bin);

    // A buffer beside the scene loads.
    const fs::path good = dir.scene_dir() / "good.gltf";
    dir.write(good, mesh_gltf(quad_xyz, quad_indices, "", "quad.bin"));
    const SceneLoadResult ok = load_scene_file(good.string());
    ASSERT_NE(ok.sim, nullptr) << ok.error;

    const auto with_uri = [&](const std::string& uri) {
        const fs::path p = dir.scene_dir() / "bad.gltf";
        dir.write(p, mesh_gltf(quad_xyz, quad_indices, "", uri));
        return load_scene_file(p.string());
    };
    expect_error(with_uri("../outside.bin"),
                 {"bad.gltf: buffers[0].uri must not leave the scene's folder"});
    expect_error(with_uri("sub/../../outside.bin"), {"buffers[0].uri must not leave"});
    expect_error(with_uri((dir.root() / "outside.bin").string()),
                 {"buffers[0].uri must be a relative path inside the scene's folder"});
    expect_error(with_uri("file:///etc/passwd"), {"buffers[0].uri must be a relative path"});
    // %-escapes are decoded before the checks, so they cannot hide a `..`.
    expect_error(with_uri("%2e%2e/outside.bin"), {"buffers[0].uri must not leave"});
    expect_error(with_uri("quad%2"), {"buffers[0].uri has a malformed %-escape"});
    expect_error(with_uri("missing.bin"),
                 {"bad.gltf: buffers[0].uri names 'missing.bin', which is not a file inside"});
    // A symlink inside the folder that points out is refused too.
    fs::create_symlink(dir.root() / "outside.bin", dir.scene_dir() / "link.bin");
    expect_error(with_uri("link.bin"), {"bad.gltf: buffers[0].uri names 'link.bin'"});
    // A file shorter than the buffer's byteLength.
    dir.write(dir.scene_dir() / "short.bin", bin.substr(0, 10));
    expect_error(with_uri("short.bin"), {"'short.bin', which has 10 bytes"});
    // An escaped name is the file's real name.
    dir.write(dir.scene_dir() / "my quad.bin", bin);
    EXPECT_NE(with_uri("my%20quad.bin").sim, nullptr);
    // From memory, no file may be read at all.
    expect_error(load_text(mesh_gltf(quad_xyz, quad_indices, "", "quad.bin")),
                 {"test.gltf: buffers[0].uri names an external file"});
}

TEST(SceneLoader, MissingOrUnreadableImagesNoMaterialUsesAreWarningsNotErrors) {
    // Only a material's base colour texture is decoded; other images are never opened.
    const std::string text = replaced(mesh_gltf(quad_xyz, quad_indices), "\"buffers\"",
                                      R"("images": [{"uri": "missing.png"}, {"uri": "../up.png"},
                               {"uri": "data:image/png;base64,notapng"}, {"bufferView": 9}],
                   "buffers")");
    TempDir dir;
    const fs::path p = dir.scene_dir() / "img.gltf";
    dir.write(p, text);
    const SceneLoadResult r = load_scene_file(p.string());
    ASSERT_NE(r.sim, nullptr) << r.error;
    ASSERT_EQ(r.warnings.size(), 3u);
    EXPECT_TRUE(has_warning(r, "img.gltf: images[0].uri 'missing.png' is not a file inside the "
                               "scene's folder; ignored (no material takes it as a base colour "
                               "texture)"));
    EXPECT_TRUE(has_warning(r, "images[1].uri '../up.png' must not leave the scene's folder"));
    EXPECT_TRUE(has_warning(r, "images[3].bufferView 9 does not exist"));
}

} // namespace
} // namespace snow
