// Scene creation. All simulation state goes through the Simulation facade
// (which validates again and throws SimulationError naming the field); what
// only the renderer reads (meshes, lights, camera, environment) goes to SceneVisuals.
#include "game/scene/scene_build.hpp"
#include "systems/api/simulation_internals.hpp"

#include "game/scene/scene_auto_snow.hpp"
#include "game/scene/scene_budget.hpp"
#include "systems/core/limits.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace snow {

namespace {

/// Runs a facade call; a SimulationError becomes a SceneError prefixed with `prefix`.
template <typename Fn>
auto through_facade(const std::string& prefix, Fn&& fn) {
    try {
        return fn();
    } catch (const SimulationError& e) {
        throw SceneError(prefix + e.what());
    }
}

/// `a·b·c` for declared sizes, saturating far past any budget.
std::uint64_t declared_product(double a, double b, double c = 1.0) {
    const double p = a * b * c;
    return p < 1.0e18 ? static_cast<std::uint64_t>(p) : std::uint64_t{1} << 60;
}

/// Rejects surfaces whose grid is too fine for their node, and adds their
/// cells to the tally, before any memory is spent on them; the facade's own
/// checks handle the remaining values. `scale` is the cell_scale override
/// already applied to d.cell (1 if none).
void tally_surface(const SurfaceDef& d, const std::string& path, float scale, WorkTally& work) {
    work.add(surfaces_work, 1, path + ".surface");
    if (!(std::isfinite(d.cell) && d.cell > 0.0f)) {
        return; // the facade names "surface.cell must be > 0"
    }
    const std::string field =
        path + ".surface.cell" +
        (scale == 1.0f ? "" : " (times the cell_scale override " + number_text(scale) + ")");
    double per_side[2];
    for (int a = 0; a < 2; ++a) {
        const float size = a == 0 ? d.size_x : d.size_z;
        per_side[a] = std::max(std::round(static_cast<double>(size) / d.cell), 1.0);
        if (per_side[a] > max_surface_cells_per_side) {
            scene_fail(field, "gives " + number_text(per_side[a]) +
                                  " cells per side over the node's " + number_text(size) +
                                  " m wide top (at most " +
                                  std::to_string(max_surface_cells_per_side) + ")");
        }
    }
    work.add(snow_cells_work, declared_product(per_side[0], per_side[1]), field);
}

/// Adds what the scene-wide settings `s` cost (flakes, cover, wind field, sky
/// map) to the tally; values past the facade's limits (systems/core/limits.hpp)
/// or otherwise invalid are left to the facade to name. What `d` does not
/// declare, auto snow (`auto_field`) made.
void tally_effects(const SceneSnow& s, const SceneDescription& d, const SimConfig& config,
                   const SceneOverrides& o, const std::string& auto_field, WorkTally& work) {
    const std::string declared = d.settings_path + ".";
    if (config.max_flakes <= max_flakes) {
        work.add(flakes_work, config.max_flakes,
                 o.max_flakes ? "max_flakes (command-line override)"
                              : declared + "simulation.max_flakes");
    }
    if (s.cover) {
        const double cell = static_cast<double>(s.cover->cell) * o.cell_scale.value_or(1.0f);
        if (std::isfinite(cell) && cell > 0.0) {
            const double x = std::ceil((double{s.cover->max_x} - s.cover->min_x) / cell);
            const double z = std::ceil((double{s.cover->max_z} - s.cover->min_z) / cell);
            if (x > 0.0 && z > 0.0 && x * z <= static_cast<double>(max_cover_cells)) {
                work.add(snow_cells_work, declared_product(x, z),
                         d.settings.cover ? declared + "cover.cell" : auto_field);
            }
        }
    }
    if (s.wind_field) {
        const WindFieldDef& f = *s.wind_field;
        const std::uint64_t cells = declared_product(f.cells_x, f.cells_y, f.cells_z);
        if (cells <= max_wind_field_cells && f.pressure_iterations <= max_pressure_iterations) {
            work.add(field_cells_work, cells, declared + "wind.field.cells");
            work.add(field_cell_sweeps_work,
                     declared_product(static_cast<double>(cells), f.pressure_iterations),
                     declared + "wind.field.pressure_iterations");
        }
    }
    const std::uint32_t side =
        o.occlusion_resolution.value_or(s.occlusion ? s.occlusion->resolution : 0);
    if (side <= max_occlusion_resolution) {
        work.add(occlusion_texels_work, declared_product(side, side),
                 o.occlusion_resolution ? "occlusion (command-line override)"
                 : d.settings.occlusion ? declared + "occlusion.resolution"
                                        : auto_field);
    }
}

Aabb default_bounds(const SceneDescription& d, const Aabb& fallback) {
    std::optional<Aabb> b = mesh_bounds(d.geometry);
    if (d.settings.world) { // the terrain is one of the meshes
        const Aabb t = terrain_bounds(*d.settings.world);
        b = b ? Aabb{glm::min(b->min, t.min), glm::max(b->max, t.max)} : t;
    }
    if (!b) {
        return fallback;
    }
    const float m = default_bounds_margin;
    return {b->min - glm::vec3(m), b->max + glm::vec3(m, default_bounds_headroom, m)};
}

SimConfig config_for(const SceneDescription& d, const SceneOverrides& o) {
    SimConfig c = d.settings.config;
    if (!d.settings.has_bounds) {
        c.bounds = default_bounds(d, c.bounds);
    }
    if (o.seed) {
        c.seed = *o.seed;
    }
    if (o.dt) {
        c.dt = *o.dt;
    }
    if (o.threads) {
        c.threads = *o.threads;
    }
    if (o.integrator) {
        c.integrator = *o.integrator;
    }
    if (o.max_flakes) {
        c.max_flakes = *o.max_flakes;
    }
    if (o.smoothing_iterations) {
        c.smoothing_iterations = *o.smoothing_iterations;
    }
    return c;
}

/// The node's collider, if it declares one; null otherwise.
ColliderId add_collider(Simulation& sim, const WorldNode& node, const NodeSnow& role) {
    switch (*role.collider) {
    case ColliderKind::box:
        return sim.add_box(node.bounds, role.porosity);
    case ColliderKind::sphere: {
        const glm::vec3 half = 0.5f * node.bounds.size();
        return sim.add_sphere(0.5f * (node.bounds.min + node.bounds.max),
                              std::max({half.x, half.y, half.z}));
    }
    case ColliderKind::mesh:
        return sim.add_mesh_collider(node_triangles(node));
    case ColliderKind::capsule:
        break; // always a body: add_body
    }
    return {};
}

/// The moving body a node declares, shaped by its bounds.
BodyId add_body(Simulation& sim, const WorldNode& node, const NodeSnow& role) {
    BodyDef d;
    const glm::vec3 half = 0.5f * node.bounds.size();
    d.position = 0.5f * (node.bounds.min + node.bounds.max);
    switch (role.collider.value_or(ColliderKind::sphere)) {
    case ColliderKind::box:
        d.shape = BodyShape::box;
        d.half_extents = half;
        break;
    case ColliderKind::capsule:
        d.shape = BodyShape::capsule;
        d.radius = std::max(half.x, half.z);
        d.half_height = std::max(half.y - d.radius, 0.0f);
        break;
    case ColliderKind::sphere:
    case ColliderKind::mesh:
        d.shape = BodyShape::sphere;
        d.radius = std::max({half.x, half.y, half.z});
        break;
    }
    d.on_ground = role.on_ground;
    d.snowball = role.snowball;
    d.compaction = role.compaction;
    if (role.motion) {
        d.motion = *role.motion;
    }
    return sim.add_body(d);
}

/// Colour of the bare terrain: grey-brown ground, not snow.
constexpr glm::vec3 terrain_color{0.36f, 0.34f, 0.30f};

/// The terrain of `d.settings.world`: one mesh collider and one drawn mesh, "terrain".
void add_terrain(Simulation& sim, const SceneDescription& d, SceneVisuals& visuals) {
    TerrainMesh mesh = terrain_mesh(*d.settings.world, *d.heights);
    through_facade(d.settings_path + ".world: ",
                   [&] { return sim.add_mesh_collider(terrain_triangles(mesh)); });
    MeshRenderable r;
    r.name = "terrain";
    r.positions = std::move(mesh.positions);
    r.normals = std::move(mesh.normals);
    r.indices = std::move(mesh.indices);
    r.color = terrain_color;
    visuals.meshes.push_back(std::move(r));
}

void add_renderables(SceneVisuals& visuals, const WorldNode& node) {
    for (std::size_t k = 0; k < node.primitives.size(); ++k) {
        const WorldPrimitive& p = node.primitives[k];
        MeshRenderable r;
        r.name = k == 0 ? node.name : node.name + "#" + std::to_string(k);
        r.positions = p.positions;
        r.normals = p.normals;
        r.indices = p.indices;
        r.color = p.color;
        r.texture = p.texture;
        r.texcoords = p.texcoords;
        visuals.meshes.push_back(std::move(r));
    }
}

} // namespace

SurfaceDef surface_over(const SurfaceDef& settings, const Aabb& bounds) {
    SurfaceDef d = settings;
    d.x0 = bounds.min.x;
    d.z0 = bounds.min.z;
    d.size_x = bounds.max.x - bounds.min.x;
    d.size_z = bounds.max.z - bounds.min.z;
    d.base_y =
        bounds.max.y - std::max(0.0f, d.slope_x) * d.size_x - std::max(0.0f, d.slope_z) * d.size_z;
    return d;
}

std::unique_ptr<Simulation> build_scene(const SceneDescription& d, const SceneOverrides& o,
                                        SceneVisuals& visuals) {
    if (o.cell_scale && !(std::isfinite(*o.cell_scale) && *o.cell_scale > 0.0f)) {
        scene_fail("cell_scale (command-line override)",
                   "must be finite and > 0 (got " + number_text(*o.cell_scale) + ")");
    }
    const SimConfig config = config_for(d, o);
    // Auto snow fills in what the file leaves undeclared; the rest of the
    // build treats its roles and effects exactly like declared ones.
    std::vector<NodeSnow> roles = d.roles;
    SceneSnow s = d.settings;
    const std::string auto_field =
        o.auto_snow ? "auto_snow (command-line override)" : d.auto_snow_path;
    if (o.auto_snow.value_or(!d.auto_snow_path.empty())) {
        add_auto_snow(d.geometry, config, auto_field, roles, s);
    }
    // Check every surface, and the work the scene declares, before anything
    // is allocated.
    WorkTally work(o.budget);
    std::vector<std::optional<SurfaceDef>> surfaces(d.geometry.nodes.size());
    for (std::size_t i = 0; i < d.geometry.nodes.size(); ++i) {
        const WorldNode& node = d.geometry.nodes[i];
        const NodeSnow& role = roles[i];
        const std::string path = "nodes[" + std::to_string(node.index) + "].extras.snow";
        if ((role.surface || role.collider || is_body(role)) && node.primitives.empty()) {
            scene_fail(path,
                       "declares a surface, collider or body, but the node has no triangle mesh");
        }
        if (role.compaction != 0.0f && !is_body(role)) {
            scene_fail(path + ".compaction",
                       "is for moving bodies only (a motion, a snowball or a capsule)");
        }
        if (role.porosity != 0.0f && (role.collider != ColliderKind::box || is_body(role))) {
            scene_fail(path + ".porosity", "is for box colliders that stand still (a fence)");
        }
        if (role.collider == ColliderKind::mesh && is_body(role)) {
            scene_fail(path + ".collider", "a moving body must be a sphere, box or capsule");
        }
        if (role.surface) {
            surfaces[i] = surface_over(*role.surface, node.bounds);
            surfaces[i]->cell *= o.cell_scale.value_or(1.0f);
            tally_surface(*surfaces[i], path, o.cell_scale.value_or(1.0f), work);
        }
        if (is_body(role)) {
            work.add(bodies_work, 1, path);
        } else if (role.collider == ColliderKind::mesh) {
            for (const WorldPrimitive& p : node.primitives) {
                work.add(collider_triangles_work, p.indices.size() / 3, path + ".collider");
            }
        }
    }
    if (d.heights) {
        work.add(collider_triangles_work,
                 terrain_triangle_count(d.heights->width, d.heights->height),
                 d.settings_path + ".world.heightmap");
    }
    tally_effects(s, d, config, o, auto_field, work);

    auto sim = through_facade("simulation settings (after command-line overrides): ",
                              [&] { return std::make_unique<Simulation>(config); });
    SceneBatch batch(*sim); // one prepare for the whole scene, not one per piece
    for (std::size_t i = 0; i < d.geometry.nodes.size(); ++i) {
        const WorldNode& node = d.geometry.nodes[i];
        const NodeSnow& role = roles[i];
        const std::string prefix = "nodes[" + std::to_string(node.index) + "].extras.snow.";
        ColliderId owner;
        if (is_body(role)) {
            through_facade(prefix, [&] { return add_body(*sim, node, role); });
        } else if (role.collider) {
            owner = through_facade(prefix + "collider: ",
                                   [&] { return add_collider(*sim, node, role); });
        }
        if (surfaces[i]) {
            through_facade(prefix, [&] { return sim->add_surface(*surfaces[i], owner); });
        }
        if (!is_body(role)) {
            add_renderables(visuals, node); // the renderer draws bodies where they are
        }
        if (const auto& light = d.lights[i]) {
            visuals.lights.push_back(PointLight{node.position, light->color, light->intensity});
        }
    }

    if (d.heights) {
        add_terrain(*sim, d, visuals);
    }

    // Facade errors name the declaration, or auto snow for what it made.
    const std::string declared = d.settings_path + ".";
    const std::string made = auto_field + ": ";
    const auto prefix = [&](bool was_declared) { return was_declared ? declared : made; };
    if (s.emitter) {
        through_facade(prefix(d.settings.emitter.has_value()),
                       [&] { return sim->add_emitter(*s.emitter); });
    }
    if (o.wind) {
        Wind wind = s.wind.value_or(Wind{});
        wind.base = wind.current = *o.wind;
        through_facade("wind (command-line override): ", [&] { sim->set_wind(wind); });
    } else if (s.wind) {
        through_facade(declared, [&] { sim->set_wind(*s.wind); });
    }
    if (s.wind_field) {
        through_facade(declared, [&] { sim->set_wind_field(*s.wind_field); });
    }
    if (s.wind_transport) {
        through_facade(declared, [&] { sim->set_wind_transport(*s.wind_transport); });
    }
    if (s.occlusion) {
        through_facade(prefix(d.settings.occlusion.has_value()),
                       [&] { sim->set_occlusion(*s.occlusion); });
    }
    if (s.cover) {
        CoverDef cover = *s.cover;
        cover.cell *= o.cell_scale.value_or(1.0f); // quality presets scale every grid
        through_facade(prefix(d.settings.cover.has_value()), [&] { return sim->add_cover(cover); });
    }
    // After the scene's own camera and the default one mesh colliders bring.
    if (const auto* cam = world_of(*sim).try_resource<OcclusionCamera>();
        cam && o.occlusion_resolution) {
        OcclusionCamera c = *cam;
        c.resolution = *o.occlusion_resolution;
        through_facade("occlusion (command-line override): ", [&] { sim->set_occlusion(c); });
    }
    batch.finish();
    visuals.camera = s.camera.value_or(CameraDef{});
    visuals.environment = s.environment;
    visuals.fog = s.fog; // render-only, validated with the schema
    visuals.spectral = s.spectral;
    visuals.sun = s.sun;
    return sim;
}

} // namespace snow
