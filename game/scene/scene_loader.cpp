// Scene loading as one straight pipeline, OSS-Fuzz cgltf style:
//   read bytes → split the container (.gltf text or .glb chunks) → parse the
//   JSON once → read glTF's objects and the snow schema from that one parse →
//   load buffer bytes → instance the geometry (every accessor range checked)
//   → create the simulation.
// Any failure is one message "<file>: <field> <problem>" and no Simulation
// (never a partly built one).
#include <snow/scene.hpp>

#include "game/scene/scene_buffers.hpp"
#include "game/scene/scene_build.hpp"
#include "game/scene/scene_container.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>

namespace snow {

namespace fs = std::filesystem;

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

/// The geometry with each instanced node's role and light, and the chosen
/// scene's settings.
SceneDescription describe(SceneGeometry geometry, const SceneSchema& schema) {
    SceneDescription d;
    for (const WorldNode& node : geometry.nodes) {
        d.roles.push_back(schema.nodes[node.index]);
        d.lights.push_back(schema.node_lights[node.index]);
    }
    if (geometry.scene_index) {
        d.settings = schema.scenes[*geometry.scene_index];
        d.settings_path = scene_snow_path(*geometry.scene_index);
    } else {
        d.settings_path = "default scene settings (the file has no scenes)";
    }
    if (schema.asset_auto_snow) {
        d.auto_snow_path = std::string(asset_snow_path) + ".auto";
    } else if (d.settings.auto_snow) {
        d.auto_snow_path = d.settings_path + ".auto";
    }
    d.geometry = std::move(geometry);
    return d;
}

/// The pipeline on bytes already in memory; `folder` empty forbids files.
void load_bytes(std::string_view bytes, const std::string& folder, bool must_be_glb,
                const SceneOverrides& overrides, SceneLoadResult& result) {
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
    GltfDocument gltf = read_document(doc, result.warnings);
    const SceneSchema schema = read_schema(doc);
    load_buffers(gltf, {source.bin, folder}, result.warnings);
    const SceneDescription d = describe(instance_scene(gltf, result.warnings), schema);
    if (!d.geometry.scene_name.empty()) {
        result.name = d.geometry.scene_name;
    }
    result.sim = build_scene(d, overrides, result.visuals);
}

/// Runs load_bytes() and turns any failure into the one error message.
SceneLoadResult load(std::string_view bytes, const std::string& name, const std::string& folder,
                     bool must_be_glb, const std::string& fallback_name,
                     const SceneOverrides& overrides) {
    SceneLoadResult result;
    result.name = fallback_name;
    try {
        load_bytes(bytes, folder, must_be_glb, overrides, result);
    } catch (const SceneError& e) {
        result.error = name + ": " + e.what();
    } catch (const std::bad_alloc&) {
        result.error = name + ": out of memory while loading the scene";
    } catch (const std::exception& e) { // EcsError, nlohmann errors: still one clean message
        result.error = name + ": " + e.what();
    }
    if (!result.error.empty()) {
        result.sim.reset();
        result.visuals = {};
    }
    for (std::string& w : result.warnings) {
        w = name + ": " + w;
        std::fprintf(stderr, "warning: %s\n", w.c_str());
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
    if (ec || size > max_scene_file_bytes) {
        result.error = path + ": is " + std::to_string(size) +
                       " bytes; scene files may have at most " +
                       std::to_string(max_scene_file_bytes);
        return result;
    }
    std::string bytes(static_cast<std::size_t>(size), '\0');
    std::ifstream in(file, std::ios::binary);
    if (!in.read(bytes.data(), static_cast<std::streamsize>(size))) {
        result.error = path + ": cannot read the scene";
        return result;
    }
    const fs::path folder = fs::absolute(file, ec).parent_path();
    return load(bytes, path, folder.string(), file.extension() == ".glb", file.stem().string(),
                overrides);
}

SceneLoadResult load_scene_memory(std::string_view bytes, std::string_view name_for_errors,
                                  const SceneOverrides& overrides) {
    const std::string name(name_for_errors);
    return load(bytes, name, "", false, name, overrides);
}

} // namespace snow
