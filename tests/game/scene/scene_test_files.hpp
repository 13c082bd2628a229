/// @file scene_test_files.hpp
/// @brief Test support for the scene loader: glTF files written in the test
/// itself (a one-mesh .gltf around given bytes, a .glb with JSON and BIN
/// chunks), a scratch folder, and checks on a failed load.
#pragma once

#include <snow/scene.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace snow::test {

namespace fs = std::filesystem;

/// A file of assets/scenes/ (the project's scenes).
inline std::string asset_path(const std::string& name) {
    return std::string(SNOW_SOURCE_DIR) + "/assets/scenes/" + name;
}

/// A file of assets/testdata/ (glTF as other tools write it; scripts/make_test_gltf.py).
inline std::string test_data_path(const std::string& name) {
    return std::string(SNOW_SOURCE_DIR) + "/assets/testdata/" + name;
}

inline std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

/// `text` with the first occurrence of `from` replaced (which must exist).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "test setup: '" << from << "' not in the scene";
    if (at != std::string::npos) {
        text.replace(at, from.size(), to);
    }
    return text;
}

/// A failed load: no simulation, and the error contains every fragment.
inline void expect_error(const SceneLoadResult& r, std::initializer_list<std::string> fragments) {
    EXPECT_EQ(r.sim, nullptr) << "expected an error, the scene loaded";
    for (const std::string& f : fragments) {
        EXPECT_NE(r.error.find(f), std::string::npos) << "error: " << r.error << "\nmissing: " << f;
    }
}

/// True when some warning contains `fragment`.
inline bool has_warning(const SceneLoadResult& r, const std::string& fragment) {
    for (const std::string& w : r.warnings) {
        if (w.find(fragment) != std::string::npos) {
            return true;
        }
    }
    return false;
}

inline std::string base64(const std::vector<unsigned char>& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = (bytes[i] << 16) | (i + 1 < bytes.size() ? bytes[i + 1] << 8 : 0) |
                                (i + 2 < bytes.size() ? bytes[i + 2] : 0);
        out += digits[(n >> 18) & 63];
        out += digits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? digits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? digits[n & 63] : '=';
    }
    return out;
}

inline std::vector<unsigned char> unbase64(const std::string& text) {
    const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::vector<unsigned char> out;
    std::uint32_t bits = 0;
    int held = 0;
    for (const char c : text) {
        if (c == '=') {
            break;
        }
        bits = (bits << 6) | static_cast<std::uint32_t>(digits.find(c));
        held += 6;
        if (held >= 8) {
            held -= 8;
            out.push_back(static_cast<unsigned char>(bits >> held));
        }
    }
    return out;
}

/// Bytes of a triangle mesh: float positions, then uint16 indices.
inline std::vector<unsigned char> mesh_bytes(const std::vector<float>& xyz,
                                             const std::vector<std::uint16_t>& indices) {
    std::vector<unsigned char> b(xyz.size() * 4 + indices.size() * 2);
    // memcpy from an empty vector's null data() is undefined even for 0 bytes.
    if (!xyz.empty())
        std::memcpy(b.data(), xyz.data(), xyz.size() * 4);
    if (!indices.empty())
        std::memcpy(b.data() + xyz.size() * 4, indices.data(), indices.size() * 2);
    return b;
}

/// A one-node glTF around a triangle mesh. `uri` empty embeds the bytes.
inline std::string mesh_gltf(const std::vector<float>& xyz,
                             const std::vector<std::uint16_t>& indices,
                             const std::string& node_extras = "", const std::string& uri = "") {
    const std::vector<unsigned char> bytes = mesh_bytes(xyz, indices);
    const std::size_t vbytes = xyz.size() * 4;
    std::ostringstream s;
    s << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0)"
      << node_extras << R"(}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "accessors": [
          {"bufferView": 0, "componentType": 5126, "count": )"
      << xyz.size() / 3 << R"(, "type": "VEC3"},
          {"bufferView": 1, "componentType": 5123, "count": )"
      << indices.size() << R"(, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": )"
      << vbytes << R"(},
          {"buffer": 0, "byteOffset": )"
      << vbytes << R"(, "byteLength": )" << indices.size() * 2 << R"(}],
        "buffers": [{"byteLength": )"
      << bytes.size() << R"(, "uri": ")"
      << (uri.empty() ? "data:application/octet-stream;base64," + base64(bytes) : uri) << R"("}]})";
    return s.str();
}

inline const std::vector<float> quad_xyz{0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1};
inline const std::vector<std::uint16_t> quad_indices{0, 2, 1, 0, 3, 2};

inline void put_u32(std::string& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) {
        out += static_cast<char>((v >> (8 * i)) & 0xFFu);
    }
}

/// `bytes` with the little-endian u32 at `offset` replaced.
inline std::string with_u32(std::string bytes, std::size_t offset, std::uint32_t v) {
    std::string le;
    put_u32(le, v);
    bytes.replace(offset, 4, le);
    return bytes;
}

inline std::uint32_t u32_at(const std::string& bytes, std::size_t offset) {
    std::uint32_t v = 0;
    for (int i = 3; i >= 0; --i) {
        v = (v << 8) | static_cast<unsigned char>(bytes[offset + static_cast<std::size_t>(i)]);
    }
    return v;
}

/// A .glb: header, the JSON chunk (space-padded) and, when `bin` is not
/// empty, the BIN chunk (zero-padded), as glTF 2.0 §4.4 lays them out.
inline std::string glb(std::string json, std::vector<unsigned char> bin = {}) {
    while (json.size() % 4 != 0) {
        json += ' ';
    }
    while (bin.size() % 4 != 0) {
        bin.push_back(0);
    }
    std::string out = "glTF";
    put_u32(out, 2);
    put_u32(out,
            static_cast<std::uint32_t>(12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size())));
    put_u32(out, static_cast<std::uint32_t>(json.size()));
    put_u32(out, 0x4E4F534A);
    out += json;
    if (!bin.empty()) {
        put_u32(out, static_cast<std::uint32_t>(bin.size()));
        put_u32(out, 0x004E4942);
        out.append(bin.begin(), bin.end());
    }
    return out;
}

/// The same scene as a .glb: buffers[0]'s data URI moves into the BIN chunk.
inline std::string gltf_to_glb(const std::string& gltf_text) {
    nlohmann::json doc = nlohmann::json::parse(gltf_text);
    const std::string uri = doc["buffers"][0]["uri"];
    doc["buffers"][0].erase("uri");
    return glb(doc.dump(), unbase64(uri.substr(uri.find(',') + 1)));
}

/// A scratch folder for file tests, removed afterwards.
class TempDir {
  public:
    TempDir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("snow_scene_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_ / "scene");
    }
    ~TempDir() { fs::remove_all(path_); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    [[nodiscard]] fs::path scene_dir() const { return path_ / "scene"; }
    [[nodiscard]] fs::path root() const { return path_; }
    void write(const fs::path& p, const std::string& bytes) const {
        std::ofstream(p, std::ios::binary) << bytes;
    }

  private:
    fs::path path_;
};

} // namespace snow::test
