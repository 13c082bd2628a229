// Accessor reads with every byte range checked before any byte is touched
// (glTF 2.0 §3.6.2: accessor → bufferView → buffer).
#include "game/scene/scene_accessor.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <span>
#include <string_view>

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

/// What an accessor must hold: its type, its components per element and the
/// component types allowed (named in errors).
struct Layout {
    std::string_view type;
    std::uint64_t components;
    std::span<const std::uint32_t> component_types;
    std::string_view allowed;
};
constexpr std::uint32_t float_types[] = {gltf::float_type};
constexpr std::uint32_t index_types[] = {gltf::unsigned_byte, gltf::unsigned_short,
                                         gltf::unsigned_int};
constexpr Layout vec2_layout{"VEC2", 2, float_types, "5126 (FLOAT)"};
constexpr Layout vec3_layout{"VEC3", 3, float_types, "5126 (FLOAT)"};
constexpr Layout index_layout{"SCALAR", 1, index_types, "5121, 5123 or 5125 (unsigned)"};

/// Validates accessor `index` (type, component type, all ranges) and returns
/// where its elements are.
ByteRange locate(const GltfDocument& doc, std::uint64_t index, const std::string& field,
                 const Layout& layout) {
    if (index >= doc.accessors.size()) {
        scene_fail(field, "refers to accessor " + std::to_string(index) + ", but the file has " +
                              std::to_string(doc.accessors.size()));
    }
    const std::string at = "accessors[" + std::to_string(index) + "]";
    const GltfAccessor& a = doc.accessors[index];
    if (a.sparse) {
        scene_fail(at, "is sparse, which scenes do not support");
    }
    if (a.type != layout.type) {
        scene_fail(at + ".type",
                   "must be " + std::string(layout.type) + " (got " + in_quotes(a.type) + ")");
    }
    if (std::find(layout.component_types.begin(), layout.component_types.end(), a.component_type) ==
        layout.component_types.end()) {
        scene_fail(at + ".componentType", "must be " + std::string(layout.allowed) + " (got " +
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
    const std::span<const unsigned char> view =
        buffer_view_bytes(doc, *a.buffer_view, at + ".bufferView");
    const std::string view_at = "bufferViews[" + std::to_string(*a.buffer_view) + "]";
    const std::uint64_t element = component_size(a.component_type) * layout.components;
    const std::uint32_t byte_stride = doc.buffer_views[*a.buffer_view].byte_stride;
    const std::uint64_t stride = byte_stride == 0 ? element : byte_stride;
    if (stride < element) {
        scene_fail(view_at + ".byteStride", "must be 0 or in [" + std::to_string(element) +
                                                ", 252] (got " + std::to_string(byte_stride) + ")");
    }
    // count in [1, 2^24] and stride <= 252 (the document's range): no overflow.
    const std::uint64_t span = stride * (a.count - 1) + element;
    if (a.byte_offset > view.size() || span > view.size() - a.byte_offset) {
        scene_fail(at, "needs bytes [" + std::to_string(a.byte_offset) + ", +" +
                           std::to_string(span) + ") of " + view_at + ", which has " +
                           std::to_string(view.size()));
    }
    return {view.data() + a.byte_offset, static_cast<std::size_t>(a.count),
            static_cast<std::size_t>(stride)};
}

/// Accessor `index` as finite float vectors of `Vec` (glm::vec2 or vec3).
template <typename Vec>
std::vector<Vec> read_float_accessor(const GltfDocument& doc, std::uint64_t index,
                                     const std::string& field, const Layout& layout) {
    const ByteRange r = locate(doc, index, field, layout);
    std::vector<Vec> out(r.count);
    for (std::size_t i = 0; i < r.count; ++i) {
        Vec v;
        std::memcpy(&v, r.first + i * r.stride, sizeof v); // unaligned-safe
        for (int c = 0; c < Vec::length(); ++c) {
            if (!std::isfinite(v[c])) {
                scene_fail("accessors[" + std::to_string(index) + "]",
                           "element " + std::to_string(i) + " is not finite (NaN or inf)");
            }
        }
        out[i] = v;
    }
    return out;
}

} // namespace

std::span<const unsigned char> buffer_view_bytes(const GltfDocument& doc, std::uint64_t view,
                                                 const std::string& field) {
    if (view >= doc.buffer_views.size()) {
        scene_fail(field, "must name one of the file's " + std::to_string(doc.buffer_views.size()) +
                              " bufferViews (got " + std::to_string(view) + ")");
    }
    const std::string at = "bufferViews[" + std::to_string(view) + "]";
    const GltfBufferView& v = doc.buffer_views[view];
    if (v.buffer >= doc.buffers.size()) {
        scene_fail(at + ".buffer", "must name one of the file's " +
                                       std::to_string(doc.buffers.size()) + " buffers (got " +
                                       std::to_string(v.buffer) + ")");
    }
    const std::vector<unsigned char>& bytes = doc.buffers[v.buffer].data;
    // Subtractions only after the comparisons that keep them non-negative.
    if (v.byte_offset > bytes.size() || v.byte_length > bytes.size() - v.byte_offset) {
        scene_fail(at, "range [" + std::to_string(v.byte_offset) + ", +" +
                           std::to_string(v.byte_length) + ") exceeds its buffer's " +
                           std::to_string(bytes.size()) + " bytes");
    }
    return std::span(bytes).subspan(static_cast<std::size_t>(v.byte_offset),
                                    static_cast<std::size_t>(v.byte_length));
}

std::vector<glm::vec3> read_vec3_accessor(const GltfDocument& doc, std::uint64_t index,
                                          const std::string& field) {
    return read_float_accessor<glm::vec3>(doc, index, field, vec3_layout);
}

std::vector<glm::vec2> read_vec2_accessor(const GltfDocument& doc, std::uint64_t index,
                                          const std::string& field) {
    return read_float_accessor<glm::vec2>(doc, index, field, vec2_layout);
}

std::vector<std::uint32_t> read_index_accessor(const GltfDocument& doc, std::uint64_t index,
                                               const std::string& field) {
    const ByteRange r = locate(doc, index, field, index_layout);
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
