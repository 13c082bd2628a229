// The `extras.snow` schema, one table per struct: JSON → SurfaceDef,
// SimConfig, Emitter, Wind, WindFieldDef, Fog, OcclusionCamera, SpectralSnow, camera,
// environment and lights. The tables check types and the ranges that only the
// scene knows (camera, colours); the simulation's validate() functions check
// the rest, and their messages are prefixed with the JSON path.
#include "game/scene/scene_schema.hpp"

#include "systems/validation.hpp"

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

constexpr Field<SurfaceDef> surface_fields[] = {
    {"cell", &SurfaceDef::cell},
    {"edge_limit", &SurfaceDef::edge_limit},
    {"laplacian_limit", &SurfaceDef::laplacian_limit},
    {"slope_x", &SurfaceDef::slope_x},
    {"slope_z", &SurfaceDef::slope_z},
    {"spills", &SurfaceDef::spills},
};

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

constexpr Field<BodyMotion> motion_fields[] = {
    {"waypoints", &read_waypoints, {}, true},
    {"speed", &BodyMotion::speed, at_least_zero},
    {"loop", &BodyMotion::loop},
};

constexpr Field<NodeSnow> node_snow_fields[] = {
    {"surface", &read_nested<&NodeSnow::surface, surface_fields, reject>},
    {"collider", +[](const Json& j, const std::string& field,
                     NodeSnow& n) { n.collider = read_choice(j, field, collider_kinds); }},
    {"motion", &read_nested<&NodeSnow::motion, motion_fields, reject>},
    {"snowball", &NodeSnow::snowball},
    {"on_ground", &NodeSnow::on_ground},
};

// --- scenes[s].extras.snow ---------------------------------------------------

constexpr Field<Aabb> bounds_fields[] = {
    {"min", &Aabb::min, {}, true},
    {"max", &Aabb::max, {}, true},
};

constexpr Field<SimConfig> simulation_fields[] = {
    {"dt", &SimConfig::dt},
    {"seed", &SimConfig::seed},
    {"max_flakes", &SimConfig::max_flakes, {1.0, 16u << 20}},
    {"threads", &SimConfig::threads, {1.0, 256.0}},
    {"gravity", &SimConfig::gravity},
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

constexpr Field<Emitter> emitter_fields[] = {
    {"rate", &Emitter::rate},
    {"mass_min_g", &Emitter::mass_min_g},
    {"mass_max_g", &Emitter::mass_max_g},
    {"size_min", &Emitter::size_min},
    {"size_max", &Emitter::size_max},
    {"fall_speed_min", &Emitter::fall_speed_min},
    {"fall_speed_max", &Emitter::fall_speed_max},
};

constexpr Field<Wind> wind_fields[] = {
    {"base",
     +[](const Json& j, const std::string& field, Wind& w) {
         read_value(j, field, {}, w.base);
         w.current = w.base; // the wind starts at its mean
     }},
    {"walk", &Wind::walk},
    {"max_deviation", &Wind::max_deviation},
    {"gust_strength", &Wind::gust_strength},
    {"gust_rate", &Wind::gust_rate},
    {"gust_duration", &Wind::gust_duration},
};

/// `wind.field.cells`: [x, y, z], each at least 1.
void read_field_cells(const Json& j, const std::string& field, WindFieldDef& d) {
    std::vector<std::uint64_t> n;
    read_value(j, field, {1.0, static_cast<double>(max_wind_field_cells)}, n);
    if (n.size() != 3) {
        scene_fail(field, "must be an array of 3 cell counts [x, y, z] (got " +
                              std::to_string(n.size()) + " values)");
    }
    d.cells_x = static_cast<std::uint32_t>(n[0]);
    d.cells_y = static_cast<std::uint32_t>(n[1]);
    d.cells_z = static_cast<std::uint32_t>(n[2]);
}

constexpr Field<WindFieldDef> wind_field_fields[] = {
    {"cells", &read_field_cells},
    {"update_every", &WindFieldDef::update_every},
    {"pressure_iterations", &WindFieldDef::pressure_iterations},
    {"eddy_viscosity", &WindFieldDef::eddy_viscosity},
};

constexpr Field<WindTransportDef> wind_transport_fields[] = {
    {"threshold", &WindTransportDef::threshold},
    {"rate", &WindTransportDef::rate},
    {"max_fraction", &WindTransportDef::max_fraction},
    {"height", &WindTransportDef::height},
};

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
                s.wind_transport = read_struct(t, tp, wind_transport_fields, reject);
            });
        s.wind_field = read_struct(grid, fp, wind_field_fields, reject);
    });
    s.wind = read_struct(global, field, wind_fields, reject);
}

constexpr std::pair<std::string_view, FogMode> fog_modes[] = {{"exponential", FogMode::exponential},
                                                              {"half_life", FogMode::half_life},
                                                              {"layered", FogMode::layered}};

constexpr Field<FogPuff> puff_fields[] = {
    {"center", &FogPuff::center},       {"sigma", &FogPuff::sigma}, {"density", &FogPuff::density},
    {"frequency", &FogPuff::frequency}, {"phase", &FogPuff::phase},
};

constexpr Field<Fog> fog_fields[] = {
    {"mode", +[](const Json& j, const std::string& field,
                 Fog& f) { f.mode = read_choice(j, field, fog_modes); }},
    {"color", &Fog::color},
    {"density", &Fog::density},
    {"half_distance", &Fog::half_distance},
    {"layer_bottom", &Fog::layer_bottom},
    {"layer_top", &Fog::layer_top},
    {"layer_density", &Fog::layer_density},
    {"puffs", &read_nested<&Fog::puffs, puff_fields, reject>},
};

constexpr Field<OcclusionCamera> occlusion_fields[] = {
    {"resolution", &OcclusionCamera::resolution, {1.0, 4096.0}},
    {"tilt", &OcclusionCamera::tilt},
};

constexpr Field<SpectralSnow> spectral_fields[] = {
    {"size_xy", &SpectralSnow::size_xy, {1.0, 1u << 16}},
    {"size_t", &SpectralSnow::size_t, {1.0, 1u << 16}},
    {"speed", &SpectralSnow::speed},
    {"band_low", &SpectralSnow::band_low},
    {"band_high", &SpectralSnow::band_high},
    {"opacity", &SpectralSnow::opacity},
    {"start_distance", &SpectralSnow::start_distance},
};

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

constexpr Field<CoverDef> cover_fields[] = {
    {"min", &read_corner<&CoverDef::min_x, &CoverDef::min_z>, {}, true},
    {"max", &read_corner<&CoverDef::max_x, &CoverDef::max_z>, {}, true},
    {"cell", &CoverDef::cell},
    {"edge_limit", &CoverDef::edge_limit},
    {"drop_limit", &CoverDef::drop_limit},
    {"laplacian_limit", &CoverDef::laplacian_limit},
    {"repose_deg", &CoverDef::repose_deg},
};

constexpr Field<CameraDef> camera_fields[] = {
    {"position", &CameraDef::position},
    {"target", &CameraDef::target},
    {"fov_y_deg", &CameraDef::fov_y_deg, {0.0, 170.0, true}},
    {"near_plane", &CameraDef::near_plane, above_zero},
    {"far_plane", &CameraDef::far_plane, above_zero},
};

constexpr Field<Environment> environment_fields[] = {
    {"ambient", &Environment::ambient, at_least_zero},
    {"sky", &Environment::sky, at_least_zero},
};

constexpr Field<SceneSnow> scene_snow_fields[] = {
    {"simulation",
     +[](const Json& j, const std::string& field, SceneSnow& s) {
         read_fields(j, field, simulation_fields, reject, s.config);
         s.has_bounds = j.contains("bounds");
     }},
    {"emitter", &read_nested<&SceneSnow::emitter, emitter_fields, reject>},
    {"wind", &read_wind},
    {"fog", &read_nested<&SceneSnow::fog, fog_fields, reject>},
    {"occlusion", &read_nested<&SceneSnow::occlusion, occlusion_fields, reject>},
    {"spectral", &read_nested<&SceneSnow::spectral, spectral_fields, reject>},
    {"cover", &read_nested<&SceneSnow::cover, cover_fields, reject>},
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
};

/// `asset.extras.snow`: the file asks for auto snow whichever scene is used.
struct AssetSnow {
    bool auto_snow = false;
};

constexpr Field<AssetSnow> asset_snow_fields[] = {
    {"auto", &AssetSnow::auto_snow},
};

/// Reads one scene's `extras.snow` and checks its effects with the
/// simulation's validate() functions.
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
    if (s.spectral) {
        check_valid(validate(*s.spectral), path);
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
    {"color", &LightSpec::color, at_least_zero},
    {"intensity", &LightSpec::intensity, at_least_zero},
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
