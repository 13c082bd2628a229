// Accessor reads with every byte range checked before any byte is touched.
// tinygltf fills the structs but does not bound-check accessor ranges.
#include "game/scene/scene_accessor.hpp"

#include <bit>
#include <cmath>
#include <cstring>

namespace snow {

// glTF buffers are little-endian; elements are copied as host values.
static_assert(std::endian::native == std::endian::little, "big-endian hosts need byte swaps");

namespace {

/// Where an accessor's elements lie in its buffer's bytes.
struct ByteRange {
    const unsigned char* first = nullptr;
    std::size_t count = 0;
    std::size_t stride = 0;
};

std::size_t component_size(int component_type) {
    switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return 1;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
        return 4;
    default:
        return 0;
    }
}

/// Validates accessor `index` (type, component type, all ranges) and returns
/// where its elements are.
ByteRange locate(const tinygltf::Model& model, int index, const std::string& field, int type,
                 const std::vector<int>& component_types) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) {
        scene_fail(field, "refers to accessor " + std::to_string(index) + ", but the file has " +
                              std::to_string(model.accessors.size()));
    }
    const std::string at = "accessors[" + std::to_string(index) + "]";
    const tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(index)];
    if (a.sparse.isSparse) {
        scene_fail(at, "is sparse, which scenes do not support");
    }
    if (a.type != type) {
        scene_fail(at + ".type", type == TINYGLTF_TYPE_VEC3 ? "must be VEC3" : "must be SCALAR");
    }
    bool known = false;
    for (const int ct : component_types) {
        known = known || ct == a.componentType;
    }
    if (!known) {
        scene_fail(at + ".componentType",
                   "must be " +
                       std::string(type == TINYGLTF_TYPE_VEC3 ? "5126 (FLOAT)"
                                                              : "5121, 5123 or 5125 (unsigned)") +
                       " (got " + std::to_string(a.componentType) + ")");
    }
    if (a.normalized) {
        scene_fail(at + ".normalized", "must be false");
    }
    if (a.count == 0 || a.count > max_accessor_count) {
        scene_fail(at + ".count", "must be in [1, " + std::to_string(max_accessor_count) +
                                      "] (got " + std::to_string(a.count) + ")");
    }
    if (a.bufferView < 0 || static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size()) {
        scene_fail(at + ".bufferView",
                   "must name one of the file's " + std::to_string(model.bufferViews.size()) +
                       " bufferViews (got " + std::to_string(a.bufferView) + ")");
    }
    const std::string view_at = "bufferViews[" + std::to_string(a.bufferView) + "]";
    const tinygltf::BufferView& v = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
    if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= model.buffers.size()) {
        scene_fail(view_at + ".buffer", "must name one of the file's " +
                                            std::to_string(model.buffers.size()) +
                                            " buffers (got " + std::to_string(v.buffer) + ")");
    }
    const std::size_t loaded = model.buffers[static_cast<std::size_t>(v.buffer)].data.size();
    // Subtractions only after the comparisons that keep them non-negative.
    if (v.byteOffset > loaded || v.byteLength > loaded - v.byteOffset) {
        scene_fail(view_at, "range [" + std::to_string(v.byteOffset) + ", +" +
                                std::to_string(v.byteLength) + ") exceeds its buffer's " +
                                std::to_string(loaded) + " bytes");
    }
    const std::size_t element =
        component_size(a.componentType) * (type == TINYGLTF_TYPE_VEC3 ? 3 : 1);
    const std::size_t stride = v.byteStride == 0 ? element : v.byteStride;
    if (stride < element || stride > 252) {
        scene_fail(view_at + ".byteStride", "must be 0 or in [" + std::to_string(element) +
                                                ", 252] (got " + std::to_string(v.byteStride) +
                                                ")");
    }
    // count <= 2^24 and stride <= 252: the product cannot overflow.
    const std::size_t span = stride * (a.count - 1) + element;
    if (a.byteOffset > v.byteLength || span > v.byteLength - a.byteOffset) {
        scene_fail(at, "needs bytes [" + std::to_string(a.byteOffset) + ", +" +
                           std::to_string(span) + ") of " + view_at + ", which has " +
                           std::to_string(v.byteLength));
    }
    const unsigned char* base = model.buffers[static_cast<std::size_t>(v.buffer)].data.data();
    return {base + v.byteOffset + a.byteOffset, a.count, stride};
}

} // namespace

std::vector<glm::vec3> read_vec3_accessor(const tinygltf::Model& model, int index,
                                          const std::string& field) {
    const ByteRange r =
        locate(model, index, field, TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT});
    std::vector<glm::vec3> out(r.count);
    for (std::size_t i = 0; i < r.count; ++i) {
        float xyz[3];
        std::memcpy(xyz, r.first + i * r.stride, sizeof xyz); // unaligned-safe
        if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2])) {
            scene_fail("accessors[" + std::to_string(index) + "]",
                       "element " + std::to_string(i) + " is not finite (NaN or inf)");
        }
        out[i] = {xyz[0], xyz[1], xyz[2]};
    }
    return out;
}

std::vector<std::uint32_t> read_index_accessor(const tinygltf::Model& model, int index,
                                               const std::string& field) {
    const ByteRange r =
        locate(model, index, field, TINYGLTF_TYPE_SCALAR,
               {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT});
    const int type = model.accessors[static_cast<std::size_t>(index)].componentType;
    std::vector<std::uint32_t> out(r.count);
    for (std::size_t i = 0; i < r.count; ++i) {
        const unsigned char* p = r.first + i * r.stride;
        if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) {
            out[i] = *p;
        } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
            std::uint16_t v = 0;
            std::memcpy(&v, p, sizeof v);
            out[i] = v;
        } else {
            std::memcpy(&out[i], p, sizeof out[i]);
        }
    }
    return out;
}

} // namespace snow
