// The .glb container (glTF 2.0 §4.4): header {magic, version, length}, then
// chunks {length, type, data}. tinygltf's own .glb reader had heap overflows
// from lying chunk lengths, so every length here is compared with the bytes
// that are really there, in 64-bit arithmetic, before it is used.
#include "game/scene/scene_container.hpp"

#include "game/scene/scene_error.hpp"

#include <bit>
#include <cstring>
#include <string>

namespace snow {

namespace {

// The container is little-endian; fields are copied as host values.
static_assert(std::endian::native == std::endian::little, "big-endian hosts need byte swaps");

constexpr std::uint32_t chunk_json = 0x4E4F534A; // "JSON"
constexpr std::uint32_t chunk_bin = 0x004E4942;  // "BIN\0"
constexpr std::uint64_t header_bytes = 12, chunk_header_bytes = 8;

std::uint32_t u32_at(std::string_view bytes, std::uint64_t offset) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, sizeof v);
    return v;
}

std::string hex(std::uint32_t v) {
    static const char* digits = "0123456789ABCDEF";
    std::string out = "0x";
    for (int shift = 28; shift >= 0; shift -= 4) {
        out += digits[(v >> shift) & 15u];
    }
    return out;
}

} // namespace

bool is_glb(std::string_view bytes) {
    return bytes.substr(0, glb_magic.size()) == glb_magic;
}

SceneSource split_glb(std::string_view bytes) {
    const std::uint64_t size = bytes.size();
    if (size < header_bytes) {
        scene_fail("glb header", "needs 12 bytes (the file has " + std::to_string(size) + ")");
    }
    if (!is_glb(bytes)) {
        scene_fail("glb header.magic",
                   "must be \"glTF\" (a .glb file; got " + hex(u32_at(bytes, 0)) + ")");
    }
    if (const std::uint32_t version = u32_at(bytes, 4); version != 2) {
        scene_fail("glb header.version",
                   "must be 2 (only glTF 2 is supported; got " + std::to_string(version) + ")");
    }
    const std::uint64_t length = u32_at(bytes, 8);
    if (length != size) {
        scene_fail("glb header.length", "is " + std::to_string(length) + " but the file has " +
                                            std::to_string(size) + " bytes" +
                                            (length > size ? " (truncated?)" : ""));
    }
    SceneSource out;
    std::uint64_t offset = header_bytes;
    for (std::size_t k = 0; offset < length; ++k) {
        const std::string at = "glb chunk " + std::to_string(k);
        if (length - offset < chunk_header_bytes) {
            scene_fail(at, "header needs 8 bytes at offset " + std::to_string(offset) +
                               " (the file has " + std::to_string(length - offset) + " left)");
        }
        const std::uint64_t chunk_length = u32_at(bytes, offset);
        const std::uint32_t type = u32_at(bytes, offset + 4);
        const std::uint64_t data = offset + chunk_header_bytes;
        if (chunk_length > length - data) {
            scene_fail(at + ".length", "is " + std::to_string(chunk_length) + " but only " +
                                           std::to_string(length - data) +
                                           " bytes follow its header");
        }
        if (k == 0 && type != chunk_json) {
            scene_fail(at + ".type", "must be " + hex(chunk_json) +
                                         " (JSON; the first chunk) (got " + hex(type) + ")");
        }
        if (k == 0) {
            if (chunk_length == 0) {
                scene_fail(at, "(JSON) is empty");
            }
            out.json = bytes.substr(data, chunk_length);
        } else if (type == chunk_json) {
            scene_fail(at + ".type", "is a second JSON chunk (a .glb has one)");
        } else if (type == chunk_bin) {
            if (k != 1) {
                scene_fail(at, "is a BIN chunk, which must directly follow the JSON chunk");
            }
            out.bin = std::span(reinterpret_cast<const unsigned char*>(bytes.data() + data),
                                chunk_length);
        } // chunks of other types are skipped, as the spec asks
        offset = data + chunk_length;
    }
    if (out.json.empty()) {
        scene_fail("glb", "has no JSON chunk");
    }
    return out;
}

} // namespace snow
