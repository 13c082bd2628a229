// Scene loading as one straight pipeline, OSS-Fuzz cgltf style:
//   read bytes → parse_scene (split the container, parse the JSON once, read
//   glTF's objects and the snow schema, load buffer bytes, instance the
//   geometry with every accessor range checked) → create the simulation.
// Any failure is one message "<file>: <field> <problem>" and no Simulation
// (never a partly built one).
#include <snow/scene.hpp>

#include "game/scene/scene_buffers.hpp"
#include "game/scene/scene_build.hpp"
#include "game/scene/scene_image.hpp"
#include "game/scene/scene_parse.hpp"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>

namespace snow {

namespace fs = std::filesystem;

namespace {

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
    ParsedScene parsed = parse_scene(bytes, folder, must_be_glb, result.warnings);
    SceneDescription d = describe(std::move(parsed.geometry), parsed.schema);
    if (d.settings.world) { // only the scene used reads its height map
        const std::string field = d.settings_path + ".world.heightmap";
        d.heights =
            decode_height_png(read_scene_file(folder, d.settings.world->heightmap, field), field);
    }
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
