// Accessor reads with every byte range checked before any byte is touched
// (glTF 2.0 §3.6.2: accessor → bufferView → buffer).
#include "game/scene/scene_accessor.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <initializer_list>

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

std::size_t component_size(std::uint32_t component_type) {
    switch (component_type) {
    case gltf::unsigned_byte:
        return 1;
    case gltf::unsigned_short:
        return 2;
    case gltf::unsigned_int:
    case gltf::float_type:
        return 4;
    default:
        return 0;
    }
}

/// Validates accessor `index` (type, component type, all ranges) and returns
/// where its elements are. `vec3` false: SCALAR.
ByteRange locate(const GltfDocument& doc, std::uint64_t index, const std::string& field, bool vec3,
                 std::initializer_list<std::uint32_t> component_types) {
    if (index >= doc.accessors.size()) {
        scene_fail(field, "refers to accessor " + std::to_string(index) + ", but the file has " +
                              std::to_string(doc.accessors.size()));
    }
    const std::string at = "accessors[" + std::to_string(index) + "]";
    const GltfAccessor& a = doc.accessors[index];
    if (a.sparse) {
        scene_fail(at, "is sparse, which scenes do not support");
    }
    if (a.type != (vec3 ? "VEC3" : "SCALAR")) {
        scene_fail(at + ".type", std::string(vec3 ? "must be VEC3" : "must be SCALAR") + " (got " +
                                     in_quotes(a.type) + ")");
    }
    if (std::find(component_types.begin(), component_types.end(), a.component_type) ==
        component_types.end()) {
        scene_fail(at + ".componentType",
                   std::string("must be ") +
                       (vec3 ? "5126 (FLOAT)" : "5121, 5123 or 5125 (unsigned)") + " (got " +
                       std::to_string(a.component_type) + ")");
    }
    if (a.normalized) {
        scene_fail(at + ".normalized", "must be false");
    }
    if (a.count > max_accessor_count) {
        scene_fail(at + ".count", "must be in [1, " + std::to_string(max_accessor_count) +
                                      "] (got " + std::to_string(a.count) + ")");
    }
    if (!a.buffer_view || *a.buffer_view >= doc.buffer_views.size()) {
        scene_fail(at + ".bufferView",
                   "must name one of the file's " + std::to_string(doc.buffer_views.size()) +
                       " bufferViews" +
                       (a.buffer_view ? " (got " + std::to_string(*a.buffer_view) + ")"
                                      : " (an accessor without one is all zeros, which "
                                        "scenes do not support)"));
    }
    const std::string view_at = "bufferViews[" + std::to_string(*a.buffer_view) + "]";
    const GltfBufferView& v = doc.buffer_views[*a.buffer_view];
    if (v.buffer >= doc.buffers.size()) {
        scene_fail(view_at + ".buffer", "must name one of the file's " +
                                            std::to_string(doc.buffers.size()) + " buffers (got " +
                                            std::to_string(v.buffer) + ")");
    }
    const std::vector<unsigned char>& bytes = doc.buffers[v.buffer].data;
    const std::uint64_t loaded = bytes.size();
    // Subtractions only after the comparisons that keep them non-negative.
    if (v.byte_offset > loaded || v.byte_length > loaded - v.byte_offset) {
        scene_fail(view_at, "range [" + std::to_string(v.byte_offset) + ", +" +
                                std::to_string(v.byte_length) + ") exceeds its buffer's " +
                                std::to_string(loaded) + " bytes");
    }
    const std::uint64_t element = component_size(a.component_type) * (vec3 ? 3 : 1);
    const std::uint64_t stride = v.byte_stride == 0 ? element : v.byte_stride;
    if (stride < element) {
        scene_fail(view_at + ".byteStride", "must be 0 or in [" + std::to_string(element) +
                                                ", 252] (got " + std::to_string(v.byte_stride) +
                                                ")");
    }
    // count in [1, 2^24] and stride <= 252 (the document's range): no overflow.
    const std::uint64_t span = stride * (a.count - 1) + element;
    if (a.byte_offset > v.byte_length || span > v.byte_length - a.byte_offset) {
        scene_fail(at, "needs bytes [" + std::to_string(a.byte_offset) + ", +" +
                           std::to_string(span) + ") of " + view_at + ", which has " +
                           std::to_string(v.byte_length));
    }
    return {bytes.data() + v.byte_offset + a.byte_offset, static_cast<std::size_t>(a.count),
            static_cast<std::size_t>(stride)};
}

} // namespace

std::vector<glm::vec3> read_vec3_accessor(const GltfDocument& doc, std::uint64_t index,
                                          const std::string& field) {
    const ByteRange r = locate(doc, index, field, true, {gltf::float_type});
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

std::vector<std::uint32_t> read_index_accessor(const GltfDocument& doc, std::uint64_t index,
                                               const std::string& field) {
    const ByteRange r = locate(doc, index, field, false,
                               {gltf::unsigned_byte, gltf::unsigned_short, gltf::unsigned_int});
    const std::uint32_t type = doc.accessors[index].component_type;
    std::vector<std::uint32_t> out(r.count);
    for (std::size_t i = 0; i < r.count; ++i) {
        const unsigned char* p = r.first + i * r.stride;
        if (type == gltf::unsigned_byte) {
            out[i] = *p;
        } else if (type == gltf::unsigned_short) {
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
