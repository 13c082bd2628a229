// tinygltf as the loader's oracle (issue 33): every glTF file of the test
// corpus is read by tinygltf 2.7 (Debian's libtinygltf-dev) and by our own
// reader (game/scene, up to its instanced geometry: parse_scene), and where
// both accept a file they must agree on which nodes the scene places and
// their world matrices, every triangle primitive's positions, normals and
// indices as its accessors hold them, the placed (world-space) vertices,
// normals and colours, and every material's base colour. tinygltf 2.7's
// known limits are pinned at the end (docs/scenes.md, "tinygltf as an oracle").
// Our own exports are also checked against the simulation that wrote them.
#include "game/export/snow_export.hpp"
#include "game/export/snow_mesh.hpp"
#include "game/export/surface_list.hpp"
#include "game/scene/scene_accessor.hpp"
#include "game/scene/scene_parse.hpp"
#include "tests/game/scene/scene_test_files.hpp"
#include "tests/support/cover_scene.hpp"

#include <tiny_gltf.h>

#include <gtest/gtest.h>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace snow {
namespace {

using namespace snow::test;

/// One file of the corpus: its bytes and the folder its URIs resolve in.
struct CorpusFile {
    std::string name;
    std::string bytes;
    std::string folder; ///< absolute; empty: read from memory, no files
    bool named_glb = false;
};

CorpusFile from_disk(const fs::path& path) {
    return {path.filename().string(), read_text(path.string()),
            fs::absolute(path).parent_path().string(), path.extension() == ".glb"};
}

bool starts_glb(const std::string& bytes) {
    return bytes.rfind("glTF", 0) == 0;
}

/// The renderer and the simulation use base colours only, so neither reader
/// decodes images: tinygltf is given a loader that accepts any.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
    return true;
}

struct TinyRead {
    bool ok = false;
    tinygltf::Model model;
    std::string error, warnings;
};

/// tinygltf's reading of `bytes`, whose first `size` bytes are the file.
TinyRead tiny_read(const std::vector<unsigned char>& bytes, std::size_t size,
                   const std::string& folder) {
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skip_image, nullptr);
    TinyRead r;
    const auto n = static_cast<unsigned int>(size);
    r.ok =
        size >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0
            ? loader.LoadBinaryFromMemory(&r.model, &r.error, &r.warnings, bytes.data(), n, folder)
            : loader.LoadASCIIFromString(&r.model, &r.error, &r.warnings,
                                         reinterpret_cast<const char*>(bytes.data()), n, folder);
    return r;
}

TinyRead tiny_read(const CorpusFile& f) {
    return tiny_read({f.bytes.begin(), f.bytes.end()}, f.bytes.size(), f.folder);
}

struct OurRead {
    std::optional<ParsedScene> parsed;
    std::string error;
};

OurRead our_read(const CorpusFile& f) {
    std::vector<std::string> warnings;
    try {
        return {parse_scene(f.bytes, f.folder, f.named_glb, warnings), ""};
    } catch (const SceneError& e) {
        return {std::nullopt, e.what()};
    }
}

// --- what tinygltf read, in our terms ----------------------------------------

/// Where element `i` of accessor `a` starts in tinygltf's buffer bytes.
const unsigned char* element(const tinygltf::Model& m, const tinygltf::Accessor& a, std::size_t i,
                             std::size_t size) {
    const tinygltf::BufferView& view = m.bufferViews.at(static_cast<std::size_t>(a.bufferView));
    const std::vector<unsigned char>& data =
        m.buffers.at(static_cast<std::size_t>(view.buffer)).data;
    const std::size_t at =
        view.byteOffset + a.byteOffset + i * static_cast<std::size_t>(a.ByteStride(view));
    if (at + size > data.size()) {
        ADD_FAILURE() << "tinygltf's accessor element " << i << " lies outside its buffer";
        return nullptr;
    }
    return data.data() + at;
}

std::vector<glm::vec3> tiny_vec3(const tinygltf::Model& m, int accessor) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
    EXPECT_EQ(a.type, TINYGLTF_TYPE_VEC3);
    EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
    std::vector<glm::vec3> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        if (const unsigned char* p = element(m, a, i, sizeof(glm::vec3))) {
            std::memcpy(&out[i], p, sizeof(glm::vec3));
        }
    }
    return out;
}

std::vector<std::uint32_t> tiny_indices(const tinygltf::Model& m, int accessor) {
    const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(accessor));
    const int bytes =
        tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
    std::vector<std::uint32_t> out(a.count);
    for (std::size_t i = 0; i < a.count; ++i) {
        const unsigned char* p = element(m, a, i, static_cast<std::size_t>(bytes));
        if (p == nullptr) {
            continue;
        }
        if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
            out[i] = *p;
        } else if (a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            std::uint16_t v = 0;
            std::memcpy(&v, p, 2);
            out[i] = v;
        } else {
            EXPECT_EQ(a.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
            std::memcpy(&out[i], p, 4);
        }
    }
    return out;
}

/// A node's own transform as glTF 2.0 §3.5.3 defines it: its column-major
/// `matrix`, or T · R · S, the rotation from the quaternion as given.
glm::dmat4 tiny_local(const tinygltf::Node& n) {
    if (n.matrix.size() == 16) {
        return glm::make_mat4(n.matrix.data());
    }
    glm::dmat4 t(1.0), r(1.0), s(1.0);
    if (n.translation.size() == 3) {
        t[3] = glm::dvec4(n.translation[0], n.translation[1], n.translation[2], 1.0);
    }
    if (n.rotation.size() == 4) {
        const double x = n.rotation[0], y = n.rotation[1], z = n.rotation[2], w = n.rotation[3];
        r[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w), 0};
        r[1] = {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w), 0};
        r[2] = {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y), 0};
    }
    if (n.scale.size() == 3) {
        s[0][0] = n.scale[0];
        s[1][1] = n.scale[1];
        s[2][2] = n.scale[2];
    }
    return t * r * s;
}

struct TinyPlaced {
    std::size_t node;
    glm::dmat4 world;
};

/// The nodes tinygltf's model places, depth first, children in file order:
/// the default scene's (else scenes[0]'s), or every root node of a file
/// without scenes (glTF 2.0 §3.3).
std::vector<TinyPlaced> tiny_placed(const tinygltf::Model& m) {
    std::vector<int> roots;
    if (m.scenes.empty()) {
        std::vector<bool> child(m.nodes.size(), false);
        for (const tinygltf::Node& n : m.nodes) {
            for (const int c : n.children) {
                child.at(static_cast<std::size_t>(c)) = true;
            }
        }
        for (std::size_t i = 0; i < m.nodes.size(); ++i) {
            if (!child[i]) {
                roots.push_back(static_cast<int>(i));
            }
        }
    } else {
        roots = m.scenes.at(static_cast<std::size_t>(std::max(m.defaultScene, 0))).nodes;
    }
    std::vector<TinyPlaced> out;
    std::vector<TinyPlaced> stack;
    for (auto r = roots.rbegin(); r != roots.rend(); ++r) {
        stack.push_back({static_cast<std::size_t>(*r), glm::dmat4(1.0)});
    }
    while (!stack.empty()) {
        const TinyPlaced p = stack.back();
        stack.pop_back();
        const tinygltf::Node& n = m.nodes.at(p.node);
        const glm::dmat4 world = p.world * tiny_local(n);
        out.push_back({p.node, world});
        for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) {
            stack.push_back({static_cast<std::size_t>(*c), world});
        }
    }
    return out;
}

// --- the comparison ------------------------------------------------------------

/// Relative closeness for values computed in two ways from the same numbers.
bool close(double a, double b, double tolerance) {
    return std::abs(a - b) <= tolerance * std::max(1.0, std::abs(b));
}

void expect_close(const glm::dmat4& ours, const glm::dmat4& theirs, const std::string& what) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            EXPECT_TRUE(close(ours[c][r], theirs[c][r], 1e-9))
                << what << " [" << c << "][" << r << "]: ours " << ours[c][r] << ", tinygltf "
                << theirs[c][r];
        }
    }
}

void expect_close(const glm::vec3& ours, const glm::dvec3& theirs, double tolerance,
                  const std::string& what) {
    for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(close(ours[k], theirs[k], tolerance))
            << what << "[" << k << "]: ours " << ours[k] << ", tinygltf " << theirs[k];
    }
}

/// Two readings of the same bytes must be equal element for element; says
/// where they first differ.
template <typename T>
void expect_same(const std::vector<T>& ours, const std::vector<T>& theirs,
                 const std::string& what) {
    ASSERT_EQ(ours.size(), theirs.size()) << what << ": element count";
    const auto diff = std::mismatch(ours.begin(), ours.end(), theirs.begin());
    EXPECT_TRUE(diff.first == ours.end())
        << what << ": element " << (diff.first - ours.begin()) << " differs";
}

/// The accessors of every triangle primitive, element by element, and its material.
void compare_meshes(const GltfDocument& ours, const tinygltf::Model& m) {
    ASSERT_EQ(ours.meshes.size(), m.meshes.size());
    for (std::size_t i = 0; i < m.meshes.size(); ++i) {
        const std::vector<tinygltf::Primitive>& theirs = m.meshes[i].primitives;
        ASSERT_EQ(ours.meshes[i].primitives.size(), theirs.size()) << "meshes[" << i << "]";
        for (std::size_t k = 0; k < theirs.size(); ++k) {
            const std::string at =
                "meshes[" + std::to_string(i) + "].primitives[" + std::to_string(k) + "]";
            const GltfPrimitive& p = ours.meshes[i].primitives[k];
            const tinygltf::Primitive& t = theirs[k];
            EXPECT_EQ(static_cast<int>(p.mode), t.mode) << at;
            EXPECT_EQ(p.material ? static_cast<int>(*p.material) : -1, t.material) << at;
            if (p.mode != gltf::mode_triangles) {
                continue; // our reader reads triangles only
            }
            const auto attribute = [&](const char* name) {
                const auto a = t.attributes.find(name);
                return a == t.attributes.end() ? -1 : a->second;
            };
            ASSERT_TRUE(p.position && attribute("POSITION") >= 0) << at;
            expect_same(read_vec3_accessor(ours, *p.position, at),
                        tiny_vec3(m, attribute("POSITION")), at + " POSITION");
            EXPECT_EQ(p.normal.has_value(), attribute("NORMAL") >= 0) << at;
            if (p.normal && attribute("NORMAL") >= 0) {
                expect_same(read_vec3_accessor(ours, *p.normal, at),
                            tiny_vec3(m, attribute("NORMAL")), at + " NORMAL");
            }
            EXPECT_EQ(p.indices.has_value(), t.indices >= 0) << at;
            if (p.indices && t.indices >= 0) {
                expect_same(read_index_accessor(ours, *p.indices, at), tiny_indices(m, t.indices),
                            at + " indices");
            }
        }
    }
}

/// A placed node's primitives against tinygltf's accessors under its world matrix.
void compare_placed(const WorldNode& node, const glm::dmat4& world, const tinygltf::Model& m) {
    const tinygltf::Node& n = m.nodes.at(node.index);
    std::vector<const tinygltf::Primitive*> triangles;
    if (n.mesh >= 0) {
        for (const tinygltf::Primitive& p :
             m.meshes.at(static_cast<std::size_t>(n.mesh)).primitives) {
            if (p.mode == TINYGLTF_MODE_TRIANGLES) {
                triangles.push_back(&p);
            }
        }
    }
    ASSERT_EQ(node.primitives.size(), triangles.size()) << node.name;
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(world)));
    const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
    for (std::size_t k = 0; k < triangles.size(); ++k) {
        const tinygltf::Primitive& t = *triangles[k];
        const WorldPrimitive& ours = node.primitives[k];
        const std::string at = node.name + " primitive " + std::to_string(k);
        const std::vector<glm::vec3> local = tiny_vec3(m, t.attributes.at("POSITION"));
        ASSERT_EQ(ours.positions.size(), local.size()) << at;
        for (std::size_t v = 0; v < local.size(); ++v) {
            expect_close(ours.positions[v],
                         glm::dvec3(world * glm::dvec4(glm::dvec3(local[v]), 1.0)), 1e-6,
                         at + " position " + std::to_string(v));
        }
        if (const auto normal = t.attributes.find("NORMAL"); normal != t.attributes.end()) {
            const std::vector<glm::vec3> normals = tiny_vec3(m, normal->second);
            for (std::size_t v = 0; v < normals.size(); ++v) {
                expect_close(ours.normals.at(v),
                             glm::normalize(normal_matrix * glm::dvec3(normals[v])), 1e-5,
                             at + " normal " + std::to_string(v));
            }
        }
        // Indices as stored (or the vertices in order), each triangle turned
        // back to counter-clockwise under a mirroring transform.
        std::vector<std::uint32_t> indices(local.size());
        for (std::size_t v = 0; v < indices.size(); ++v) {
            indices[v] = static_cast<std::uint32_t>(v);
        }
        if (t.indices >= 0) {
            indices = tiny_indices(m, t.indices);
        }
        for (std::size_t i = 0; mirrored && i + 2 < indices.size(); i += 3) {
            std::swap(indices[i + 1], indices[i + 2]);
        }
        expect_same(ours.indices, indices, at + " indices");
        glm::dvec3 color(1.0); // glTF's default material
        if (t.material >= 0) {
            const std::vector<double>& f = m.materials.at(static_cast<std::size_t>(t.material))
                                               .pbrMetallicRoughness.baseColorFactor;
            color = {f.at(0), f.at(1), f.at(2)};
        }
        expect_close(ours.color, color, 1e-7, at + " colour");
    }
}

void compare(const CorpusFile& f) {
    SCOPED_TRACE(f.name);
    const OurRead ours = our_read(f);
    const TinyRead theirs = tiny_read(f);
    ASSERT_TRUE(ours.parsed.has_value() && theirs.ok)
        << "a disagreement on the file itself; ours: " << (ours.parsed ? "accepted" : ours.error)
        << "; tinygltf: " << (theirs.ok ? "accepted" : theirs.error);
    const ParsedScene& p = *ours.parsed;
    const tinygltf::Model& m = theirs.model;
    EXPECT_EQ(p.gltf.nodes.size(), m.nodes.size());
    EXPECT_EQ(p.gltf.accessors.size(), m.accessors.size());
    EXPECT_EQ(p.gltf.buffers.size(), m.buffers.size());
    for (std::size_t b = 0; b < std::min(p.gltf.buffers.size(), m.buffers.size()); ++b) {
        expect_same(p.gltf.buffers[b].data, m.buffers[b].data,
                    "buffers[" + std::to_string(b) + "]");
    }
    ASSERT_EQ(p.gltf.materials.size(), m.materials.size());
    for (std::size_t i = 0; i < m.materials.size(); ++i) {
        EXPECT_EQ(p.gltf.materials[i].base_color,
                  m.materials[i].pbrMetallicRoughness.baseColorFactor)
            << "materials[" << i << "]";
    }
    compare_meshes(p.gltf, m);
    const std::vector<TinyPlaced> placed = tiny_placed(m);
    ASSERT_EQ(p.geometry.nodes.size(), placed.size()) << "nodes the scene places";
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const WorldNode& node = p.geometry.nodes[i];
        ASSERT_EQ(node.index, placed[i].node) << "placed node " << i;
        expect_close(node.world, placed[i].world, node.name + " world matrix");
        compare_placed(node, placed[i].world, m);
    }
}

/// tinygltf's reading of an export against the simulation it came from: one
/// node per surface with settled snow, named as snow_run's report names it,
/// holding that surface's snow mesh bit for bit, its POSITION bounds those
/// vertices' own and inside the surface's grid.
void expect_matches_simulation(const tinygltf::Model& m, const Simulation& sim) {
    std::size_t snowed = 0;
    for (const NamedSurface& s : named_surfaces(sim)) {
        SCOPED_TRACE(s.name);
        const auto node = std::find_if(m.nodes.begin(), m.nodes.end(),
                                       [&](const tinygltf::Node& n) { return n.name == s.name; });
        const bool has_snow = surface_stats(*s.surface).settled_units > 0;
        ASSERT_EQ(node != m.nodes.end(), has_snow) << "a node exactly when snow lies there";
        if (!has_snow) {
            continue;
        }
        ++snowed;
        const SnowMesh mesh = build_snow_mesh(*s.surface);
        const std::vector<tinygltf::Primitive>& primitives =
            m.meshes.at(static_cast<std::size_t>(node->mesh)).primitives;
        ASSERT_EQ(primitives.size(), 1u);
        const tinygltf::Primitive& p = primitives[0];
        const int position = p.attributes.at("POSITION");
        expect_same(tiny_vec3(m, position), mesh.positions, "vertices");
        expect_same(tiny_vec3(m, p.attributes.at("NORMAL")), mesh.normals, "normals");
        expect_same(tiny_indices(m, p.indices), mesh.indices, "indices");

        glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-lo);
        for (const glm::vec3& v : mesh.positions) {
            lo = glm::min(lo, glm::dvec3(v));
            hi = glm::max(hi, glm::dvec3(v));
        }
        const tinygltf::Accessor& a = m.accessors.at(static_cast<std::size_t>(position));
        EXPECT_EQ(a.minValues, (std::vector<double>{lo.x, lo.y, lo.z}));
        EXPECT_EQ(a.maxValues, (std::vector<double>{hi.x, hi.y, hi.z}));
        const SnowSurface& g = *s.surface;
        const double slack = 1e-5 * std::max(1.0, static_cast<double>(g.nx + g.nz) * g.cell);
        EXPECT_GE(lo.x, g.x0 - slack);
        EXPECT_GE(lo.z, g.z0 - slack);
        EXPECT_LE(hi.x, g.x0 + g.nx * static_cast<double>(g.cell) + slack);
        EXPECT_LE(hi.z, g.z0 + g.nz * static_cast<double>(g.cell) + slack);
    }
    EXPECT_GT(snowed, 0u) << "an export with nothing to compare";
    EXPECT_EQ(m.nodes.size(), snowed) << "nodes for surfaces the simulation lacks";
}

// --- the corpus ----------------------------------------------------------------

std::vector<CorpusFile> files_in(const std::string& folder) {
    std::vector<fs::path> paths;
    for (const auto& e : fs::directory_iterator(std::string(SNOW_SOURCE_DIR) + "/" + folder)) {
        if (e.path().extension() == ".gltf" || e.path().extension() == ".glb") {
            paths.push_back(e.path());
        }
    }
    std::sort(paths.begin(), paths.end());
    std::vector<CorpusFile> out;
    for (const fs::path& p : paths) {
        out.push_back(from_disk(p));
    }
    return out;
}

TEST(TinygltfOracle, ShippedScenesAgree) {
    const std::vector<CorpusFile> files = files_in("assets/scenes");
    ASSERT_GE(files.size(), 4u);
    for (const CorpusFile& f : files) {
        compare(f);
    }
}

TEST(TinygltfOracle, OtherToolsTestDataAgrees) {
    const std::vector<CorpusFile> files = files_in("assets/testdata");
    ASSERT_GE(files.size(), 2u);
    for (const CorpusFile& f : files) {
        compare(f);
    }
}

TEST(TinygltfOracle, TheTestsOwnFilesAgree) {
    // The files tests/game/scene writes (scene_test_files.hpp): a quad with
    // its buffer in a data: URI, the same as a .glb, the village as a .glb.
    const std::string quad = mesh_gltf(quad_xyz, quad_indices);
    compare({"quad.gltf", quad, "", false});
    compare({"quad.glb", gltf_to_glb(quad), "", true});
    compare({"village.glb", gltf_to_glb(read_text(asset_path("village.gltf"))), "", true});
}

TEST(TinygltfOracle, OurExportsAgreeAndMatchTheSimulation) {
    // snow_run --export's .glb of the village and of a cover scene.
    TempDir dir;
    SceneLoadResult village = load_scene_file(asset_path("village.gltf"));
    ASSERT_NE(village.sim, nullptr) << village.error;
    village.sim->run(300);
    const CoverScene cover = snowed_cover_scene(300);
    const std::pair<const char*, const Simulation*> runs[] = {
        {"village_snow.glb", village.sim.get()}, {"cover_snow.glb", cover.sim.get()}};
    for (const auto& [name, sim] : runs) {
        SCOPED_TRACE(name);
        export_snow_glb(*sim, dir.root() / name);
        const CorpusFile f = from_disk(dir.root() / name);
        ASSERT_TRUE(starts_glb(f.bytes));
        compare(f);
        const TinyRead theirs = tiny_read(f);
        ASSERT_TRUE(theirs.ok) << theirs.error;
        expect_matches_simulation(theirs.model, *sim);
    }
}

// --- tinygltf 2.7's known limits (docs/scenes.md) -------------------------------

TEST(TinygltfOracle, KnownLimitBinChunkBoundsIn270) {
    // A BIN chunk whose length claims 4 bytes more than the file holds, and a
    // buffer that claims them too. tinygltf before 2.8.20 leaves the chunk
    // header out of its bounds check, so it accepts the file and copies 4
    // bytes from past its end (here from slack we put there, so the read stays
    // inside our allocation). Ours names the lying length.
    const std::string quad = gltf_to_glb(mesh_gltf(quad_xyz, quad_indices));
    const std::size_t bin_header = 20 + u32_at(quad, 12);
    ASSERT_EQ(u32_at(quad, bin_header), 60u);
    const std::string lying =
        replaced(with_u32(quad, bin_header, 64), "\"byteLength\":60}]", "\"byteLength\":64}]");
    ASSERT_EQ(lying.size(), quad.size()) << "the JSON keeps its length";

    const OurRead ours = our_read({"lying.glb", lying, "", true});
    EXPECT_FALSE(ours.parsed.has_value());
    EXPECT_NE(ours.error.find("glb chunk 1.length is 64 but only 60 bytes follow its header"),
              std::string::npos)
        << ours.error;

    std::vector<unsigned char> bytes(lying.begin(), lying.end());
    bytes.insert(bytes.end(), {0xAB, 0xAB, 0xAB, 0xAB, 0xAB, 0xAB, 0xAB, 0xAB});
    const TinyRead theirs = tiny_read(bytes, lying.size(), "");
    ASSERT_TRUE(theirs.ok) << "tinygltf now refuses the overrun (" << theirs.error
                           << "): update docs/scenes.md's known limits";
    ASSERT_EQ(theirs.model.buffers.at(0).data.size(), 64u);
    EXPECT_EQ(theirs.model.buffers[0].data[60], 0xAB) << "the bytes after the file's end";
}

TEST(TinygltfOracle, KnownLimitExtrasIntegersAre32BitIn270) {
    // extras.snow.simulation.seed is a 64-bit integer; tinygltf keeps extras'
    // integers as int, so it reads 2^32 + 5 as 5. Ours reads it whole.
    const std::string quad = replaced(
        mesh_gltf(quad_xyz, quad_indices), R"("scenes": [{"nodes": [0]}])",
        R"("scenes": [{"nodes": [0], "extras": {"snow": {"simulation": {"seed": 4294967301}}}}])");
    const OurRead ours = our_read({"seed.gltf", quad, "", false});
    ASSERT_TRUE(ours.parsed.has_value()) << ours.error;
    EXPECT_EQ(ours.parsed->schema.scenes.at(0).config.seed, 4294967301u);
    const TinyRead theirs = tiny_read({"seed.gltf", quad, "", false});
    ASSERT_TRUE(theirs.ok) << theirs.error;
    const tinygltf::Value& seed =
        theirs.model.scenes.at(0).extras.Get("snow").Get("simulation").Get("seed");
    ASSERT_TRUE(seed.IsInt()) << "tinygltf now keeps wider integers: update docs/scenes.md";
    EXPECT_EQ(seed.Get<int>(), 5);
}

} // namespace
} // namespace snow
