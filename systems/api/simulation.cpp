#include "systems/api/simulation.hpp"

#include "ecs/job_pool.hpp"
#include "systems/api/systems.hpp"
#include "systems/api/validation.hpp"
#include "systems/core/jobs.hpp"
#include "systems/core/limits.hpp"
#include "systems/flakes/flake_order.hpp"
#include "systems/geometry/colliders.hpp"
#include "systems/wind/wind_field_solver.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace snow {

namespace {

bool flakes_alive(const World& w) {
    return w.resource<FlakePool>().alive > 0;
}

/// The T of entity `e`; throws SimulationError naming `field` when `e` is
/// stale, null or has no T (`kind` says what it should have been).
template <typename T, typename W>
auto& component_of(W& world, Entity e, const std::string& field, const char* kind) {
    auto* c = world.alive(e) ? world.template try_get<T>(e) : nullptr;
    if (c == nullptr) {
        throw SimulationError(field, std::string("is not a living ") + kind);
    }
    return *c;
}

} // namespace

Simulation::Simulation(const SimConfig& config) {
    throw_if(validate(config));
    world_.set_resource<SimConfig>(config);
    world_.set_resource<SimClock>();
    world_.set_resource<MassLedger>();
    world_.set_resource<SimCounters>();
    world_.set_resource<SourceVersions>();
    world_.set_resource<FlakePool>().reset(config.max_flakes);
    world_.set_resource<FlakeOrder>().reset(config.max_flakes);
    TaskSystem* tasks = config.task_system;
    if (tasks == nullptr) {
        jobs_ = std::make_unique<JobPool>(config.threads);
        tasks = jobs_.get();
    }
    world_.set_resource<Jobs>(Jobs{tasks});
    build_schedule();
}

Simulation::~Simulation() = default;

void Simulation::build_schedule() {
    // Order is the tick's data flow (docs/design.md "One tick"); needs make absent effects free.
    const Requirement flakes = flakes_alive;
    schedule_.add("cover", cover_system, {needs<SnowCover>()});
    schedule_.add("bodies", body_system, {needs<Body>()});
    schedule_.add("order", flake_order_system, {flakes});
    schedule_.add("spawn", spawn_system, {needs<Emitter>()});
    schedule_.add("wind", wind_system, {needs<Wind>()});
    schedule_.add("wind_field", wind_field_system, {needs<WindField>()});
    schedule_.add("flakes", flake_pass_system, {flakes});
    schedule_.add("carve", carve_system, {needs<Body>(), needs<SnowSurface>()});
    schedule_.add("wind_transport", wind_transport_system,
                  {wind_transport_declared, needs<SnowSurface>()});
    schedule_.add("redistribute", redistribute_system, {needs<SnowSurface>()});
    schedule_.add("spill", spill_system, {needs<SnowSurface>()});
    schedule_.add("occlusion", occlusion_system, {needs<OcclusionCamera>()});
}

Entity Simulation::add_emitter(const Emitter& e) {
    throw_if(validate(e));
    const Entity id = world_.create();
    world_.add<Emitter>(id, e);
    return id;
}

void Simulation::set_emitter_rate(Entity emitter, float rate) {
    Emitter& e = component_of<Emitter>(world_, emitter, "set_emitter_rate(emitter)", "emitter");
    Emitter changed = e;
    changed.rate = rate;
    throw_if(validate(changed));
    e = changed;
}

void Simulation::set_wind(const Wind& w) {
    throw_if(validate(w));
    world_.set_resource<Wind>(w);
}

void Simulation::clear_wind() {
    world_.erase_resource<Wind>();
}

void Simulation::set_wind_field(const WindFieldDef& def) {
    throw_if(validate(def));
    WindField f = make_wind_field(def, config().bounds);
    if (const auto* old = world_.try_resource<WindField>()) {
        f.transport = old->transport;
    }
    world_.set_resource<WindField>(std::move(f));
    world_.erase_resource<WindFieldSolver>();     // obstacles are marked for the new grid
    world_.resource<FlakePool>().hold_wind(true); // every flake samples the new field
}

void Simulation::set_wind_transport(const WindTransportDef& def) {
    throw_if(validate(def));
    auto* f = world_.try_resource<WindField>();
    if (f == nullptr) {
        throw SimulationError("set_wind_transport", "needs a wind field (set_wind_field first)");
    }
    f->transport = def;
}

void Simulation::clear_wind_transport() {
    if (auto* f = world_.try_resource<WindField>()) {
        f->transport.reset();
    }
}

void Simulation::clear_wind_field() {
    world_.erase_resource<WindField>();
    world_.erase_resource<WindFieldSolver>();
    world_.resource<FlakePool>().hold_wind(false);
}

Entity Simulation::add_surface(const SurfaceDef& def, Entity owner) {
    if (!owner.is_null() && !world_.alive(owner)) {
        throw SimulationError("add_surface(owner)", "is not a living entity");
    }
    SnowSurface surface = make_surface(def);
    const Entity id = world_.create();
    world_.add<SnowSurface>(id, std::move(surface));
    world_.add<SurfaceOf>(id, SurfaceOf{owner});
    if (!owner.is_null()) {
        world_.add<SnowHolder>(owner);
    }
    ++world_.resource<SourceVersions>().surfaces;
    return id;
}

Entity Simulation::add_cover(const CoverDef& def) {
    SnowSurface surface = make_cover_surface(def);
    const Entity id = world_.create();
    world_.add<SnowSurface>(id, std::move(surface));
    SnowCover cover;
    cover.drop_limit = def.drop_limit;
    world_.add<SnowCover>(id, std::move(cover));
    ++world_.resource<SourceVersions>().surfaces;
    return id;
}

Entity Simulation::add_body(const BodyDef& def) {
    throw_if(validate(def));
    const Entity id = world_.create();
    world_.add<Body>(id, make_body(def));
    return id;
}

void Simulation::move_body(Entity e, const glm::vec3& position) {
    Invalid err;
    check::finite3(err, "move_body.position", position);
    throw_if(err);
    Body& b = component_of<Body>(world_, e, "move_body(body)", "body");
    b.target = position;
    b.has_target = true;
}

void Simulation::set_body_velocity(Entity e, const glm::vec3& velocity) {
    Invalid err;
    check::finite3(err, "set_body_velocity.velocity", velocity);
    throw_if(err);
    component_of<Body>(world_, e, "set_body_velocity(body)", "body").velocity = velocity;
}

void Simulation::set_body_motion(Entity e, const BodyMotion& motion) {
    throw_if(validate(motion));
    Body& b = component_of<Body>(world_, e, "set_body_motion(body)", "body");
    b.motion = motion;
    b.segment = 0;
    b.along = 0.0f;
}

std::uint64_t Simulation::drop_snowball(Entity e) {
    Body& b = component_of<Body>(world_, e, "drop_snowball(body)", "body");
    if (b.carried == 0) {
        return 0;
    }
    // Onto the highest surface cell under its centre, then smoothing spreads it.
    SnowSurface* best = nullptr;
    std::size_t cell = 0;
    world_.each<SnowSurface>([&](Entity, SnowSurface& s) {
        std::uint32_t ix = 0, iz = 0;
        if (s.cell_at(b.position.x, b.position.z, ix, iz) && !s.is_void(s.index(ix, iz)) &&
            (best == nullptr || s.level(s.index(ix, iz)) > best->level(cell))) {
            best = &s;
            cell = s.index(ix, iz);
        }
    });
    if (best == nullptr) {
        throw SimulationError("drop_snowball(body)", "has no snow surface or cover under it");
    }
    const std::uint64_t room = std::numeric_limits<std::uint32_t>::max() - best->snow[cell];
    const std::uint64_t units = std::min(b.carried, room);
    best->snow[cell] += static_cast<std::uint32_t>(units);
    best->mark_dirty(cell);
    b.carried -= units;
    b.radius = snowball_radius(b.bare_radius, b.carried);
    return units;
}

Entity Simulation::add_box(const Aabb& box) {
    throw_if(validate(box));
    const Entity id = world_.create();
    world_.add<BoxCollider>(id, BoxCollider{box});
    ++world_.resource<SourceVersions>().solids;
    return id;
}

void Simulation::move_box(Entity box_collider, const Aabb& box) {
    BoxCollider& c =
        component_of<BoxCollider>(world_, box_collider, "move_box(box_collider)", "box collider");
    if (world_.has<SnowHolder>(box_collider)) {
        throw SimulationError("move_box(box_collider)",
                              "carries a snow surface, which cannot move with it");
    }
    throw_if(validate(box));
    c.box = box;
    ++world_.resource<SourceVersions>().solids;
}

Entity Simulation::add_sphere(const glm::vec3& center, float radius) {
    Invalid e;
    check::finite3(e, "sphere.center", center);
    check::number(e, "sphere.radius", positive, radius);
    throw_if(e);
    const Entity id = world_.create();
    world_.add<SphereCollider>(id, SphereCollider{center, radius});
    ++world_.resource<SourceVersions>().solids;
    return id;
}

Entity Simulation::add_mesh_collider(std::vector<glm::vec3> triangles) {
    Invalid e;
    if (triangles.empty() || triangles.size() % 3 != 0) {
        check::fail(e, "mesh.triangles (vertex count)", "a positive multiple of 3",
                    static_cast<double>(triangles.size()));
    }
    for (std::size_t i = 0; i < triangles.size() && e.empty(); ++i) {
        check::finite3(e, "mesh.triangles[" + std::to_string(i) + "]", triangles[i]);
    }
    throw_if(e);
    const Entity id = world_.create();
    world_.add<MeshCollider>(id, MeshCollider{std::move(triangles)});
    // Flakes meet meshes only through the sky map [SKY]: a mesh needs one.
    auto& versions = world_.resource<SourceVersions>();
    if (!world_.has_resource<OcclusionCamera>()) {
        world_.set_resource<OcclusionCamera>();
        ++versions.occlusion;
    }
    ++versions.solids;
    return id;
}

void Simulation::set_occlusion(const OcclusionCamera& cam) {
    throw_if(validate(cam));
    world_.set_resource<OcclusionCamera>(cam);
    ++world_.resource<SourceVersions>().occlusion;
}

void Simulation::set_fog(const Fog& fog) {
    throw_if(validate(fog));
    world_.set_resource<Fog>(fog);
}

void Simulation::clear_fog() {
    world_.erase_resource<Fog>();
}

void Simulation::set_spectral(const SpectralSnow& s) {
    throw_if(validate(s));
    world_.set_resource<SpectralSnow>(s);
}

void Simulation::remove(Entity e) {
    if (!world_.alive(e)) {
        throw SimulationError("remove(entity)", "is a stale or null handle");
    }
    auto& ledger = world_.resource<MassLedger>();
    auto& versions = world_.resource<SourceVersions>();
    if (world_.has<BoxCollider>(e) || world_.has<SphereCollider>(e) ||
        world_.has<MeshCollider>(e)) {
        ++versions.solids;
    }
    // Surfaces lying on a removed solid go with it; their snow leaves the books as removed.
    std::vector<Entity> doomed{e};
    world_.each<SurfaceOf>([&](Entity s, const SurfaceOf& of) {
        if (of.owner == e) {
            doomed.push_back(s);
        }
    });
    bool surfaces_gone = false;
    for (const Entity d : doomed) {
        if (const auto* s = world_.try_get<SnowSurface>(d)) {
            ledger.removed_surface += s->settled_units();
            surfaces_gone = true;
        }
        if (const auto* b = world_.try_get<Body>(d)) {
            ledger.removed_surface += b->carried; // a snowball goes with its snow
        }
        world_.destroy(d);
    }
    versions.surfaces += surfaces_gone ? 1 : 0;
}

std::optional<std::uint32_t> Simulation::place_flake(const FlakeSpec& flake) {
    throw_if(validate(flake));
    FlakePool& f = world_.resource<FlakePool>();
    std::uint32_t slot = 0;
    if (!f.acquire(slot)) {
        return std::nullopt;
    }
    f.px[slot] = flake.position.x;
    f.py[slot] = flake.position.y;
    f.pz[slot] = flake.position.z;
    f.vx[slot] = flake.velocity.x;
    f.vy[slot] = flake.velocity.y;
    f.vz[slot] = flake.velocity.z;
    f.k_over_m[slot] = flake.k_over_m;
    f.size[slot] = flake.size;
    f.mass_units[slot] = flake.mass_units;
    world_.resource<MassLedger>().spawned += flake.mass_units;
    return slot;
}

void Simulation::add_settled_snow(Entity surface, std::uint32_t ix, std::uint32_t iz,
                                  std::uint32_t units) {
    SnowSurface& s =
        component_of<SnowSurface>(world_, surface, "add_settled_snow(surface)", "snow surface");
    Invalid e;
    if (ix >= s.nx) {
        check::fail(e, "add_settled_snow(ix)", "< " + std::to_string(s.nx), ix);
    }
    if (iz >= s.nz) {
        check::fail(e, "add_settled_snow(iz)", "< " + std::to_string(s.nz), iz);
    }
    if (units == 0) {
        check::fail(e, "add_settled_snow(units)", ">= 1", units);
    }
    if (e.empty() && units > max_cell_units - s.snow[s.index(ix, iz)]) {
        check::fail(e, "add_settled_snow(units)",
                    "at most " + std::to_string(max_cell_units - s.snow[s.index(ix, iz)]) +
                        " (a cell may reach " + std::to_string(max_cell_units) + ")",
                    units);
    }
    throw_if(e);
    s.snow[s.index(ix, iz)] += units;
    s.mark_dirty(ix, iz);
    world_.resource<MassLedger>().spawned += units;
}

const SnowSurface& Simulation::surface(Entity surface) const {
    return component_of<SnowSurface>(world_, surface, "surface(entity)", "snow surface");
}

const Body& Simulation::body(Entity body) const {
    return component_of<Body>(world_, body, "body(entity)", "body");
}

void Simulation::set_integrator(Integrator i) {
    SimConfig c = world_.resource<SimConfig>();
    c.integrator = i;
    throw_if(validate(c)); // an unknown value would match no rule and freeze every flake
    world_.resource<SimConfig>().integrator = i;
}

void Simulation::tick() {
    schedule_.run(world_);
    ++world_.resource<SimClock>().tick;
}

void Simulation::run(std::uint64_t ticks) {
    for (std::uint64_t i = 0; i < ticks; ++i) {
        tick();
    }
}

MassReport Simulation::mass() const {
    MassReport r;
    const auto& ledger = world_.resource<MassLedger>();
    r.spawned = ledger.spawned;
    r.removed = ledger.removed();
    r.airborne = world_.resource<FlakePool>().airborne_units();
    world_.each<SnowSurface>([&](Entity, const SnowSurface& s) { r.settled += s.settled_units(); });
    world_.each<Body>([&](Entity, const Body& b) { r.carried += b.carried; });
    return r;
}

std::uint64_t Simulation::nonfinite_count() const {
    const FlakePool& f = world_.resource<FlakePool>();
    std::uint64_t n = 0;
    for (std::uint32_t i = 0; i < f.capacity(); ++i) {
        if (!f.is_alive(i)) {
            continue;
        }
        for (const auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz}) {
            n += std::isfinite((*a)[i]) ? 0 : 1;
        }
    }
    if (const auto* w = world_.try_resource<Wind>()) {
        for (int c = 0; c < 3; ++c) {
            n += std::isfinite(w->current[c]) ? 0 : 1;
        }
    }
    return n;
}

} // namespace snow
