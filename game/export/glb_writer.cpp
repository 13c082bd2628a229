#include "game/export/glb_writer.hpp"

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace snow {

namespace {

// glTF constants (glTF 2.0 §3.6 and §4.4).
constexpr std::uint32_t glb_magic = 0x46546C67; // "glTF"
constexpr std::uint32_t chunk_json = 0x4E4F534A;
constexpr std::uint32_t chunk_bin = 0x004E4942;
constexpr int component_float = 5126;
constexpr int component_uint = 5125;
constexpr int target_vertices = 34962;
constexpr int target_indices = 34963;
constexpr int mode_triangles = 4;

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int b = 0; b < 4; ++b) {
        out.push_back(static_cast<std::uint8_t>(v >> (8 * b)));
    }
}

/// Appends `bytes` to the binary chunk as a new bufferView (4-byte aligned).
int add_view(nlohmann::ordered_json& views, std::vector<std::uint8_t>& bin, const void* bytes,
             std::size_t size, int target) {
    const std::size_t offset = bin.size();
    bin.resize(offset + size);
    if (size != 0)
        std::memcpy(bin.data() + offset, bytes, size);
    bin.resize((bin.size() + 3) & ~std::size_t{3}, 0);
    views.push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}, {"target", target}});
    return static_cast<int>(views.size()) - 1;
}

int add_accessor(nlohmann::ordered_json& accessors, nlohmann::ordered_json a) {
    accessors.push_back(std::move(a));
    return static_cast<int>(accessors.size()) - 1;
}

} // namespace

std::vector<std::uint8_t> encode_glb(const std::vector<NamedMesh>& meshes,
                                     std::string_view generator) {
    using json = nlohmann::ordered_json;
    json views = json::array(), accessors = json::array(), gl_meshes = json::array();
    json nodes = json::array(), scene_nodes = json::array();
    std::vector<std::uint8_t> bin;
    std::size_t bin_size = 0;
    for (const NamedMesh& nm : meshes) {
        if (nm.mesh != nullptr) {
            bin_size += nm.mesh->positions.size() * 2 * sizeof(glm::vec3) +
                        nm.mesh->indices.size() * sizeof(std::uint32_t);
        }
    }
    bin.reserve(bin_size);
    for (const NamedMesh& nm : meshes) {
        if (nm.mesh == nullptr || nm.mesh->empty()) {
            continue;
        }
        const SnowMesh& m = *nm.mesh;
        glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
        for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const std::size_t vec3_bytes = m.positions.size() * sizeof(glm::vec3);
        const int pos = add_accessor(
            accessors,
            {{"bufferView", add_view(views, bin, m.positions.data(), vec3_bytes, target_vertices)},
             {"componentType", component_float},
             {"count", m.positions.size()},
             {"type", "VEC3"},
             {"min", {lo.x, lo.y, lo.z}},
             {"max", {hi.x, hi.y, hi.z}}});
        const int nrm = add_accessor(
            accessors,
            {{"bufferView", add_view(views, bin, m.normals.data(), vec3_bytes, target_vertices)},
             {"componentType", component_float},
             {"count", m.normals.size()},
             {"type", "VEC3"}});
        const int idx = add_accessor(
            accessors,
            {{"bufferView", add_view(views, bin, m.indices.data(),
                                     m.indices.size() * sizeof(std::uint32_t), target_indices)},
             {"componentType", component_uint},
             {"count", m.indices.size()},
             {"type", "SCALAR"}});
        scene_nodes.push_back(nodes.size());
        nodes.push_back({{"name", nm.name}, {"mesh", gl_meshes.size()}});
        gl_meshes.push_back({{"name", nm.name},
                             {"primitives",
                              {{{"attributes", {{"POSITION", pos}, {"NORMAL", nrm}}},
                                {"indices", idx},
                                {"material", 0},
                                {"mode", mode_triangles}}}}});
    }
    json doc;
    doc["asset"] = {{"version", "2.0"}, {"generator", generator}};
    doc["scene"] = 0;
    doc["scenes"] = {{{"name", "snow"}}};
    if (!nodes.empty()) {
        doc["scenes"][0]["nodes"] = scene_nodes;
        doc["nodes"] = nodes;
        // Fresh snow: bright, slightly blue, not metallic, very rough.
        doc["materials"] = {{{"name", "snow"},
                             {"pbrMetallicRoughness",
                              {{"baseColorFactor", {0.92, 0.94, 0.97, 1.0}},
                               {"metallicFactor", 0.0},
                               {"roughnessFactor", 0.9}}}}};
        doc["meshes"] = gl_meshes;
        doc["accessors"] = accessors;
        doc["bufferViews"] = views;
        doc["buffers"] = {{{"byteLength", bin.size()}}};
    }
    std::string text = doc.dump();
    text.resize((text.size() + 3) & ~std::size_t{3}, ' '); // the JSON chunk pads with spaces
    const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    if (total > std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("the snow meshes need " + std::to_string(total) +
                                " bytes; one .glb holds at most 4 GiB");
    }
    std::vector<std::uint8_t> out;
    out.reserve(total);
    append_u32(out, glb_magic);
    append_u32(out, 2);
    append_u32(out, static_cast<std::uint32_t>(total));
    append_u32(out, static_cast<std::uint32_t>(text.size()));
    append_u32(out, chunk_json);
    out.insert(out.end(), text.begin(), text.end());
    if (!bin.empty()) {
        append_u32(out, static_cast<std::uint32_t>(bin.size()));
        append_u32(out, chunk_bin);
        out.insert(out.end(), bin.begin(), bin.end());
    }
    return out;
}

} // namespace snow
