// Baking snow out: the mesh of a surface (void and bare cells left out,
// skirts wherever the snow ends, so every open edge lies on the bare base),
// the .glb container read back, the 16-bit depth PNG read back by stb_image,
// and snow_run --export / --export-depth as a user runs them.
#include "game/export/glb_writer.hpp"
#include "game/export/png16.hpp"
#include "game/export/snow_export.hpp"
#include "game/export/snow_mesh.hpp"
#include "game/export/surface_list.hpp"
#include "systems/api/simulation_internals.hpp"
#include "tests/support/cover_scene.hpp"
#include "tests/support/run_app.hpp"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <tuple>

namespace snow {
namespace {

namespace fs = std::filesystem;

SnowSurface flat_surface(std::uint32_t nx, std::uint32_t nz, float base_y) {
    SurfaceDef d;
    d.x0 = -1.0f;
    d.z0 = 2.0f;
    d.cell = 0.25f;
    d.size_x = static_cast<float>(nx) * d.cell;
    d.size_z = static_cast<float>(nz) * d.cell;
    d.base_y = base_y;
    return make_surface(d); // throws SimulationError for a bad definition
}

std::vector<std::uint8_t> read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t le32(const std::vector<std::uint8_t>& b, std::size_t at) {
    return b[at] | (b[at + 1] << 8) | (b[at + 2] << 16) |
           (static_cast<std::uint32_t>(b[at + 3]) << 24);
}

/// Every bare base height a mesh corner over grid corner (cx, cz) may have:
/// the mean base of any non-empty set of the snowed cells around it.
std::vector<float> corner_bases(const SnowSurface& s, std::uint32_t cx, std::uint32_t cz) {
    std::vector<float> around;
    for (unsigned k = 0; k < 4; ++k) {
        const std::uint32_t x = cx - 1 + (k & 1u), z = cz - 1 + (k >> 1);
        if (x < s.nx && z < s.nz && !s.is_void(s.index(x, z)) && s.snow[s.index(x, z)] > 0) {
            around.push_back(s.height(s.base_level[s.index(x, z)]));
        }
    }
    std::vector<float> means;
    for (unsigned set = 1; set < (1u << around.size()); ++set) {
        float sum = 0.0f;
        int n = 0;
        for (std::size_t k = 0; k < around.size(); ++k) {
            if (set & (1u << k)) {
                sum += around[k];
                ++n;
            }
        }
        means.push_back(sum / static_cast<float>(n));
    }
    return means;
}

/// The promises of build_snow_mesh, checked on any surface: indices in range,
/// unit normals on the side the winding faces, no degenerate triangle, and
/// every edge crossed as often one way as the other (consistently wound and
/// closed) except on the bare base, where the snow stands. Edges are keyed by
/// position, so two patches touching at a corner share their vertical edges.
void expect_closed_looking(const SnowSurface& s, const SnowMesh& m) {
    ASSERT_EQ(m.positions.size(), m.normals.size());
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (const glm::vec3& n : m.normals) {
        ASSERT_NEAR(glm::length(n), 1.0f, 1e-5f);
    }
    using Key = std::tuple<float, float, float>;
    const auto key = [&](std::uint32_t v) {
        const glm::vec3& p = m.positions[v];
        return Key{p.x, p.y, p.z};
    };
    std::map<std::pair<Key, Key>, int> directed;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const std::uint32_t v[3] = {m.indices[t], m.indices[t + 1], m.indices[t + 2]};
        for (const std::uint32_t i : v) {
            ASSERT_LT(i, m.positions.size());
        }
        const glm::vec3 face = glm::cross(m.positions[v[1]] - m.positions[v[0]],
                                          m.positions[v[2]] - m.positions[v[0]]);
        ASSERT_GT(glm::length(face), 0.0f) << "degenerate triangle " << t / 3;
        for (const std::uint32_t i : v) {
            EXPECT_GT(glm::dot(face, m.normals[i]), 0.0f)
                << "winding against the normal, triangle " << t / 3;
        }
        for (int e = 0; e < 3; ++e) {
            ++directed[{key(v[e]), key(v[(e + 1) % 3])}];
        }
    }
    int open_edges = 0;
    for (const auto& [edge, count] : directed) {
        const auto back = directed.find({edge.second, edge.first});
        if (back != directed.end() && back->second == count) {
            continue;
        }
        ++open_edges;
        for (const Key& end : {edge.first, edge.second}) {
            const auto [x, y, z] = end;
            const float fx = (x - s.x0) / s.cell, fz = (z - s.z0) / s.cell;
            ASSERT_NEAR(fx, std::round(fx), 1e-3f) << "open edge off the grid";
            ASSERT_NEAR(fz, std::round(fz), 1e-3f) << "open edge off the grid";
            const std::vector<float> bases =
                corner_bases(s, static_cast<std::uint32_t>(std::lround(fx)),
                             static_cast<std::uint32_t>(std::lround(fz)));
            const bool on_base = std::any_of(bases.begin(), bases.end(),
                                             [y = y](float b) { return std::abs(b - y) < 1e-5f; });
            EXPECT_TRUE(on_base) << "open edge above the base at (" << x << ", " << y << ", " << z
                                 << ")";
        }
    }
    EXPECT_GT(open_edges, 0) << "the snow stands on its base";
}

/// The cell under the centre of each top triangle (normal pointing up); -1 off the grid.
std::vector<long> top_triangle_cells(const SnowSurface& s, const SnowMesh& m) {
    std::vector<long> cells;
    for (std::size_t t = 0; t < m.indices.size(); t += 3) {
        const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                        c = m.positions[m.indices[t + 2]];
        if (glm::normalize(glm::cross(b - a, c - a)).y < 0.1f) {
            continue; // a skirt
        }
        const glm::vec3 mid = (a + b + c) / 3.0f;
        std::uint32_t ix = 0, iz = 0;
        cells.push_back(s.cell_at(mid.x, mid.z, ix, iz) ? static_cast<long>(s.index(ix, iz)) : -1);
    }
    return cells;
}

TEST(SnowMesh, FullSurfaceIsATopWithSkirtsAllRound) {
    SnowSurface s = flat_surface(4, 3, 0.5f);
    for (std::size_t i = 0; i < s.cell_count(); ++i) {
        s.snow[i] = 100 + static_cast<std::uint32_t>(i);
    }
    const SnowMesh m = build_snow_mesh(s);
    // 2 triangles per cell on top, 2 per border cell side down the skirt.
    EXPECT_EQ(m.indices.size() / 3, 2u * 12u + 2u * 2u * (4u + 3u));
    expect_closed_looking(s, m);
    // The top is one sheet: a vertex per grid corner before the skirts.
    std::set<std::pair<float, float>> corners;
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        if (m.normals[v].y > 0.5f) {
            corners.insert({m.positions[v].x, m.positions[v].z});
        }
    }
    EXPECT_EQ(corners.size(), 5u * 4u);
}

TEST(SnowMesh, VoidAndBareCellsAreLeftOut) {
    SnowSurface s = flat_surface(5, 5, 0.0f);
    std::fill(s.snow.begin(), s.snow.end(), 40u);
    for (const std::uint32_t i : {s.index(1, 1), s.index(2, 1), s.index(1, 2), s.index(2, 2)}) {
        s.base_level[i] = void_level;
        s.snow[i] = 0;
    }
    s.snow[s.index(4, 4)] = 0; // bare corner cell
    const SnowMesh m = build_snow_mesh(s);
    expect_closed_looking(s, m);
    const std::vector<long> cells = top_triangle_cells(s, m);
    EXPECT_EQ(cells.size(), 2u * (25u - 5u));
    for (const long c : cells) {
        ASSERT_GE(c, 0);
        EXPECT_FALSE(s.is_void(static_cast<std::size_t>(c)));
        EXPECT_GT(s.snow[static_cast<std::size_t>(c)], 0u);
    }
    EXPECT_TRUE(build_snow_mesh(flat_surface(3, 3, 1.0f)).empty()) << "no snow, no mesh";
}

TEST(SnowMesh, ClosedEdgesSplitTheTopAtADrop) {
    // A 6 x 2 cover-like surface: the +x half stands 1 m higher, with the
    // edges between the halves closed as a cover closes its drops.
    SnowSurface s = flat_surface(6, 2, 0.0f);
    const auto step = static_cast<std::int64_t>(std::llround(1.0 / s.unit_height));
    std::fill(s.snow.begin(), s.snow.end(), 200u);
    s.closed.assign(s.cell_count(), 0);
    for (std::uint32_t iz = 0; iz < 2; ++iz) {
        for (std::uint32_t ix = 3; ix < 6; ++ix) {
            s.base_level[s.index(ix, iz)] += step;
        }
        s.closed[s.index(2, iz)] |= 2u; // +x of the low side
        s.closed[s.index(3, iz)] |= 1u; // -x of the high side
    }
    const SnowMesh m = build_snow_mesh(s);
    expect_closed_looking(s, m);
    const float mid_x = s.x0 + 3.0f * s.cell;
    const float low_top = s.top_y(s.index(2, 0)), high_top = s.top_y(s.index(3, 0));
    bool low_edge = false, high_edge = false;
    for (const glm::vec3& p : m.positions) {
        if (std::abs(p.x - mid_x) < 1e-5f) {
            low_edge |= std::abs(p.y - low_top) < 1e-4f;
            high_edge |= std::abs(p.y - high_top) < 1e-4f;
            EXPECT_TRUE(p.y <= low_top + 1e-4f ||
                        p.y >= s.height(s.base_level[s.index(3, 0)]) - 1e-4f)
                << "no snow smeared across the drop at y " << p.y;
        }
    }
    EXPECT_TRUE(low_edge && high_edge);
}

TEST(SnowMesh, CoverOverSphereBoxAndGroundLooksClosed) {
    const test::CoverScene scene = test::snowed_cover_scene(600);
    const World& w = world_of(*scene.sim);
    const SnowSurface& cover = w.get<SnowSurface>(entity_of(scene.cover));
    const SnowMesh m = build_snow_mesh(cover);
    ASSERT_FALSE(m.empty());
    expect_closed_looking(cover, m);
    // The ground mesh ends at ±2 m: the cover's ring beyond it is void.
    for (const glm::vec3& p : m.positions) {
        EXPECT_LE(std::abs(p.x), scene.ground_half + 1e-4f);
        EXPECT_LE(std::abs(p.z), scene.ground_half + 1e-4f);
    }
    // The shed's roof is a declared surface: the cover leaves its columns to it.
    const SnowSurface& roof = w.get<SnowSurface>(entity_of(scene.roof));
    for (const long c : top_triangle_cells(cover, m)) {
        ASSERT_GE(c, 0);
        const float x = cover.x0 + (static_cast<float>(c % cover.nx) + 0.5f) * cover.cell;
        const float z = cover.z0 + (static_cast<float>(c / cover.nx) + 0.5f) * cover.cell;
        std::uint32_t rx = 0, rz = 0;
        EXPECT_FALSE(roof.cell_at(x, z, rx, rz) && x > roof.x0 + roof.cell &&
                     z > roof.z0 + roof.cell && x < roof.x0 + (roof.nx - 1) * roof.cell &&
                     z < roof.z0 + (roof.nz - 1) * roof.cell)
            << "cover snow inside the roof at (" << x << ", " << z << ")";
    }
    EXPECT_FALSE(build_snow_mesh(roof).empty());
}

class ExportFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::path(SNOW_BINARY_DIR) / "test_out" /
               ("export_" +
                std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    /// Every file under dir_, relative to it.
    std::set<std::string> listing() const {
        std::set<std::string> out;
        for (const auto& e : fs::recursive_directory_iterator(dir_)) {
            out.insert(fs::relative(e.path(), dir_).string());
        }
        return out;
    }
    fs::path dir_;
};

TEST_F(ExportFiles, GlbReadsBackAsGltf2) {
    const test::CoverScene scene = test::snowed_cover_scene(400);
    const fs::path file = dir_ / "cover.glb";
    export_snow_glb(*scene.sim, file);
    EXPECT_EQ(listing(), std::set<std::string>{"cover.glb"}) << "no temporary file left";
    const std::vector<std::uint8_t> b = read_bytes(file);
    ASSERT_GE(b.size(), 28u);
    EXPECT_EQ(std::memcmp(b.data(), "glTF", 4), 0);
    EXPECT_EQ(le32(b, 4), 2u);
    EXPECT_EQ(le32(b, 8), b.size());
    const std::uint32_t json_len = le32(b, 12);
    EXPECT_EQ(json_len % 4, 0u);
    EXPECT_EQ(std::memcmp(b.data() + 16, "JSON", 4), 0);
    const auto j = nlohmann::json::parse(b.begin() + 20, b.begin() + 20 + json_len);
    const std::size_t bin_at = 20 + json_len;
    ASSERT_EQ(bin_at + 8 + le32(b, bin_at), b.size());
    EXPECT_EQ(std::memcmp(b.data() + bin_at + 4, "BIN\0", 4), 0);
    const std::uint8_t* bin = b.data() + bin_at + 8;
    EXPECT_EQ(j["asset"]["version"], "2.0");
    EXPECT_FALSE(j["asset"]["generator"].get<std::string>().empty());
    EXPECT_EQ(j["buffers"][0]["byteLength"], le32(b, bin_at));
    for (const auto& v : j["bufferViews"]) {
        EXPECT_EQ(v["byteOffset"].get<std::size_t>() % 4, 0u);
        EXPECT_LE(v["byteOffset"].get<std::size_t>() + v["byteLength"].get<std::size_t>(),
                  j["buffers"][0]["byteLength"].get<std::size_t>());
    }
    // A node per surface holding snow, named after it, with the snow material.
    std::set<std::string> expected;
    for (const NamedSurface& ns : named_surfaces(*scene.sim)) {
        if (!build_snow_mesh(*ns.surface).empty()) {
            expected.insert(ns.name);
        }
    }
    std::set<std::string> names;
    for (const auto& n : j["nodes"]) {
        names.insert(n["name"]);
    }
    EXPECT_EQ(names, expected);
    EXPECT_TRUE(names.count("cover_" + std::to_string(entity_of(scene.cover).index())));
    const auto& pbr = j["materials"][0]["pbrMetallicRoughness"];
    EXPECT_EQ(pbr["metallicFactor"], 0.0);
    EXPECT_GE(pbr["roughnessFactor"].get<double>(), 0.8);
    // POSITION's declared bounds are the data's, bit for bit.
    for (const auto& mesh : j["meshes"]) {
        const auto& prim = mesh["primitives"][0];
        const auto& acc = j["accessors"][prim["attributes"]["POSITION"].get<int>()];
        const auto& view = j["bufferViews"][acc["bufferView"].get<int>()];
        const std::size_t count = acc["count"];
        ASSERT_EQ(view["byteLength"].get<std::size_t>(), count * 12);
        std::vector<float> xyz(count * 3);
        std::memcpy(xyz.data(), bin + view["byteOffset"].get<std::size_t>(), count * 12);
        for (int c = 0; c < 3; ++c) {
            float lo = INFINITY, hi = -INFINITY;
            for (std::size_t v = 0; v < count; ++v) {
                lo = std::min(lo, xyz[v * 3 + c]);
                hi = std::max(hi, xyz[v * 3 + c]);
            }
            EXPECT_EQ(acc["min"][c].get<double>(), static_cast<double>(lo));
            EXPECT_EQ(acc["max"][c].get<double>(), static_cast<double>(hi));
        }
        EXPECT_EQ(j["accessors"][prim["indices"].get<int>()]["componentType"], 5125);
    }
}

TEST_F(ExportFiles, GlbOfASceneWithoutSnowHasNoBuffer) {
    Simulation sim;
    sim.add_surface(SurfaceDef{});
    const std::vector<std::uint8_t> b = encode_glb({}, "test");
    EXPECT_EQ(le32(b, 8), b.size());
    EXPECT_EQ(20 + le32(b, 12), b.size()) << "a JSON chunk only";
    const auto j = nlohmann::json::parse(b.begin() + 20, b.end());
    EXPECT_FALSE(j.contains("buffers"));
    EXPECT_FALSE(j["scenes"][0].contains("nodes"));
    export_snow_glb(sim, dir_ / "empty.glb");
    EXPECT_TRUE(fs::exists(dir_ / "empty.glb"));
}

TEST(Png16, DecodesToTheSameSamplesWithValidChunks) {
    const std::uint32_t w = 5, h = 3;
    std::vector<std::uint16_t> px(w * h);
    for (std::size_t i = 0; i < px.size(); ++i) {
        px[i] = static_cast<std::uint16_t>(i * 4681u); // spans 0 .. 65534, both bytes vary
    }
    px[7] = 65535;
    const std::vector<std::uint8_t> png = encode_png_gray16(w, h, px);
    int dw = 0, dh = 0, comp = 0;
    stbi_us* decoded =
        stbi_load_16_from_memory(png.data(), static_cast<int>(png.size()), &dw, &dh, &comp, 1);
    ASSERT_NE(decoded, nullptr) << stbi_failure_reason();
    EXPECT_EQ(dw, 5);
    EXPECT_EQ(dh, 3);
    EXPECT_EQ(comp, 1);
    EXPECT_EQ(std::vector<std::uint16_t>(decoded, decoded + px.size()), px);
    stbi_image_free(decoded);
    // Chunk by chunk: lengths add up and every CRC matches.
    const auto be32 = [&](std::size_t at) {
        return (static_cast<std::uint32_t>(png[at]) << 24) | (png[at + 1] << 16) |
               (png[at + 2] << 8) | png[at + 3];
    };
    std::vector<std::string> types;
    std::size_t at = 8;
    while (at < png.size()) {
        const std::uint32_t len = be32(at);
        ASSERT_LE(at + 12 + len, png.size());
        types.emplace_back(reinterpret_cast<const char*>(&png[at + 4]), 4);
        EXPECT_EQ(crc32(0, &png[at + 4], len + 4), be32(at + 8 + len)) << types.back();
        at += 12 + len;
    }
    EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "IDAT", "IEND"}));
    EXPECT_EQ(png[24], 16) << "bit depth";
    EXPECT_EQ(png[25], 0) << "grayscale";
    EXPECT_THROW((void)encode_png_gray16(0, 3, {}), std::invalid_argument);
    EXPECT_THROW((void)encode_png_gray16(2, 2, px), std::invalid_argument);
}

TEST(DepthExport, MillimetresPerCellVoidZeroAndClamped) {
    SnowSurface s = flat_surface(3, 2, 0.0f);
    const double unit_mm = s.unit_height * 1000.0;
    s.snow = {0, 1, 1000, 50, 0, static_cast<std::uint32_t>(70000.0 / unit_mm)};
    s.base_level[s.index(1, 1)] = void_level;
    s.snow[s.index(1, 1)] = 0;
    const std::vector<std::uint16_t> mm = depth_mm(s);
    ASSERT_EQ(mm.size(), 6u);
    EXPECT_EQ(mm[0], 0);
    EXPECT_EQ(mm[1], static_cast<std::uint16_t>(std::round(unit_mm)));
    EXPECT_EQ(mm[2], static_cast<std::uint16_t>(std::round(1000 * unit_mm)));
    EXPECT_EQ(mm[s.index(1, 1)], 0) << "void";
    EXPECT_EQ(mm[5], 65535) << "clamped";
}

TEST(SurfaceStats, MeanOverNonVoidCells) {
    SnowSurface s = flat_surface(2, 2, 0.0f);
    s.snow = {10, 30, 0, 0};
    s.base_level[3] = void_level;
    const SurfaceStats st = surface_stats(s);
    EXPECT_EQ(st.cells, 3u);
    EXPECT_EQ(st.settled_units, 40u);
    EXPECT_DOUBLE_EQ(st.mean_depth_m, 40.0 * s.unit_height / 3.0);
    EXPECT_DOUBLE_EQ(st.max_depth_m, 30.0 * static_cast<double>(s.unit_height));
}

test::AppRun snow_run(const std::string& args, bool with_stderr = true) {
    return test::run_app("game/snow_run", args, "", with_stderr);
}

TEST_F(ExportFiles, SnowRunWritesAGlbAndADepthImagePerSurface) {
    const fs::path glb = dir_ / "village.glb", depth = dir_ / "depth" / "new";
    const test::AppRun r = snow_run("--ticks 300 --report json --export " + glb.string() +
                                        " --export-depth " + depth.string(),
                                    false);
    ASSERT_EQ(r.status, 0) << r.out;
    const auto report = nlohmann::json::parse(r.out);
    const std::vector<std::uint8_t> b = read_bytes(glb);
    ASSERT_GE(b.size(), 12u);
    EXPECT_EQ(std::memcmp(b.data(), "glTF", 4), 0);
    std::uint64_t settled = 0;
    std::set<std::string> expected = {"village.glb", "depth", "depth/new"};
    ASSERT_FALSE(report["surfaces"].empty());
    int covers = 0;
    for (const auto& s : report["surfaces"]) {
        const std::string name = s["name"];
        // The village's five declared surfaces and its one cover.
        EXPECT_TRUE(s["kind"] == "surface" || s["kind"] == "cover") << name;
        covers += s["kind"] == "cover" ? 1 : 0;
        EXPECT_GT(s["cells"].get<std::uint64_t>(), 0u);
        EXPECT_LE(s["mean_depth_m"].get<double>(), s["max_depth_m"].get<double>());
        settled += s["settled_units"].get<std::uint64_t>();
        expected.insert("depth/new/" + name + ".png");
        expected.insert("depth/new/" + name + ".json");
        const auto meta = nlohmann::json::parse(read_bytes(depth / (name + ".json")));
        EXPECT_EQ(meta["name"], name);
        ASSERT_EQ(meta["origin"].size(), 2u);
        EXPECT_GT(meta["cell"].get<double>(), 0.0);
        const std::vector<std::uint8_t> png = read_bytes(depth / (name + ".png"));
        int w = 0, h = 0, comp = 0;
        stbi_us* px =
            stbi_load_16_from_memory(png.data(), static_cast<int>(png.size()), &w, &h, &comp, 1);
        ASSERT_NE(px, nullptr) << name;
        EXPECT_EQ(w, meta["cells"][0].get<int>());
        EXPECT_EQ(h, meta["cells"][1].get<int>());
        EXPECT_EQ(*std::max_element(px, px + w * h),
                  static_cast<stbi_us>(std::round(s["max_depth_m"].get<double>() * 1000.0)))
            << name;
        stbi_image_free(px);
    }
    EXPECT_EQ(covers, 1);
    EXPECT_EQ(settled, report["mass"]["settled"].get<std::uint64_t>())
        << "all settled snow lies on the listed surfaces";
    EXPECT_EQ(listing(), expected) << "no temporary file left";
}

TEST_F(ExportFiles, UnwritablePathsFailBeforeTheRunAndWriteNothing) {
    const fs::path file = dir_ / "a_file";
    std::ofstream(file) << "x";
    // A run this long would not end within the test's time: the check comes first.
    const std::string forever = "--ticks 1000000000000 ";
    for (const std::string& bad :
         {"--export " + (file / "x.glb").string(), "--export " + dir_.string(),
          "--export-depth " + (file / "depth").string(), "--export-depth " + file.string()}) {
        const test::AppRun r = snow_run(forever + bad);
        EXPECT_EQ(r.status, 2) << bad << "\n" << r.out;
        EXPECT_NE(r.out.find("cannot write '" + dir_.string()), std::string::npos) << r.out;
        EXPECT_NE(r.out.find(bad.substr(0, bad.find(' '))), std::string::npos)
            << "names the flag: " << r.out;
    }
    EXPECT_EQ(snow_run("--export ''").status, 2);
    EXPECT_EQ(listing(), std::set<std::string>{"a_file"});
}

} // namespace
} // namespace snow
