// The `extras.snow` schema: JSON → SurfaceDef, SimConfig, Emitter, Wind, Fog,
// OcclusionCamera, SpectralSnow, camera and lights. Types are checked here;
// value ranges by the simulation's own validate() functions (one place, shared
// with the facade), whose messages are prefixed with the JSON path.
#include "game/scene_schema.hpp"

#include "systems/validation.hpp"

namespace snow {

namespace {

/// Throws SceneError("prefix.message") when `message` (from validate()) is set.
void check_valid(const std::string& message, const std::string& prefix) {
    if (!message.empty()) {
        throw SceneError(prefix + "." + message);
    }
}

SurfaceDef read_surface(JsonReader r) {
    SurfaceDef d;
    r.read("cell", d.cell);
    r.read("edge_limit", d.edge_limit);
    r.read("laplacian_limit", d.laplacian_limit);
    r.read("slope_x", d.slope_x);
    r.read("slope_z", d.slope_z);
    r.read("spills", d.spills);
    r.finish();
    return d;
}

ColliderKind read_collider(const Json& j, const std::string& field) {
    if (j == "box") {
        return ColliderKind::box;
    }
    if (j == "sphere") {
        return ColliderKind::sphere;
    }
    if (j == "mesh") {
        return ColliderKind::mesh;
    }
    scene_fail(field, "must be \"box\", \"sphere\" or \"mesh\" (got " +
                          (j.is_string() ? quoted(j.get<std::string>()) : json_type_name(j)) + ")");
}

void read_simulation(JsonReader r, SceneSnow& s) {
    SimConfig& c = s.config;
    r.read("dt", c.dt);
    r.read("seed", c.seed, 0, ~0ull);
    r.read("max_flakes", c.max_flakes, 1, 16u << 20);
    r.read("threads", c.threads, 1, 256);
    r.read("gravity", c.gravity);
    std::string integrator;
    r.read("integrator", integrator);
    if (r.has("integrator")) {
        const auto i = parse_integrator(integrator);
        if (!i) {
            scene_fail(r.field("integrator"),
                       "must be one of " + integrator_choices() + " (got \"" + integrator + "\")");
        }
        c.integrator = *i;
    }
    if (auto b = r.object("bounds")) {
        if (!b->has("min") || !b->has("max")) {
            scene_fail(b->path(), "needs both min and max");
        }
        b->read("min", c.bounds.min);
        b->read("max", c.bounds.max);
        b->finish();
        s.has_bounds = true;
    }
    r.finish();
}

Emitter read_emitter(JsonReader r) {
    Emitter e;
    r.read("rate", e.rate);
    r.read("mass_min_g", e.mass_min_g);
    r.read("mass_max_g", e.mass_max_g);
    r.read("size_min", e.size_min);
    r.read("size_max", e.size_max);
    r.read("fall_speed_min", e.fall_speed_min);
    r.read("fall_speed_max", e.fall_speed_max);
    r.finish();
    return e;
}

/// `wind.field`: the grid is "cells": [x, y, z], each at least 1.
WindFieldDef read_wind_field(JsonReader r) {
    WindFieldDef d;
    if (const Json* cells = r.array("cells")) {
        const std::string field = r.field("cells");
        if (cells->size() != 3) {
            scene_fail(field, "must be an array of 3 cell counts [x, y, z] (got " +
                                  std::to_string(cells->size()) + " values)");
        }
        std::uint32_t* out[3] = {&d.cells_x, &d.cells_y, &d.cells_z};
        for (std::size_t a = 0; a < 3; ++a) {
            *out[a] = static_cast<std::uint32_t>(json_to_uint(
                (*cells)[a], field + "[" + std::to_string(a) + "]", 1, max_wind_field_cells));
        }
    }
    r.read("update_every", d.update_every, 1, 1u << 16);
    r.read("pressure_iterations", d.pressure_iterations, 1, 4096);
    r.read("eddy_viscosity", d.eddy_viscosity);
    r.finish();
    return d;
}

Wind read_wind(JsonReader r, std::optional<WindFieldDef>& field) {
    Wind w;
    if (auto f = r.object("field")) {
        field = read_wind_field(*f);
    }
    r.read("base", w.base);
    w.current = w.base;
    r.read("walk", w.walk);
    r.read("max_deviation", w.max_deviation);
    r.read("gust_strength", w.gust_strength);
    r.read("gust_rate", w.gust_rate);
    r.read("gust_duration", w.gust_duration);
    r.finish();
    return w;
}

FogMode read_fog_mode(const JsonReader& r, const std::string& mode) {
    if (mode == "exponential") {
        return FogMode::exponential;
    }
    if (mode == "half_life") {
        return FogMode::half_life;
    }
    if (mode == "layered") {
        return FogMode::layered;
    }
    scene_fail(r.field("mode"),
               "must be \"exponential\", \"half_life\" or \"layered\" (got \"" + mode + "\")");
}

Fog read_fog(JsonReader r) {
    Fog f;
    std::string mode = "exponential";
    r.read("mode", mode);
    f.mode = read_fog_mode(r, mode);
    r.read("color", f.color);
    r.read("density", f.density);
    r.read("half_distance", f.half_distance);
    r.read("layer_bottom", f.layer_bottom);
    r.read("layer_top", f.layer_top);
    r.read("layer_density", f.layer_density);
    if (const Json* puffs = r.array("puffs")) {
        for (std::size_t i = 0; i < puffs->size(); ++i) {
            JsonReader p((*puffs)[i], r.field("puffs") + "[" + std::to_string(i) + "]");
            FogPuff puff;
            p.read("center", puff.center);
            p.read("sigma", puff.sigma);
            p.read("density", puff.density);
            p.read("frequency", puff.frequency);
            p.read("phase", puff.phase);
            p.finish();
            f.puffs.push_back(puff);
        }
    }
    r.finish();
    return f;
}

OcclusionCamera read_occlusion(JsonReader r) {
    OcclusionCamera o;
    r.read("resolution", o.resolution, 1, 4096);
    r.read("tilt", o.tilt);
    r.finish();
    return o;
}

SpectralSnow read_spectral(JsonReader r) {
    SpectralSnow s;
    r.read("size_xy", s.size_xy, 1, 1u << 16);
    r.read("size_t", s.size_t, 1, 1u << 16);
    r.read("speed", s.speed);
    r.read("band_low", s.band_low);
    r.read("band_high", s.band_high);
    r.read("opacity", s.opacity);
    r.read("start_distance", s.start_distance);
    r.finish();
    return s;
}

CameraDef read_camera(JsonReader r) {
    CameraDef c;
    r.read("position", c.position);
    r.read("target", c.target);
    r.read("fov_y_deg", c.fov_y_deg);
    r.read("near_plane", c.near_plane);
    r.read("far_plane", c.far_plane);
    r.finish();
    std::string e;
    check::positive(e, r.field("fov_y_deg"), c.fov_y_deg);
    check::at_most(e, r.field("fov_y_deg"), c.fov_y_deg, 170.0);
    check::positive(e, r.field("near_plane"), c.near_plane);
    if (!(c.far_plane > c.near_plane)) {
        check::fail(e, r.field("far_plane"), "> near_plane", c.far_plane);
    }
    if (c.position == c.target) {
        check::fail(e, r.field("target"), "different from position", c.target.x);
    }
    if (!e.empty()) {
        throw SceneError(e);
    }
    return c;
}

glm::vec3 read_colour(JsonReader& r, std::string_view key, glm::vec3 colour) {
    r.read(key, colour);
    std::string e;
    for (int i = 0; i < 3; ++i) {
        check::non_negative(e, r.field(key) + "[" + std::to_string(i) + "]", colour[i]);
    }
    if (!e.empty()) {
        throw SceneError(e);
    }
    return colour;
}

Environment read_environment(JsonReader r) {
    Environment env;
    env.ambient = read_colour(r, "ambient", env.ambient);
    env.sky = read_colour(r, "sky", env.sky);
    r.finish();
    return env;
}

} // namespace

NodeSnow parse_node_snow(const Json& snow, const std::string& path) {
    JsonReader r(snow, path);
    NodeSnow n;
    if (auto s = r.object("surface")) {
        n.surface = read_surface(*s);
    }
    if (const Json* c = r.value("collider")) {
        n.collider = read_collider(*c, r.field("collider"));
    }
    r.finish();
    return n;
}

SceneSnow parse_scene_snow(const Json* snow, const std::string& path) {
    SceneSnow s;
    if (snow == nullptr) {
        return s;
    }
    JsonReader r(*snow, path);
    if (auto sim = r.object("simulation")) {
        read_simulation(*sim, s);
    }
    check_valid(validate(s.config), path);
    if (auto e = r.object("emitter")) {
        s.emitter = read_emitter(*e);
        check_valid(validate(*s.emitter), path);
    }
    if (auto w = r.object("wind")) {
        s.wind = read_wind(*w, s.wind_field);
        check_valid(validate(*s.wind), path);
        if (s.wind_field) {
            check_valid(validate(*s.wind_field), path);
        }
    }
    if (auto f = r.object("fog")) {
        s.fog = read_fog(*f);
        check_valid(validate(*s.fog), path);
    }
    if (auto o = r.object("occlusion")) {
        s.occlusion = read_occlusion(*o);
    }
    if (auto sp = r.object("spectral")) {
        s.spectral = read_spectral(*sp);
        check_valid(validate(*s.spectral), path);
    }
    if (auto c = r.object("camera")) {
        s.camera = read_camera(*c);
    }
    if (auto env = r.object("environment")) {
        s.environment = read_environment(*env);
    }
    r.finish();
    return s;
}

std::vector<LightSpec> parse_lights(const Json& doc) {
    std::vector<LightSpec> lights;
    const auto ext = doc.find("extensions");
    if (ext == doc.end() || !ext->is_object() || !ext->contains("KHR_lights_punctual")) {
        return lights;
    }
    const std::string path = "extensions.KHR_lights_punctual";
    JsonReader khr(ext->at("KHR_lights_punctual"), path);
    const Json* list = khr.array("lights");
    if (list == nullptr) {
        return lights;
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
        JsonReader r((*list)[i], path + ".lights[" + std::to_string(i) + "]");
        std::string type;
        r.read("type", type);
        if (type != "point") {
            scene_fail(r.field("type"),
                       "must be \"point\" (only point lights are supported; got \"" + type + "\")");
        }
        LightSpec l;
        l.color = read_colour(r, "color", l.color);
        r.read("intensity", l.intensity);
        std::string e;
        check::non_negative(e, r.field("intensity"), l.intensity);
        if (!e.empty()) {
            throw SceneError(e);
        }
        lights.push_back(l);
    }
    return lights;
}

std::optional<std::size_t> node_light(const Json& node, const std::string& path,
                                      std::size_t light_count) {
    const auto ext = node.find("extensions");
    if (ext == node.end() || !ext->is_object() || !ext->contains("KHR_lights_punctual")) {
        return std::nullopt;
    }
    JsonReader r(ext->at("KHR_lights_punctual"), path + ".extensions.KHR_lights_punctual");
    if (!r.has("light")) {
        scene_fail(r.path(), "needs a light index");
    }
    if (light_count == 0) {
        scene_fail(r.field("light"), "refers to a light but the file declares none");
    }
    std::uint64_t index = 0;
    r.read("light", index, 0, light_count - 1);
    return static_cast<std::size_t>(index);
}

} // namespace snow
