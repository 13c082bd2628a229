// The loader's pipeline up to the geometry, OSS-Fuzz cgltf style: every size
// is checked before the bytes it covers are used, and the JSON is parsed once.
#include "game/scene/scene_parse.hpp"

#include "game/scene/scene_buffers.hpp"
#include "game/scene/scene_container.hpp"
#include <snow/scene.hpp>

#include <algorithm>

namespace snow {

namespace {

/// Deepest array/object nesting accepted, checked before parsing. Scenes need
/// under 10; the cap keeps hostile nesting from costing memory and time.
constexpr int max_json_depth = 64;

/// Deepest nesting of [ and { outside strings (a scan, no recursion).
int json_depth(std::string_view text) {
    int depth = 0, deepest = 0;
    bool in_string = false, escaped = false;
    for (const char c : text) {
        if (in_string) {
            if (escaped) {
                escaped = false;
            } else if (c == '\\') {
                escaped = true;
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            deepest = std::max(deepest, ++depth);
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return deepest;
}

Json parse_json(std::string_view text) {
    try {
        return Json::parse(text.begin(), text.end());
    } catch (const Json::exception& e) {
        // Drop nlohmann's "[json.exception.parse_error.101] " tag.
        std::string what = e.what();
        const std::size_t tag = what.find("] ");
        throw SceneError("not valid JSON: " +
                         (tag == std::string::npos ? what : what.substr(tag + 2)));
    }
}

} // namespace

ParsedScene parse_scene(std::string_view bytes, const std::string& folder, bool must_be_glb,
                        std::vector<std::string>& warnings) {
    if (bytes.size() > max_scene_file_bytes) {
        throw SceneError("is " + std::to_string(bytes.size()) +
                         " bytes; scene files may have at most " +
                         std::to_string(max_scene_file_bytes));
    }
    const SceneSource source =
        must_be_glb || is_glb(bytes) ? split_glb(bytes) : SceneSource{bytes, std::nullopt};
    if (source.json.size() > max_scene_bytes) {
        throw SceneError("has " + std::to_string(source.json.size()) +
                         " bytes of JSON; scenes may have at most " +
                         std::to_string(max_scene_bytes));
    }
    if (json_depth(source.json) > max_json_depth) {
        throw SceneError("JSON nests deeper than " + std::to_string(max_json_depth) + " levels");
    }
    const Json doc = parse_json(source.json);
    ParsedScene parsed;
    parsed.gltf = read_document(doc, warnings);
    parsed.schema = read_schema(doc);
    load_buffers(parsed.gltf, {source.bin, folder}, warnings);
    parsed.geometry = instance_scene(parsed.gltf, warnings);
    return parsed;
}

} // namespace snow
