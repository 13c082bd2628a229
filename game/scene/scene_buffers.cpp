// Buffer bytes, with file access fenced to the scene's folder. History of
// glTF loaders: wordexp on URIs (tinygltf CVE-2022-3008), `../` traversal,
// symlinks out of the folder. So URIs are taken literally (no `~`, no `$`),
// relative paths only, and the resolved path (symlinks followed) must still
// lie inside the folder.
#include "game/scene/scene_buffers.hpp"

#include "game/scene/scene_accessor.hpp"
#include "game/scene/scene_image.hpp"

#include <snow/scene.hpp>

#include <array>
#include <filesystem>
#include <fstream>
#include <memory>
#include <span>

namespace snow {

namespace fs = std::filesystem;

namespace {

std::string list_item(const char* list, std::size_t i) {
    return std::string(list) + "[" + std::to_string(i) + "]";
}

/// The 6-bit value of a base64 digit, or -1.
int base64_digit(char c) {
    if (c >= 'A' && c <= 'Z') {
        return c - 'A';
    }
    if (c >= 'a' && c <= 'z') {
        return c - 'a' + 26;
    }
    if (c >= '0' && c <= '9') {
        return c - '0' + 52;
    }
    return c == '+' ? 62 : c == '/' ? 63 : -1;
}

/// Decodes base64 (padding optional); throws naming `field` at a bad character.
std::vector<unsigned char> decode_base64(std::string_view text, const std::string& field) {
    while (!text.empty() && text.back() == '=') {
        text.remove_suffix(1);
    }
    std::vector<unsigned char> out;
    out.reserve(text.size() / 4 * 3 + 2);
    std::uint32_t bits = 0;
    int held = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const int d = base64_digit(text[i]);
        if (d < 0) {
            scene_fail(field,
                       "is not valid base64 (character " + std::to_string(i) + " of the data)");
        }
        bits = (bits << 6) | static_cast<std::uint32_t>(d);
        held += 6;
        if (held >= 8) {
            held -= 8;
            out.push_back(static_cast<unsigned char>(bits >> held));
        }
    }
    return out;
}

/// The bytes of a `data:...;base64,` URI.
std::vector<unsigned char> data_uri_bytes(const std::string& uri, const std::string& field) {
    const std::size_t comma = uri.find(',');
    const std::string_view header = std::string_view(uri).substr(0, comma);
    if (comma == std::string::npos || !header.ends_with(";base64")) {
        scene_fail(field, "must be a base64 data URI (data:<type>;base64,<data>)");
    }
    return decode_base64(std::string_view(uri).substr(comma + 1), field);
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9') {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f') {
        return c - 'a' + 10;
    }
    return c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
}

/// The URI with %XX escapes decoded (glTF URIs are RFC 3986 references), or
/// the reason it cannot be.
std::string percent_decoded(const std::string& uri, std::string& problem) {
    std::string out;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] != '%') {
            out += uri[i];
            continue;
        }
        const int hi = i + 2 < uri.size() ? hex_digit(uri[i + 1]) : -1;
        const int lo = hi >= 0 ? hex_digit(uri[i + 2]) : -1;
        if (lo < 0) {
            problem = "has a malformed %-escape";
            return {};
        }
        out += static_cast<char>(hi * 16 + lo);
        i += 2;
    }
    return out;
}

/// Why `path` (decoded) is not a relative path inside the folder; empty if it is.
std::string path_problem(const std::string& path) {
    if (path.empty()) {
        return "is empty";
    }
    if (path.front() == '/' || path.find('\\') != std::string::npos ||
        path.find(':') != std::string::npos || path.find('\0') != std::string::npos) {
        return "must be a relative path inside the scene's folder";
    }
    for (const auto& part : fs::path(path)) {
        if (part == "..") {
            return "must not leave the scene's folder";
        }
    }
    return {};
}

/// The resolved file `relative` names, if it is a regular file inside `root`
/// (canonical). weakly_canonical follows symlinks, so a link pointing out is
/// refused too.
std::optional<fs::path> file_inside(const fs::path& root, const std::string& relative) {
    std::error_code ec;
    const fs::path canon = fs::weakly_canonical(root / relative, ec);
    if (ec) {
        return std::nullopt;
    }
    auto c = canon.begin();
    for (auto r = root.begin(); r != root.end(); ++r, ++c) {
        if (c == canon.end() || *r != *c) {
            return std::nullopt;
        }
    }
    if (c == canon.end() || !fs::is_regular_file(canon, ec)) {
        return std::nullopt;
    }
    return canon;
}

/// The file `uri` names inside the folder; throws naming `field` otherwise.
fs::path fenced_file(const fs::path& root, const std::string& uri, const std::string& field) {
    std::string problem;
    const std::string relative = percent_decoded(uri, problem);
    if (problem.empty()) {
        problem = path_problem(relative);
    }
    if (!problem.empty()) {
        scene_fail(field, problem + " (got '" + uri + "')");
    }
    const auto file = file_inside(root, relative);
    if (!file) {
        scene_fail(field, "names '" + uri + "', which is not a file inside the scene's folder");
    }
    return *file;
}

/// The first `length` bytes of `file` (checked to hold at least that many).
std::vector<unsigned char> file_bytes(const fs::path& file, const std::string& uri,
                                      std::uint64_t length, const std::string& field) {
    std::vector<unsigned char> out(static_cast<std::size_t>(length));
    std::ifstream in(file, std::ios::binary);
    if (!in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(length))) {
        scene_fail(field, "names '" + uri + "', which could not be read");
    }
    return out;
}

/// The size of `file`, or a failure naming `field`.
std::uint64_t file_size(const fs::path& file, const std::string& uri, const std::string& field) {
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) {
        scene_fail(field, "names '" + uri + "', whose size could not be read");
    }
    return size;
}

void load_buffer(GltfBuffer& b, std::size_t i, const BufferSources& sources, const fs::path& root) {
    const std::string at = list_item("buffers", i);
    if (!b.uri) {
        if (i != 0 || !sources.bin) {
            scene_fail(at + ".uri", sources.bin
                                        ? "is required (only buffers[0] may use the .glb's BIN "
                                          "chunk)"
                                        : "is required (the file has no .glb BIN chunk to stand "
                                          "in for it)");
        }
        if (sources.bin->size() < b.byte_length) {
            scene_fail(at + ".byteLength", "is " + std::to_string(b.byte_length) +
                                               " but the .glb's BIN chunk has " +
                                               std::to_string(sources.bin->size()) + " bytes");
        }
        b.data.assign(sources.bin->begin(),
                      sources.bin->begin() + static_cast<std::ptrdiff_t>(b.byte_length));
        return;
    }
    const std::string field = at + ".uri";
    if (b.uri->starts_with("data:")) {
        b.data = data_uri_bytes(*b.uri, field);
        if (b.data.size() < b.byte_length) {
            scene_fail(at + ".byteLength", "is " + std::to_string(b.byte_length) +
                                               " but its data: URI holds " +
                                               std::to_string(b.data.size()) + " bytes");
        }
        b.data.resize(static_cast<std::size_t>(b.byte_length));
        return;
    }
    if (root.empty()) {
        scene_fail(field, "names an external file ('" + *b.uri +
                              "'), which a scene loaded from memory may not; embed it as a "
                              "data: URI or in a .glb");
    }
    const fs::path file = fenced_file(root, *b.uri, field);
    if (const std::uint64_t size = file_size(file, *b.uri, field); size < b.byte_length) {
        scene_fail(field, "names '" + *b.uri + "', which has " + std::to_string(size) +
                              " bytes; the buffer's byteLength is " +
                              std::to_string(b.byte_length));
    }
    b.data = file_bytes(file, *b.uri, b.byte_length, field);
}

/// Decodes image `i` from its bufferView, data: URI or file inside the folder.
std::shared_ptr<const Image> decode_image(const GltfDocument& doc, std::size_t i,
                                          const fs::path& root, std::uint64_t& texels) {
    const std::string at = list_item("images", i);
    const GltfImage& image = doc.images[i];
    if (image.buffer_view) {
        return std::make_shared<const Image>(
            decode_png(buffer_view_bytes(doc, *image.buffer_view, at + ".bufferView"), at, texels));
    }
    if (!image.uri) {
        scene_fail(at, "needs a uri or a bufferView");
    }
    const std::string field = at + ".uri";
    std::vector<unsigned char> bytes;
    if (image.uri->starts_with("data:")) {
        bytes = data_uri_bytes(*image.uri, field);
    } else if (root.empty()) {
        scene_fail(field, "names an external file ('" + *image.uri +
                              "'), which a scene loaded from memory may not; embed it as a "
                              "data: URI or in a .glb");
    } else {
        const fs::path file = fenced_file(root, *image.uri, field);
        const std::uint64_t size = file_size(file, *image.uri, field);
        if (size > max_scene_buffer_bytes) {
            scene_fail(field, "names '" + *image.uri + "', which has " + std::to_string(size) +
                                  " bytes, more than the " +
                                  std::to_string(max_scene_buffer_bytes) + " a file may have");
        }
        bytes = file_bytes(file, *image.uri, size, field);
    }
    return std::make_shared<const Image>(decode_png(bytes, field, texels));
}

/// Decodes every image a material takes as its base colour texture, once each.
void load_textures(GltfDocument& doc, const fs::path& root) {
    std::uint64_t texels = 0;
    for (std::size_t m = 0; m < doc.materials.size(); ++m) {
        const std::optional<std::uint64_t> texture = doc.materials[m].base_color_texture;
        if (!texture) {
            continue;
        }
        if (*texture >= doc.textures.size()) {
            scene_fail(list_item("materials", m) + ".pbrMetallicRoughness.baseColorTexture.index",
                       "must name one of the file's " + std::to_string(doc.textures.size()) +
                           " textures (got " + std::to_string(*texture) + ")");
        }
        const std::string at = list_item("textures", *texture);
        const std::optional<std::uint64_t> source = doc.textures[*texture].source;
        if (!source || *source >= doc.images.size()) {
            scene_fail(at + ".source", "must name one of the file's " +
                                           std::to_string(doc.images.size()) + " images" +
                                           (source ? " (got " + std::to_string(*source) + ")"
                                                   : " (it has none, or only an extension's)"));
        }
        GltfImage& image = doc.images[*source];
        if (!image.pixels) {
            image.pixels = decode_image(doc, *source, root, texels);
        }
    }
}

/// A warning when an image no material draws refers to something that is not
/// there; such an image is never opened, so nothing else about it matters.
void check_image(const GltfImage& image, std::size_t i, const GltfDocument& doc,
                 const fs::path& root, std::vector<std::string>& warnings) {
    const std::string at = list_item("images", i);
    const std::string ignored = "; ignored (no material takes it as a base colour texture)";
    if (image.buffer_view && *image.buffer_view >= doc.buffer_views.size()) {
        warnings.push_back(at + ".bufferView " + std::to_string(*image.buffer_view) +
                           " does not exist" + ignored);
    }
    if (!image.uri || image.uri->starts_with("data:")) {
        return;
    }
    std::string problem;
    const std::string relative = percent_decoded(*image.uri, problem);
    if (problem.empty()) {
        problem = path_problem(relative);
    }
    if (problem.empty() && root.empty()) {
        problem = "names an external file, which a scene loaded from memory does not read";
    }
    if (problem.empty() && !file_inside(root, relative)) {
        problem = "is not a file inside the scene's folder";
    }
    if (!problem.empty()) {
        warnings.push_back(at + ".uri '" + *image.uri + "' " + problem + ignored);
    }
}

} // namespace

void load_buffers(GltfDocument& doc, const BufferSources& sources,
                  std::vector<std::string>& warnings) {
    fs::path root;
    if (!sources.folder.empty()) {
        std::error_code ec;
        root = fs::weakly_canonical(sources.folder, ec);
        if (ec) {
            throw SceneError("cannot resolve the scene's folder '" + sources.folder + "'");
        }
    }
    // Every size is checked before any byte is allocated.
    std::uint64_t total = 0;
    for (std::size_t i = 0; i < doc.buffers.size(); ++i) {
        const std::uint64_t length = doc.buffers[i].byte_length;
        if (length > max_scene_buffer_bytes - total) { // total <= the cap: no wrap-around
            scene_fail(list_item("buffers", i) + ".byteLength",
                       "is " + std::to_string(length) + ", more than the " +
                           std::to_string(max_scene_buffer_bytes) +
                           " bytes all buffers of a scene may have together");
        }
        total += length;
    }
    for (std::size_t i = 0; i < doc.buffers.size(); ++i) {
        load_buffer(doc.buffers[i], i, sources, root);
    }
    load_textures(doc, root);
    for (std::size_t i = 0; i < doc.images.size(); ++i) {
        if (!doc.images[i].pixels) {
            check_image(doc.images[i], i, doc, root, warnings);
        }
    }
}

std::vector<unsigned char> read_scene_file(const std::string& folder, const std::string& uri,
                                           const std::string& field) {
    if (folder.empty()) {
        scene_fail(field,
                   "names a file ('" + uri + "'), which a scene loaded from memory may not read");
    }
    std::error_code ec;
    const fs::path root = fs::weakly_canonical(folder, ec);
    if (ec) {
        throw SceneError("cannot resolve the scene's folder '" + folder + "'");
    }
    const fs::path file = fenced_file(root, uri, field);
    const std::uint64_t size = file_size(file, uri, field);
    if (size > max_scene_buffer_bytes) {
        scene_fail(field, "names '" + uri + "', which has " + std::to_string(size) +
                              " bytes, more than the " + std::to_string(max_scene_buffer_bytes) +
                              " a file may have");
    }
    return file_bytes(file, uri, size, field);
}

} // namespace snow
