// Scene loading, OSS-Fuzz cgltf style: cap the input, parse, validate, load
// buffers, unpack every accessor with checked ranges, and only then create
// the simulation. Any failure is one message "<file>: <field> <problem>" and
// no Simulation (never a partly built one).
#include "game/scene_loader.hpp"

#include "game/scene_build.hpp"
#include "game/scene_gltf.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <new>

namespace snow {

namespace fs = std::filesystem;

namespace {

/// Deepest array/object nesting accepted. Scenes need under 10; tinygltf
/// converts extras recursively, so hostile depth could exhaust the stack.
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

void check_is_gltf(const Json& doc) {
    if (!doc.is_object()) {
        throw SceneError("not a glTF file: the top level must be an object (got " +
                         json_type_name(doc) + ")");
    }
    const auto asset = doc.find("asset");
    if (asset == doc.end() || !asset->is_object()) {
        throw SceneError("not a glTF file: it has no asset object");
    }
    const auto version = asset->find("version");
    if (version == asset->end() || !version->is_string() ||
        version->get<std::string>().rfind("2.", 0) != 0) {
        scene_fail("asset.version", "must be \"2.0\" (only glTF 2 is supported)");
    }
}

/// `extras.snow` of a glTF object, or null.
const Json* snow_extras(const Json& owner) {
    const auto extras = owner.find("extras");
    if (extras == owner.end() || !extras->is_object()) {
        return nullptr;
    }
    const auto snow = extras->find("snow");
    return snow == extras->end() ? nullptr : &*snow;
}

SceneDescription describe(const Json& doc, const tinygltf::Model& model) {
    SceneDescription d;
    d.geometry = instance_scene(model);
    const std::vector<LightSpec> lights = parse_lights(doc);
    const Json no_nodes = Json::array();
    const Json& nodes = doc.contains("nodes") ? doc.at("nodes") : no_nodes;
    if (!nodes.is_array() || nodes.size() != model.nodes.size()) {
        scene_fail("nodes", "must be an array of node objects");
    }
    for (const WorldNode& node : d.geometry.nodes) {
        const std::string path = "nodes[" + std::to_string(node.index) + "]";
        const Json& json_node = nodes.at(node.index);
        const Json* snow = snow_extras(json_node);
        d.roles.push_back(snow ? parse_node_snow(*snow, path + ".extras.snow") : NodeSnow{});
        const auto light = node_light(json_node, path, lights.size());
        d.lights.push_back(light ? std::optional<LightSpec>(lights[*light]) : std::nullopt);
    }
    const std::string scene_path = "scenes[" + std::to_string(d.geometry.scene_index) + "]";
    d.settings_path = scene_path + ".extras.snow";
    d.settings =
        parse_scene_snow(snow_extras(doc.at("scenes").at(d.geometry.scene_index)), d.settings_path);
    return d;
}

/// The whole pipeline on text already in memory; `folder` empty forbids files.
SceneLoadResult load_text(std::string_view text, const std::string& name, const std::string& folder,
                          const std::string& fallback_name, const SceneOverrides& overrides) {
    SceneLoadResult result;
    try {
        if (text.size() > max_scene_bytes) {
            throw SceneError("is " + std::to_string(text.size()) +
                             " bytes; scenes may have at most " + std::to_string(max_scene_bytes));
        }
        if (text.substr(0, 4) == "glTF") {
            throw SceneError("binary glTF (.glb) is not supported; use .gltf");
        }
        if (json_depth(text) > max_json_depth) {
            throw SceneError("JSON nests deeper than " + std::to_string(max_json_depth) +
                             " levels");
        }
        const Json doc = parse_json(text);
        check_is_gltf(doc);
        check_uris(doc, !folder.empty());
        const tinygltf::Model model = parse_gltf(text, folder);
        const SceneDescription d = describe(doc, model);
        result.name = d.geometry.scene_name.empty() ? fallback_name : d.geometry.scene_name;
        result.sim = build_scene(d, overrides, result.visuals);
    } catch (const SceneError& e) {
        result.error = name + ": " + e.what();
    } catch (const std::bad_alloc&) {
        result.error = name + ": out of memory while loading the scene";
    } catch (const std::exception& e) { // EcsError, nlohmann type errors: still one clean message
        result.error = name + ": " + e.what();
    }
    if (!result.error.empty()) {
        result.sim.reset();
        result.visuals = {};
    }
    return result;
}

} // namespace

SceneLoadResult load_scene_file(const std::string& path, const SceneOverrides& overrides) {
    SceneLoadResult result;
    const fs::path file(path);
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
        result.error = path + ": cannot open the scene (" +
                       (fs::exists(file, ec) ? "not a regular file" : "no such file") + ")";
        return result;
    }
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec || size > max_scene_bytes) {
        result.error = path + ": is " + std::to_string(size) + " bytes; scenes may have at most " +
                       std::to_string(max_scene_bytes);
        return result;
    }
    std::string text(static_cast<std::size_t>(size), '\0');
    std::ifstream in(file, std::ios::binary);
    if (!in.read(text.data(), static_cast<std::streamsize>(size))) {
        result.error = path + ": cannot read the scene";
        return result;
    }
    const fs::path folder = fs::absolute(file, ec).parent_path();
    return load_text(text, path, folder.string(), file.stem().string(), overrides);
}

SceneLoadResult load_scene_memory(std::string_view gltf_json, std::string_view name_for_errors,
                                  const SceneOverrides& overrides) {
    const std::string name(name_for_errors);
    return load_text(gltf_json, name, "", name, overrides);
}

} // namespace snow
