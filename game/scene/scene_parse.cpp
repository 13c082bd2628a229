// The loader's pipeline up to the geometry, OSS-Fuzz cgltf style: every size
// is checked before the bytes it covers are used, and the JSON is parsed once.
#include "game/scene/scene_parse.hpp"

#include "game/scene/scene_buffers.hpp"
#include "game/scene/scene_container.hpp"
#include <snow/scene.hpp>

#include <algorithm>
#include <cstdint>

namespace snow {

namespace {

/// Deepest array/object nesting accepted, checked before parsing. Scenes need
/// under 10; the cap keeps hostile nesting from costing memory and time.
constexpr int max_json_depth = 64;
/// Most JSON values accepted, checked before parsing: the parsed document
/// costs time and memory per value (docs/reliability.md "Bounded work").
/// The shipped scenes have a few thousand; a buffer in a data URI is one.
constexpr std::uint64_t max_json_values = 1u << 20;

/// How deep a JSON text nests and about how many values it holds (an upper
/// bound: each value but the first follows a ',' or opens an array or object).
struct JsonShape {
    int depth = 0;
    std::uint64_t values = 1;
};

/// The shape of the JSON outside its strings (a scan, no recursion).
JsonShape json_shape(std::string_view text) {
    JsonShape shape;
    int depth = 0;
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
            shape.depth = std::max(shape.depth, ++depth);
            ++shape.values;
        } else if (c == ']' || c == '}') {
            --depth;
        } else if (c == ',') {
            ++shape.values;
        }
    }
    return shape;
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
    const JsonShape shape = json_shape(source.json);
    if (shape.depth > max_json_depth) {
        throw SceneError("JSON nests deeper than " + std::to_string(max_json_depth) + " levels");
    }
    if (shape.values > max_json_values) {
        throw SceneError("JSON holds about " + std::to_string(shape.values) +
                         " values; scenes may have at most " + std::to_string(max_json_values));
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
