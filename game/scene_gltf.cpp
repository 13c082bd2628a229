// tinygltf with its file system fenced in and image decoding off. History
// (docs/design.md "Bad input"): CVE-2022-3008 (wordexp on URIs), `../` traversal (#373),
// .glb heap overflows (#372, #363). So: ASCII only, our own fs callbacks that
// resolve every path and refuse anything outside the scene's folder, and a
// no-op image loader (the simulation needs no textures; stb_image never runs).
#include "game/scene_gltf.hpp"

#include "game/scene_loader.hpp"

#include <filesystem>
#include <fstream>
#include <optional>

namespace snow {

namespace fs = std::filesystem;

namespace {

/// What tinygltf may read: files below `root` (canonical; empty = none), in
/// total at most `budget` bytes.
struct FsFence {
    fs::path root;
    std::size_t budget = max_scene_buffer_bytes;
};

/// The canonical form of `path` if it lies strictly inside the fence's root.
std::optional<fs::path> fenced(const FsFence& fence, const std::string& path) {
    if (fence.root.empty() || path.empty()) {
        return std::nullopt;
    }
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec);
    if (ec) {
        return std::nullopt;
    }
    // weakly_canonical resolves symlinks, so a link pointing out is refused too.
    const fs::path canon = fs::weakly_canonical(absolute, ec);
    if (ec) {
        return std::nullopt;
    }
    auto c = canon.begin();
    for (auto r = fence.root.begin(); r != fence.root.end(); ++r, ++c) {
        if (c == canon.end() || *r != *c) {
            return std::nullopt;
        }
    }
    if (c == canon.end()) {
        return std::nullopt; // the folder itself
    }
    return canon;
}

bool fs_exists(const std::string& path, void* user) {
    const auto p = fenced(*static_cast<FsFence*>(user), path);
    std::error_code ec;
    return p && fs::is_regular_file(*p, ec);
}

// No `~` or `$VAR` expansion: URIs are taken literally (CVE-2022-3008).
std::string fs_expand(const std::string& path, void*) {
    return path;
}

bool fs_read(std::vector<unsigned char>* out, std::string* err, const std::string& path,
             void* user) {
    FsFence& fence = *static_cast<FsFence*>(user);
    const auto p = fenced(fence, path);
    std::error_code ec;
    if (!p || !fs::is_regular_file(*p, ec)) {
        *err = "refused: not a file inside the scene's folder";
        return false;
    }
    const std::uintmax_t size = fs::file_size(*p, ec);
    if (ec || size > fence.budget) {
        *err = "refused: buffers larger than " + std::to_string(max_scene_buffer_bytes >> 20) +
               " MiB in total";
        return false;
    }
    std::ifstream in(*p, std::ios::binary);
    out->resize(static_cast<std::size_t>(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), static_cast<std::streamsize>(size))) {
        *err = "read failed";
        return false;
    }
    fence.budget -= static_cast<std::size_t>(size);
    return true;
}

bool fs_write(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
    *err = "writing is disabled";
    return false;
}

// Images are never decoded: the simulation and renderer use base colours only.
bool skip_image(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                const unsigned char*, int, void*) {
    return true;
}

std::string first_line(const std::string& s) {
    const std::size_t end = s.find('\n');
    return end == std::string::npos ? s : s.substr(0, end);
}

void check_uri(const std::string& uri, const std::string& field, bool files_allowed) {
    if (uri.rfind("data:", 0) == 0) {
        return;
    }
    if (!files_allowed) {
        scene_fail(field, "names an external file ('" + uri +
                              "'), which a scene loaded from memory may not; embed it as a "
                              "data: URI");
    }
    if (uri.empty()) {
        scene_fail(field, "must not be empty");
    }
    if (uri.find('%') != std::string::npos) {
        scene_fail(field, "must not contain %-escapes (got '" + uri + "')");
    }
    if (uri.front() == '/' || uri.find('\\') != std::string::npos ||
        uri.find(':') != std::string::npos) {
        scene_fail(field, "must be a relative path inside the scene's folder (got '" + uri + "')");
    }
    for (const auto& part : fs::path(uri)) {
        if (part == "..") {
            scene_fail(field, "must not leave the scene's folder (got '" + uri + "')");
        }
    }
}

} // namespace

void check_uris(const Json& doc, bool files_allowed) {
    for (const char* list : {"buffers", "images"}) {
        const auto it = doc.find(list);
        if (it == doc.end() || !it->is_array()) {
            continue; // tinygltf reports the structural error
        }
        for (std::size_t i = 0; i < it->size(); ++i) {
            const Json& item = (*it)[i];
            if (item.is_object() && item.contains("uri") && item["uri"].is_string()) {
                check_uri(item["uri"].get<std::string>(),
                          std::string(list) + "[" + std::to_string(i) + "].uri", files_allowed);
            }
        }
    }
}

tinygltf::Model parse_gltf(std::string_view text, const std::string& folder) {
    FsFence fence;
    if (!folder.empty()) {
        std::error_code ec;
        fence.root = fs::weakly_canonical(folder, ec);
        if (ec) {
            throw SceneError("cannot resolve the scene's folder '" + folder + "'");
        }
    }
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(&skip_image, nullptr);
    loader.SetFsCallbacks({&fs_exists, &fs_expand, &fs_read, &fs_write, &fence});
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = loader.LoadASCIIFromString(&model, &err, &warn, text.data(),
                                               static_cast<unsigned>(text.size()), folder);
    if (!ok || !err.empty()) {
        throw SceneError("glTF error: " + first_line(err.empty() ? "tinygltf failed" : err));
    }
    // A missing image, for one, is only a warning in tinygltf (docs/toolchain.md).
    if (!warn.empty()) {
        throw SceneError("glTF warning (treated as an error): " + first_line(warn));
    }
    return model;
}

} // namespace snow
