// The `extras.snow` schema: JSON → SurfaceDef, SimConfig, Emitter, Wind,
// WindFieldDef, Fog, OcclusionCamera, SpectralSnow, CoverDef and BodyMotion,
// each read by its systems table (settings_fields.hpp) plus rows for choices,
// nested objects, corners, cells and waypoints; camera, environment and
// lights by tables of their own. The reader checks types and the ranges that
// only the scene knows (camera, colours); the simulation's validate()
// functions check the rest, and their messages are prefixed with the JSON path.
#include "game/scene/scene_schema.hpp"

#include "render/visual_rules.hpp"
#include "systems/api/validation.hpp"

#include <cmath>

namespace snow {

namespace {

constexpr auto reject = UnknownKeys::reject;
constexpr auto ignore = UnknownKeys::ignore;

/// Throws SceneError("prefix.field", problem) when `v` (from validate()) holds a problem.
void check_valid(const Invalid& v, const std::string& prefix) {
    if (!v.empty()) {
        throw SceneError(prefix + "." + v.field, v.problem);
    }
}

// --- nodes[i].extras.snow ----------------------------------------------------

/// A surface's rectangle and height come from its node's mesh.
constexpr std::string_view surface_from_mesh[] = {"x0", "z0", "size_x", "size_z", "base_y"};
constexpr Schema<SurfaceDef> surface_schema{surface_fields, {}, surface_from_mesh};

constexpr std::pair<std::string_view, ColliderKind> collider_kinds[] = {
    {"box", ColliderKind::box},
    {"sphere", ColliderKind::sphere},
    {"mesh", ColliderKind::mesh},
    {"capsule", ColliderKind::capsule}};

/// `[x, y, z]` points, at least one.
void read_waypoints(const Json& j, const std::string& field, BodyMotion& m) {
    if (!j.is_array() || j.empty()) {
        scene_fail(field, "must be an array of at least one [x, y, z] point (got " +
                              (j.is_array() ? std::string("an empty array") : json_type_name(j)) +
                              ")");
    }
    m.waypoints.resize(j.size());
    for (std::size_t i = 0; i < j.size(); ++i) {
        read_value(j[i], field + "[" + std::to_string(i) + "]", {}, m.waypoints[i]);
    }
}

constexpr Field<BodyMotion> motion_rows[] = {{"waypoints", &read_waypoints, {}, true}};
constexpr Schema<BodyMotion> motion_schema{motion_fields, motion_rows};

constexpr Field<NodeSnow> node_snow_fields[] = {
    {"surface", &read_nested<&NodeSnow::surface, surface_schema, reject>},
    {"collider", +[](const Json& j, const std::string& field,
                     NodeSnow& n) { n.collider = read_choice(j, field, collider_kinds); }},
    {"motion", &read_nested<&NodeSnow::motion, motion_schema, reject>},
    {"snowball", &NodeSnow::snowball},
    {"on_ground", &NodeSnow::on_ground},
    {"compaction", &NodeSnow::compaction, between(0, 1)},
    {"porosity", &NodeSnow::porosity, from_below(0, 1)},
};

// --- scenes[s].extras.snow ---------------------------------------------------

constexpr Field<Aabb> bounds_fields[] = {
    {"min", &Aabb::min, {}, true},
    {"max", &Aabb::max, {}, true},
};

constexpr Field<SimConfig> simulation_rows[] = {
    {"integrator",
     +[](const Json& j, const std::string& field, SimConfig& c) {
         const auto i = j.is_string() ? parse_integrator(j.get<std::string>()) : std::nullopt;
         if (!i) {
             scene_fail(field,
                        "must be one of " + integrator_choices() + " (got " +
                            (j.is_string() ? in_quotes(j.get<std::string>()) : json_type_name(j)) +
                            ")");
         }
         c.integrator = *i;
     }},
    {"bounds", &read_nested<&SimConfig::bounds, bounds_fields, reject>},
};
/// Smoothing sub-iterations and the settling step are quality knobs of the
/// host, not part of the scene schema (docs/scenes.md).
constexpr std::string_view simulation_unread[] = {"smoothing_iterations", "settle_interval"};
constexpr Schema<SimConfig> simulation_schema{sim_config_fields, simulation_rows,
                                              simulation_unread};

constexpr std::pair<std::string_view, CrystalType> crystal_types[] = {
    {"dendrite_aggregate", CrystalType::dendrite_aggregate},
    {"rimed_aggregate", CrystalType::rimed_aggregate}};

constexpr Field<Emitter> emitter_rows[] = {
    {"crystal", +[](const Json& j, const std::string& field, Emitter& e) {
         e.crystal = read_choice(j, field, crystal_types);
     }}};
constexpr Schema<Emitter> emitter_schema{emitter_fields, emitter_rows};

constexpr Field<Wind> wind_rows[] = {
    {"base",
     +[](const Json& j, const std::string& field, Wind& w) {
         read_value(j, field, {}, w.base);
         w.current = w.base; // the wind starts at its mean
     }},
};
/// The wind's running state starts from its mean.
constexpr std::string_view wind_state[] = {"current", "deviation", "gust_left"};
constexpr Schema<Wind> wind_schema{wind_fields, wind_rows, wind_state};

/// `wind.field.cells`: [x, y, z] cell counts.
void read_field_cells(const Json& j, const std::string& field, WindFieldDef& d) {
    if (!j.is_array() || j.size() != 3) {
        scene_fail(field,
                   "must be an array of 3 cell counts [x, y, z] (got " +
                       (j.is_array() ? std::to_string(j.size()) + " values" : json_type_name(j)) +
                       ")");
    }
    std::uint32_t* const cells[] = {&d.cells_x, &d.cells_y, &d.cells_z};
    for (std::size_t i = 0; i < 3; ++i) {
        read_value(j[i], field + "[" + std::to_string(i) + "]", {}, *cells[i]);
    }
}

constexpr Field<WindFieldDef> wind_field_rows[] = {{"cells", &read_field_cells}};
constexpr Schema<WindFieldDef> wind_field_schema{wind_field_fields, wind_field_rows};

constexpr Schema<WindTransportDef> wind_transport_schema{wind_transport_fields};

/// `j` without its member `key`, which `read` takes first when present.
template <typename Read>
Json split_member(const Json& j, const std::string& path, const char* key, Read read) {
    require_object(j, path);
    Json rest = j;
    if (const auto it = j.find(key); it != j.end()) {
        read(*it, path + "." + key);
        rest.erase(key);
    }
    return rest;
}

/// `wind`: the global wind; in `wind.field` the field obstacles shape, and in
/// `wind.field.transport` the snow its wind moves.
void read_wind(const Json& j, const std::string& field, SceneSnow& s) {
    const Json global = split_member(j, field, "field", [&](const Json& f, const std::string& fp) {
        const Json grid =
            split_member(f, fp, "transport", [&](const Json& t, const std::string& tp) {
                s.wind_transport = read_struct(t, tp, wind_transport_schema, reject);
            });
        s.wind_field = read_struct(grid, fp, wind_field_schema, reject);
    });
    s.wind = read_struct(global, field, wind_schema, reject);
}

constexpr std::pair<std::string_view, FogMode> fog_modes[] = {{"exponential", FogMode::exponential},
                                                              {"half_life", FogMode::half_life},
                                                              {"layered", FogMode::layered}};

constexpr Schema<FogPuff> puff_schema{fog_puff_fields};

constexpr Field<Fog> fog_rows[] = {
    {"mode", +[](const Json& j, const std::string& field,
                 Fog& f) { f.mode = read_choice(j, field, fog_modes); }},
    {"puffs", &read_nested<&Fog::puffs, puff_schema, reject>},
};
constexpr Schema<Fog> fog_schema{fog_fields, fog_rows};

constexpr Schema<OcclusionCamera> occlusion_schema{occlusion_fields};

constexpr Schema<SpectralSnow> spectral_schema{spectral_fields};

constexpr Schema<Sun> sun_schema{sun_fields};

/// `[x, z]` of a cover corner.
template <float CoverDef::*X, float CoverDef::*Z>
void read_corner(const Json& j, const std::string& field, CoverDef& c) {
    std::vector<double> xz;
    read_value(j, field, {}, xz);
    if (xz.size() != 2) {
        scene_fail(field, "must be [x, z] (got " + std::to_string(xz.size()) + " numbers)");
    }
    c.*X = static_cast<float>(xz[0]);
    c.*Z = static_cast<float>(xz[1]);
}

constexpr Field<CoverDef> cover_rows[] = {
    {"min", &read_corner<&CoverDef::min_x, &CoverDef::min_z>, {}, true},
    {"max", &read_corner<&CoverDef::max_x, &CoverDef::max_z>, {}, true},
};
constexpr Schema<CoverDef> cover_schema{cover_fields, cover_rows};

constexpr Field<CameraDef> camera_fields[] = {
    {"position", &CameraDef::position},
    {"target", &CameraDef::target},
    {"fov_y_deg", &CameraDef::fov_y_deg, {0.0, 170.0, true}},
    {"near_plane", &CameraDef::near_plane, positive},
    {"far_plane", &CameraDef::far_plane, positive},
};

constexpr Field<Environment> environment_fields[] = {
    {"ambient", &Environment::ambient, non_negative},
    {"sky", &Environment::sky, non_negative},
};

constexpr Field<SceneSnow> scene_snow_fields[] = {
    {"simulation",
     +[](const Json& j, const std::string& field, SceneSnow& s) {
         read_fields(j, field, simulation_schema, reject, s.config);
         s.has_bounds = j.contains("bounds");
     }},
    {"emitter", &read_nested<&SceneSnow::emitter, emitter_schema, reject>},
    {"wind", &read_wind},
    {"fog", &read_nested<&SceneSnow::fog, fog_schema, reject>},
    {"occlusion", &read_nested<&SceneSnow::occlusion, occlusion_schema, reject>},
    {"spectral", &read_nested<&SceneSnow::spectral, spectral_schema, reject>},
    {"sun", &read_nested<&SceneSnow::sun, sun_schema, reject>},
    {"cover", &read_nested<&SceneSnow::cover, cover_schema, reject>},
    {"camera",
     +[](const Json& j, const std::string& field, SceneSnow& s) {
         const CameraDef& c = s.camera.emplace(read_struct(j, field, camera_fields, reject));
         if (!(c.far_plane > c.near_plane)) {
             scene_fail(field + ".far_plane",
                        "must be > near_plane (got " + number_text(c.far_plane) + ")");
         }
         if (c.position == c.target) {
             scene_fail(field + ".target", "must differ from position");
         }
     }},
    {"environment", &read_nested<&SceneSnow::environment, environment_fields, reject>},
    {"auto", &SceneSnow::auto_snow},
    {"world", +[](const Json& j, const std::string& field,
                  SceneSnow& s) { s.world = read_world(j, field); }},
};

/// `asset.extras.snow`: the file asks for auto snow whichever scene is used.
struct AssetSnow {
    bool auto_snow = false;
};

constexpr Field<AssetSnow> asset_snow_fields[] = {
    {"auto", &AssetSnow::auto_snow},
};

/// Reads one scene's `extras.snow` and checks its effects with the
/// simulation's (and, for fog, spectral snow and the sun, the renderer's) validate()
/// functions.
SceneSnow read_scene_snow(const Json& j, const std::string& path) {
    const SceneSnow s = read_struct(j, path, scene_snow_fields, reject);
    check_valid(validate(s.config), path);
    if (s.emitter) {
        check_valid(validate(*s.emitter), path);
    }
    if (s.wind) {
        check_valid(validate(*s.wind), path);
    }
    if (s.wind_field) {
        check_valid(validate(*s.wind_field), path);
    }
    if (s.wind_transport) {
        check_valid(validate(*s.wind_transport), path);
    }
    if (s.fog) {
        check_valid(validate(*s.fog), path);
    }
    if (s.occlusion) {
        check_valid(validate(*s.occlusion), path);
    }
    if (s.spectral) {
        check_valid(validate(*s.spectral), path);
    }
    if (s.sun) {
        check_valid(validate(*s.sun), path);
    }
    return s;
}

// --- KHR_lights_punctual -----------------------------------------------------

constexpr Field<LightSpec> light_fields[] = {
    {"type",
     +[](const Json& j, const std::string& field, LightSpec&) {
         if (j != "point") {
             scene_fail(field,
                        "must be \"point\" (only point lights are supported; got " +
                            (j.is_string() ? in_quotes(j.get<std::string>()) : json_type_name(j)) +
                            ")");
         }
     },
     {},
     true},
    {"color", &LightSpec::color, non_negative},
    {"intensity", &LightSpec::intensity, non_negative},
};

/// A node's or the file's `extensions.KHR_lights_punctual`, or null.
const Json* khr_lights(const Json& owner) {
    const auto ext = owner.find("extensions");
    if (ext == owner.end() || !ext->is_object()) {
        return nullptr;
    }
    const auto khr = ext->find("KHR_lights_punctual");
    return khr == ext->end() ? nullptr : &*khr;
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

/// The file's lights: `extensions.KHR_lights_punctual.lights`.
std::vector<LightSpec> read_lights(const Json& doc) {
    const Json* khr = khr_lights(doc);
    if (khr == nullptr) {
        return {};
    }
    const std::string path = "extensions.KHR_lights_punctual";
    require_object(*khr, path);
    const auto list = khr->find("lights");
    return list == khr->end() ? std::vector<LightSpec>{}
                              : read_list(*list, path + ".lights", light_fields, ignore);
}

/// The light a node carries (`extensions.KHR_lights_punctual.light`), if any.
std::optional<LightSpec> node_light(const Json& node, const std::string& path,
                                    const std::vector<LightSpec>& lights) {
    const Json* khr = khr_lights(node);
    if (khr == nullptr) {
        return std::nullopt;
    }
    struct Ref {
        std::optional<std::uint64_t> light;
    };
    static constexpr Field<Ref> ref_fields[] = {{"light", &Ref::light, {}, true}};
    const std::string at = path + ".extensions.KHR_lights_punctual";
    const Ref ref = read_struct(*khr, at, ref_fields, ignore);
    if (*ref.light >= lights.size()) {
        scene_fail(at + ".light", lights.empty()
                                      ? "refers to a light but the file declares none"
                                      : "must be in [0, " + std::to_string(lights.size() - 1) +
                                            "] (got " + std::to_string(*ref.light) + ")");
    }
    return lights[*ref.light];
}

/// The array `key` of the document (checked by read_document), or an empty one.
const Json& top_list(const Json& doc, const char* key) {
    static const Json empty = Json::array();
    const auto it = doc.find(key);
    return it == doc.end() ? empty : *it;
}

} // namespace

std::string scene_snow_path(std::size_t scene) {
    return "scenes[" + std::to_string(scene) + "].extras.snow";
}

SceneSchema read_schema(const Json& doc) {
    SceneSchema schema;
    const std::vector<LightSpec> lights = read_lights(doc);
    const Json& nodes = top_list(doc, "nodes");
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        const std::string path = "nodes[" + std::to_string(i) + "]";
        const Json* snow = snow_extras(nodes[i]);
        schema.nodes.push_back(
            snow ? read_struct(*snow, path + ".extras.snow", node_snow_fields, reject)
                 : NodeSnow{});
        schema.node_lights.push_back(node_light(nodes[i], path, lights));
    }
    if (const Json* snow = snow_extras(doc.at("asset"))) {
        schema.asset_auto_snow =
            read_struct(*snow, asset_snow_path, asset_snow_fields, reject).auto_snow;
    }
    const Json& scenes = top_list(doc, "scenes");
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const Json* snow = snow_extras(scenes[s]);
        schema.scenes.push_back(snow ? read_scene_snow(*snow, scene_snow_path(s)) : SceneSnow{});
    }
    return schema;
}

} // namespace snow
