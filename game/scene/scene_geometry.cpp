// Scene instancing: node graph → world-space meshes. The graph is walked with
// an explicit stack (no recursion for hostile depths) and a seen-mask, so a
// cycle or a node with two parents is an error rather than a hang.
#include "game/scene/scene_geometry.hpp"

#include "game/scene/scene_accessor.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

namespace {

std::string index_name(const char* list, std::uint64_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
}

/// Running totals against the scene caps.
struct Budget {
    std::size_t primitives = 0, vertices = 0, indices = 0;
};

void charge(std::size_t& used, std::size_t add, std::size_t cap, const std::string& field,
            const char* what) {
    used += add;
    if (used > cap) {
        scene_fail(field, std::string("brings the scene over ") + std::to_string(cap) + " " + what);
    }
}

void check_length(const std::vector<double>& v, std::size_t size, const std::string& field) {
    if (!v.empty() && v.size() != size) {
        scene_fail(field, "must have " + std::to_string(size) + " numbers (got " +
                              std::to_string(v.size()) + ")");
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (!std::isfinite(v[i])) {
            scene_fail(field + "[" + std::to_string(i) + "]", "must be finite");
        }
    }
}

glm::dmat4 local_matrix(const GltfNode& n, const std::string& at) {
    check_length(n.matrix, 16, at + ".matrix");
    check_length(n.translation, 3, at + ".translation");
    check_length(n.rotation, 4, at + ".rotation");
    check_length(n.scale, 3, at + ".scale");
    if (!n.matrix.empty()) {
        if (!n.translation.empty() || !n.rotation.empty() || !n.scale.empty()) {
            scene_fail(at, "has both matrix and translation/rotation/scale (glTF allows one)");
        }
        glm::dmat4 m(1.0);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) {
                m[c][r] = n.matrix[static_cast<std::size_t>(c * 4 + r)]; // column-major
            }
        }
        // §5.25: a matrix must decompose into TRS, so its last row is 0 0 0 1.
        if (!(m[0][3] == 0.0 && m[1][3] == 0.0 && m[2][3] == 0.0 && m[3][3] == 1.0)) {
            scene_fail(at + ".matrix", "must be affine (elements 3, 7, 11, 15 = 0, 0, 0, 1)");
        }
        return m;
    }
    glm::dmat4 m(1.0);
    if (!n.translation.empty()) {
        m = glm::translate(m, glm::dvec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (!n.rotation.empty()) {
        // glTF stores (x, y, z, w); glm's constructor takes (w, x, y, z).
        glm::dquat q(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
        const double len = glm::length(q);
        if (!(std::abs(len - 1.0) <= 0.01)) {
            scene_fail(at + ".rotation",
                       "must be a unit quaternion (length " + number_text(len) + ")");
        }
        m = m * glm::mat4_cast(q / len);
    }
    if (!n.scale.empty()) {
        m = glm::scale(m, glm::dvec3(n.scale[0], n.scale[1], n.scale[2]));
    }
    return m;
}

/// A double vector as float, or an error when it does not fit.
glm::vec3 to_float3(const glm::dvec3& v, const std::string& field, const char* what) {
    constexpr double limit = std::numeric_limits<float>::max();
    for (int i = 0; i < 3; ++i) {
        if (!(std::abs(v[i]) <= limit)) {
            scene_fail(field,
                       std::string(what) + " is not finite in float after the node transforms");
        }
    }
    return glm::vec3(v);
}

/// The material `material` names, or null for glTF's default one.
const GltfMaterial* material_of(const GltfDocument& doc, std::optional<std::uint64_t> material,
                                const std::string& at) {
    if (!material) {
        return nullptr;
    }
    if (*material >= doc.materials.size()) {
        scene_fail(at + ".material", "must name one of the file's " +
                                         std::to_string(doc.materials.size()) + " materials (got " +
                                         std::to_string(*material) + ")");
    }
    return &doc.materials[*material];
}

/// The material's baseColorFactor rgb (range and length checked when read)
/// and base colour texture, with the primitive's TEXCOORD_0 it needs.
void apply_material(const GltfDocument& doc, const GltfPrimitive& prim, const std::string& at,
                    WorldPrimitive& out) {
    const GltfMaterial* m = material_of(doc, prim.material, at);
    if (m == nullptr) {
        return; // glTF's default material: white
    }
    out.color = {static_cast<float>(m->base_color[0]), static_cast<float>(m->base_color[1]),
                 static_cast<float>(m->base_color[2])};
    if (!m->base_color_texture) {
        return;
    }
    // scene_buffers decoded it (the indices are checked there).
    out.texture = doc.images[*doc.textures[*m->base_color_texture].source].pixels;
    if (!prim.texcoord) {
        scene_fail(at + ".attributes", "needs TEXCOORD_0: its material (materials[" +
                                           std::to_string(*prim.material) +
                                           "]) has a baseColorTexture");
    }
    out.texcoords = read_vec2_accessor(doc, *prim.texcoord, at + ".attributes.TEXCOORD_0");
    if (out.texcoords.size() != out.positions.size()) {
        scene_fail(at + ".attributes.TEXCOORD_0", "must have as many elements as POSITION (" +
                                                      std::to_string(out.positions.size()) +
                                                      ", got " +
                                                      std::to_string(out.texcoords.size()) + ")");
    }
}

/// Area-weighted vertex normals, for primitives that bring none.
std::vector<glm::vec3> computed_normals(const WorldPrimitive& p) {
    std::vector<glm::dvec3> sum(p.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const glm::dvec3 a(p.positions[p.indices[t]]);
        const glm::dvec3 b(p.positions[p.indices[t + 1]]);
        const glm::dvec3 c(p.positions[p.indices[t + 2]]);
        const glm::dvec3 n = glm::cross(b - a, c - a);
        for (std::size_t k = 0; k < 3; ++k) {
            sum[p.indices[t + k]] += n;
        }
    }
    std::vector<glm::vec3> out(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double len = glm::length(sum[i]);
        // A vertex of only degenerate triangles has no direction: point it up.
        out[i] = len > 0.0 && std::isfinite(len) ? glm::vec3(sum[i] / len) : glm::vec3(0, 1, 0);
    }
    return out;
}

WorldPrimitive world_primitive(const GltfDocument& doc, const GltfPrimitive& prim,
                               const std::string& at, const glm::dmat4& world, Budget& budget) {
    if (!prim.position) {
        scene_fail(at + ".attributes", "needs POSITION");
    }
    WorldPrimitive out;
    out.positions = read_vec3_accessor(doc, *prim.position, at + ".attributes.POSITION");
    const std::size_t n = out.positions.size();
    charge(budget.vertices, n, max_scene_vertices, at, "vertices");
    if (prim.normal) {
        out.normals = read_vec3_accessor(doc, *prim.normal, at + ".attributes.NORMAL");
        if (out.normals.size() != n) {
            scene_fail(at + ".attributes.NORMAL", "must have as many elements as POSITION (" +
                                                      std::to_string(n) + ", got " +
                                                      std::to_string(out.normals.size()) + ")");
        }
    }
    if (prim.indices) {
        out.indices = read_index_accessor(doc, *prim.indices, at + ".indices");
        for (std::size_t i = 0; i < out.indices.size(); ++i) {
            if (out.indices[i] >= n) {
                scene_fail(at + ".indices", "element " + std::to_string(i) + " is " +
                                                std::to_string(out.indices[i]) +
                                                ", but there are " + std::to_string(n) +
                                                " vertices");
            }
        }
    } else { // non-indexed: vertices in order, three per triangle
        out.indices.resize(n);
        for (std::size_t i = 0; i < n; ++i) {
            out.indices[i] = static_cast<std::uint32_t>(i);
        }
    }
    if (out.indices.empty() || out.indices.size() % 3 != 0) {
        scene_fail(at, "must have a positive multiple of 3 indices (got " +
                           std::to_string(out.indices.size()) + ")");
    }
    charge(budget.indices, out.indices.size(), max_scene_indices, at, "indices");
    apply_material(doc, prim, at, out);

    const glm::dmat3 linear(world);
    const double det = glm::determinant(linear);
    if (!(std::isfinite(det) && det != 0.0)) {
        scene_fail(at, "is placed by a singular or non-finite node transform (determinant " +
                           number_text(det) + ")");
    }
    for (glm::vec3& p : out.positions) {
        p = to_float3(glm::dvec3(world * glm::dvec4(glm::dvec3(p), 1.0)),
                      at + ".attributes.POSITION", "a position");
    }
    const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(linear));
    for (std::size_t i = 0; i < out.normals.size(); ++i) {
        const glm::dvec3 v = normal_matrix * glm::dvec3(out.normals[i]);
        const double len = glm::length(v);
        if (!(len > 0.0 && std::isfinite(len))) {
            scene_fail(at + ".attributes.NORMAL",
                       "element " + std::to_string(i) + " has zero or non-finite length");
        }
        out.normals[i] = glm::vec3(v / len);
    }
    if (det < 0.0) { // a mirroring transform: keep triangles counter-clockwise from outside
        for (std::size_t t = 0; t < out.indices.size(); t += 3) {
            std::swap(out.indices[t + 1], out.indices[t + 2]);
        }
    }
    if (out.normals.empty()) {
        out.normals = computed_normals(out);
    }
    return out;
}

/// glTF's names of the primitive modes, for warnings.
const char* mode_name(std::uint32_t mode) {
    static const char* names[] = {"POINTS",    "LINES",          "LINE_LOOP",   "LINE_STRIP",
                                  "TRIANGLES", "TRIANGLE_STRIP", "TRIANGLE_FAN"};
    return mode < std::size(names) ? names[mode] : "unknown";
}

void add_mesh(const GltfDocument& doc, std::uint64_t mesh, const std::string& node_at,
              const glm::dmat4& world, WorldNode& node, Budget& budget,
              std::vector<std::string>& warnings) {
    if (mesh >= doc.meshes.size()) {
        scene_fail(node_at + ".mesh", "must name one of the file's " +
                                          std::to_string(doc.meshes.size()) + " meshes (got " +
                                          std::to_string(mesh) + ")");
    }
    const std::string mesh_at = index_name("meshes", mesh);
    const std::vector<GltfPrimitive>& prims = doc.meshes[mesh].primitives;
    for (std::size_t k = 0; k < prims.size(); ++k) {
        const std::string at = mesh_at + ".primitives[" + std::to_string(k) + "]";
        if (prims[k].mode != gltf::mode_triangles) {
            warnings.push_back(at + ".mode is " + std::to_string(prims[k].mode) + " (" +
                               mode_name(prims[k].mode) +
                               "); only TRIANGLES become geometry, so it is skipped");
            continue;
        }
        charge(budget.primitives, 1, max_scene_primitives, at, "primitives");
        node.primitives.push_back(world_primitive(doc, prims[k], at, world, budget));
    }
    if (node.primitives.empty()) {
        return;
    }
    node.bounds = {node.primitives[0].positions[0], node.primitives[0].positions[0]};
    for (const WorldPrimitive& p : node.primitives) {
        for (const glm::vec3& v : p.positions) {
            node.bounds.min = glm::min(node.bounds.min, v);
            node.bounds.max = glm::max(node.bounds.max, v);
        }
    }
}

/// A node to visit: its index, its parent's world transform and the property
/// that named it (for errors).
struct Pending {
    std::uint64_t node;
    glm::dmat4 parent;
    std::string via;
};

/// The root nodes to start from, last first (the walk pops from the back).
std::vector<Pending> roots(const GltfDocument& doc, SceneGeometry& g) {
    std::vector<Pending> stack;
    if (doc.scenes.empty()) {
        if (doc.scene) {
            scene_fail("scene", "refers to scene " + std::to_string(*doc.scene) +
                                    ", but the file has no scenes");
        }
        // §3.3: without scenes, the file's content is its root nodes. Children
        // named out of range fail later, at their parent.
        std::vector<char> is_child(doc.nodes.size(), 0);
        for (const GltfNode& n : doc.nodes) {
            for (const std::uint64_t c : n.children) {
                if (c < is_child.size()) {
                    is_child[c] = 1;
                }
            }
        }
        for (std::size_t i = doc.nodes.size(); i-- > 0;) {
            if (is_child[i] == 0) {
                stack.push_back({i, glm::dmat4(1.0), "root node"});
            }
        }
        return stack;
    }
    const std::uint64_t chosen = doc.scene.value_or(0);
    if (chosen >= doc.scenes.size()) {
        scene_fail("scene", "must name one of the file's " + std::to_string(doc.scenes.size()) +
                                " scenes (got " + std::to_string(chosen) + ")");
    }
    g.scene_index = static_cast<std::size_t>(chosen);
    const GltfScene& scene = doc.scenes[chosen];
    g.scene_name = scene.name;
    const std::string list = index_name("scenes", chosen) + ".nodes";
    for (std::size_t k = scene.nodes.size(); k-- > 0;) {
        stack.push_back({scene.nodes[k], glm::dmat4(1.0), list + "[" + std::to_string(k) + "]"});
    }
    return stack;
}

} // namespace

SceneGeometry instance_scene(const GltfDocument& doc, std::vector<std::string>& warnings) {
    if (doc.nodes.size() > max_scene_nodes) {
        scene_fail("nodes", "must have at most " + std::to_string(max_scene_nodes) +
                                " entries (got " + std::to_string(doc.nodes.size()) + ")");
    }
    SceneGeometry g;
    std::vector<Pending> stack = roots(doc, g);
    std::vector<char> seen(doc.nodes.size(), 0);
    Budget budget;
    while (!stack.empty()) {
        const Pending item = std::move(stack.back());
        stack.pop_back();
        if (item.node >= doc.nodes.size()) {
            scene_fail(item.via, "must name one of the file's " + std::to_string(doc.nodes.size()) +
                                     " nodes (got " + std::to_string(item.node) + ")");
        }
        const auto i = static_cast<std::size_t>(item.node);
        const std::string at = index_name("nodes", i);
        if (seen[i] != 0) {
            scene_fail(at, "is reached twice from the scene (a cycle, or a child of two parents)");
        }
        seen[i] = 1;
        const GltfNode& n = doc.nodes[i];
        const glm::dmat4 world = item.parent * local_matrix(n, at);
        WorldNode node;
        node.index = i;
        node.name = n.name.empty() ? at : n.name;
        node.world = world;
        node.position = to_float3(glm::dvec3(world[3]), at, "the origin");
        if (n.mesh) {
            add_mesh(doc, *n.mesh, at, world, node, budget, warnings);
        }
        g.nodes.push_back(std::move(node));
        for (std::size_t k = n.children.size(); k-- > 0;) {
            stack.push_back({n.children[k], world, at + ".children[" + std::to_string(k) + "]"});
        }
    }
    return g;
}

std::vector<glm::vec3> node_triangles(const WorldNode& node) {
    std::vector<glm::vec3> out;
    for (const WorldPrimitive& p : node.primitives) {
        for (const std::uint32_t i : p.indices) {
            out.push_back(p.positions[i]);
        }
    }
    return out;
}

} // namespace snow
