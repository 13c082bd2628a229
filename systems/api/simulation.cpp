#include "systems/api/simulation_internals.hpp"

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
auto& component_of(W& world, Entity e, const char* field, const char* kind) {
    auto* c = world.alive(e) ? world.template try_get<T>(e) : nullptr;
    if (c == nullptr) {
        throw SimulationError(field, std::string("is not a living ") + kind);
    }
    return *c;
}

template <typename T>
bool has_component(const World& world, Entity e) {
    return world.alive(e) && world.has<T>(e);
}

bool is_collider(const World& world, Entity e) {
    return world.alive(e) && (world.has<BoxCollider>(e) || world.has<SphereCollider>(e) ||
                              world.has<MeshCollider>(e));
}

/// Removes `e` if it is alive and of its kind (else throws naming `field`);
/// surfaces lying on it go with it, their snow booked as removed.
void remove_entity(World& world, Entity e, const char* field, const char* kind,
                   bool (*is_kind)(const World&, Entity)) {
    if (!is_kind(world, e)) {
        throw SimulationError(field, std::string("is not a living ") + kind);
    }
    auto& ledger = world.resource<MassLedger>();
    auto& versions = world.resource<SourceVersions>();
    if (is_collider(world, e)) {
        ++versions.solids;
    }
    // Surfaces lying on a removed solid go with it; their snow leaves the books as removed.
    Vector<Entity> doomed{e};
    world.each<SurfaceOf>([&](Entity s, const SurfaceOf& of) {
        if (of.owner == e) {
            doomed.push_back(s);
        }
    });
    bool surfaces_gone = false;
    for (const Entity d : doomed) {
        if (const auto* s = world.try_get<SnowSurface>(d)) {
            ledger.removed_surface += s->settled_units();
            surfaces_gone = true;
        }
        if (const auto* b = world.try_get<Body>(d)) {
            ledger.removed_surface += b->carried; // a snowball goes with its snow
        }
        world.destroy(d);
    }
    versions.surfaces += surfaces_gone ? 1 : 0;
}

/// Adds `units` of settled snow to cell (ix, iz), refusing what would
/// overflow the cell.
void add_snow(World& world, SnowSurface& s, std::uint32_t ix, std::uint32_t iz,
              std::uint32_t units) {
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
    world.resource<MassLedger>().spawned += units;
}

SnowGrid grid_of(const World& world, Entity e, const SnowSurface& s) {
    SnowGrid g;
    if (world.has<SnowCover>(e)) {
        g.cover = id_of<CoverId>(e);
    } else {
        g.surface = id_of<SurfaceId>(e);
        g.owner = id_of<ColliderId>(world.get<SurfaceOf>(e).owner);
    }
    g.x0 = s.x0;
    g.z0 = s.z0;
    g.cell = s.cell;
    g.nx = s.nx;
    g.nz = s.nz;
    g.unit_height = s.unit_height;
    g.units = s.snow;
    g.compacted = s.compacted;
    g.base_level = s.base_level;
    g.base_version = s.base_version;
    return g;
}

} // namespace

Simulation::Simulation(const SimConfig& config) : impl_(std::make_unique<Impl>()) {
    throw_if(validate(config));
    World& world = impl_->world;
    world.set_resource<SimConfig>(config);
    world.set_resource<SimClock>();
    world.set_resource<MassLedger>();
    world.set_resource<SimCounters>();
    world.set_resource<SourceVersions>();
    world.set_resource<FlakePool>().reset(config.max_flakes);
    world.set_resource<FlakeOrder>().reset(config.max_flakes);
    TaskSystem* tasks = config.task_system;
    if (tasks == nullptr) {
        impl_->jobs = std::make_unique<JobPool>(config.threads);
        tasks = impl_->jobs.get();
    }
    world.set_resource<Jobs>(Jobs{tasks});
    impl_->build_schedule();
    impl_->prepare();
}

Simulation::~Simulation() = default;

void Simulation::Impl::build_schedule() {
    // Order is the tick's data flow (docs/design.md "One tick"); needs make absent effects free.
    const Requirement flakes = flakes_alive;
    schedule.add("cover", cover_system, {needs<SnowCover>()});
    schedule.add("bodies", body_system, {needs<Body>()});
    schedule.add("order", flake_order_system, {flakes});
    schedule.add("spawn", spawn_system, {needs<Emitter>()});
    schedule.add("wind", wind_system, {needs<Wind>()});
    schedule.add("wind_field", wind_field_system, {needs<WindField>()});
    schedule.add("flakes", flake_pass_system, {flakes});
    schedule.add("carve", carve_system, {needs<Body>(), needs<SnowSurface>()});
    schedule.add("wind_transport", wind_transport_system,
                 {wind_transport_declared, needs<SnowSurface>()});
    schedule.add("settle", settle_system, {needs<SnowSurface>()});
    schedule.add("redistribute", redistribute_system, {needs<SnowSurface>()});
    schedule.add("spill", spill_system, {needs<SnowSurface>()});
    schedule.add("occlusion", occlusion_system, {needs<OcclusionCamera>()});
}

void Simulation::Impl::prepare() {
    if (batched) {
        return; // SceneBatch::finish() prepares once
    }
    // In tick order: later ones read what earlier ones built (the collider grid).
    prepare_cover(world);
    prepare_flake_order(world);
    prepare_wind_field(world);
    prepare_flake_pass(world);
    prepare_carve(world);
    prepare_wind_transport(world);
    prepare_redistribute(world);
    prepare_occlusion(world);
}

SceneBatch::SceneBatch(Simulation& sim) : impl_(InternalAccess::impl(sim)) {
    impl_.batched = true;
}

SceneBatch::~SceneBatch() {
    impl_.batched = false;
}

void SceneBatch::finish() {
    impl_.batched = false;
    impl_.prepare();
}

EmitterId Simulation::add_emitter(const Emitter& e) {
    throw_if(validate(e, impl_->world.resource<SimConfig>().bounds));
    const Entity id = impl_->world.create();
    impl_->world.add<Emitter>(id, e);
    return id_of<EmitterId>(id);
}

void Simulation::set_emitter_rate(EmitterId emitter, float rate) {
    Emitter& e = component_of<Emitter>(impl_->world, entity_of(emitter),
                                       "set_emitter_rate(emitter)", "emitter");
    Emitter changed = e;
    changed.rate = rate;
    throw_if(validate(changed, impl_->world.resource<SimConfig>().bounds));
    e = changed;
}

void Simulation::set_emitter(EmitterId emitter, const Emitter& e) {
    Emitter& current =
        component_of<Emitter>(impl_->world, entity_of(emitter), "set_emitter(emitter)", "emitter");
    throw_if(validate(e, impl_->world.resource<SimConfig>().bounds));
    current = e;
}

void Simulation::set_wind(const Wind& w) {
    throw_if(validate(w));
    impl_->world.set_resource<Wind>(w);
}

void Simulation::clear_wind() {
    impl_->world.erase_resource<Wind>();
}

void Simulation::set_wind_field(const WindFieldDef& def) {
    throw_if(validate(def));
    WindField f = make_wind_field(def, config().bounds);
    if (const auto* old = impl_->world.try_resource<WindField>()) {
        f.transport = old->transport;
    }
    impl_->world.set_resource<WindField>(std::move(f));
    impl_->world.erase_resource<WindFieldSolver>();     // obstacles are marked for the new grid
    impl_->world.resource<FlakePool>().hold_wind(true); // every flake samples the new field
    impl_->prepare();
}

void Simulation::set_wind_transport(const WindTransportDef& def) {
    throw_if(validate(def));
    auto* f = impl_->world.try_resource<WindField>();
    if (f == nullptr) {
        throw SimulationError("set_wind_transport", "needs a wind field (set_wind_field first)");
    }
    f->transport = def;
    impl_->prepare();
}

void Simulation::clear_wind_transport() {
    if (auto* f = impl_->world.try_resource<WindField>()) {
        f->transport.reset();
    }
}

void Simulation::clear_wind_field() {
    impl_->world.erase_resource<WindField>();
    impl_->world.erase_resource<WindFieldSolver>();
    impl_->world.resource<FlakePool>().hold_wind(false);
}

SurfaceId Simulation::add_surface(const SurfaceDef& def, ColliderId owner_id) {
    const Entity owner = entity_of(owner_id);
    if (!owner.is_null() && !is_collider(impl_->world, owner)) {
        throw SimulationError("add_surface(owner)", "is not a living collider");
    }
    SnowSurface surface = make_surface(def, fresh_snow_density(impl_->world.resource<SimConfig>()));
    const Entity id = impl_->world.create();
    impl_->world.add<SnowSurface>(id, std::move(surface));
    impl_->world.add<SurfaceOf>(id, SurfaceOf{owner});
    if (!owner.is_null()) {
        impl_->world.add<SnowHolder>(owner);
    }
    ++impl_->world.resource<SourceVersions>().surfaces;
    impl_->prepare();
    return id_of<SurfaceId>(id);
}

CoverId Simulation::add_cover(const CoverDef& def) {
    SnowSurface surface =
        make_cover_surface(def, fresh_snow_density(impl_->world.resource<SimConfig>()));
    const Entity id = impl_->world.create();
    impl_->world.add<SnowSurface>(id, std::move(surface));
    SnowCover cover;
    cover.drop_limit = def.drop_limit;
    impl_->world.add<SnowCover>(id, std::move(cover));
    ++impl_->world.resource<SourceVersions>().surfaces;
    impl_->prepare();
    return id_of<CoverId>(id);
}

BodyId Simulation::add_body(const BodyDef& def) {
    throw_if(validate(def));
    const Entity id = impl_->world.create();
    impl_->world.add<Body>(id, make_body(def));
    impl_->prepare();
    return id_of<BodyId>(id);
}

void Simulation::move_body(BodyId body, const glm::vec3& position) {

    const Entity e = entity_of(body);
    Invalid err;
    check::finite3(err, "move_body.position", position);
    throw_if(err);
    Body& b = component_of<Body>(impl_->world, e, "move_body(body)", "body");
    b.target = position;
    b.has_target = true;
}

void Simulation::set_body_velocity(BodyId body, const glm::vec3& velocity) {

    const Entity e = entity_of(body);
    Invalid err;
    check::finite3(err, "set_body_velocity.velocity", velocity);
    throw_if(err);
    component_of<Body>(impl_->world, e, "set_body_velocity(body)", "body").velocity = velocity;
}

void Simulation::set_body_motion(BodyId body, const BodyMotion& motion) {

    const Entity e = entity_of(body);
    throw_if(validate(motion));
    Body& b = component_of<Body>(impl_->world, e, "set_body_motion(body)", "body");
    b.motion = body_path(motion);
    b.segment = 0;
    b.along = 0.0f;
}

std::uint64_t Simulation::drop_snowball(BodyId body) {
    const Entity e = entity_of(body);
    Body& b = component_of<Body>(impl_->world, e, "drop_snowball(body)", "body");
    if (b.carried == 0) {
        return 0;
    }
    // Onto the highest surface cell under its centre, then smoothing spreads it.
    SnowSurface* best = nullptr;
    std::size_t cell = 0;
    impl_->world.each<SnowSurface>([&](Entity, SnowSurface& s) {
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

ColliderId Simulation::add_box(const Aabb& box, float porosity) {
    throw_if(validate(box));
    throw_if(validate_porosity(porosity));
    const Entity id = impl_->world.create();
    impl_->world.add<BoxCollider>(id, BoxCollider{box, porosity});
    ++impl_->world.resource<SourceVersions>().solids;
    impl_->prepare();
    return id_of<ColliderId>(id);
}

void Simulation::move_box(ColliderId box_id, const Aabb& box) {
    const Entity box_collider = entity_of(box_id);
    BoxCollider& c = component_of<BoxCollider>(impl_->world, box_collider, "move_box(box_collider)",
                                               "box collider");
    if (impl_->world.has<SnowHolder>(box_collider)) {
        throw SimulationError("move_box(box_collider)",
                              "carries a snow surface, which cannot move with it");
    }
    throw_if(validate(box));
    c.box = box;
    ++impl_->world.resource<SourceVersions>().solids;
    impl_->prepare();
}

ColliderId Simulation::add_sphere(const glm::vec3& center, float radius) {
    Invalid e;
    check::finite3(e, "sphere.center", center);
    check::number(e, "sphere.radius", positive, radius);
    throw_if(e);
    const Entity id = impl_->world.create();
    impl_->world.add<SphereCollider>(id, SphereCollider{center, radius});
    ++impl_->world.resource<SourceVersions>().solids;
    impl_->prepare();
    return id_of<ColliderId>(id);
}

ColliderId Simulation::add_mesh_collider(std::vector<glm::vec3> triangles) {
    Invalid e;
    if (triangles.empty() || triangles.size() % 3 != 0) {
        check::fail(e, "mesh.triangles (vertex count)", "a positive multiple of 3",
                    static_cast<double>(triangles.size()));
    }
    check::finite_each(e, "mesh.triangles", triangles);
    throw_if(e);
    const Entity id = impl_->world.create();
    // The host's vector is copied into the host allocator's memory.
    impl_->world.add<MeshCollider>(
        id, MeshCollider{Vector<glm::vec3>(triangles.begin(), triangles.end())});
    // Flakes meet meshes only through the sky map [SKY]: a mesh needs one.
    auto& versions = impl_->world.resource<SourceVersions>();
    if (!impl_->world.has_resource<OcclusionCamera>()) {
        impl_->world.set_resource<OcclusionCamera>();
        ++versions.occlusion;
    }
    ++versions.solids;
    impl_->prepare();
    return id_of<ColliderId>(id);
}

void Simulation::set_occlusion(const OcclusionCamera& cam) {
    throw_if(validate(cam));
    impl_->world.set_resource<OcclusionCamera>(cam);
    ++impl_->world.resource<SourceVersions>().occlusion;
    impl_->prepare();
}

void Simulation::remove(EmitterId emitter) {
    remove_entity(impl_->world, entity_of(emitter), "remove(emitter)", "emitter",
                  has_component<Emitter>);
    impl_->prepare();
}

void Simulation::remove(SurfaceId surface) {
    remove_entity(impl_->world, entity_of(surface), "remove(surface)", "snow surface",
                  has_component<SurfaceOf>);
    impl_->prepare();
}

void Simulation::remove(CoverId cover) {
    remove_entity(impl_->world, entity_of(cover), "remove(cover)", "snow cover",
                  has_component<SnowCover>);
    impl_->prepare();
}

void Simulation::remove(BodyId body) {
    remove_entity(impl_->world, entity_of(body), "remove(body)", "body", has_component<Body>);
    impl_->prepare();
}

void Simulation::remove(ColliderId collider) {
    remove_entity(impl_->world, entity_of(collider), "remove(collider)", "collider", is_collider);
    impl_->prepare();
}

std::optional<std::uint32_t> Simulation::place_flake(const FlakeSpec& flake) {
    throw_if(validate(flake));
    FlakePool& f = impl_->world.resource<FlakePool>();
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
    impl_->world.resource<MassLedger>().spawned += flake.mass_units;
    return slot;
}

void Simulation::add_settled_snow(SurfaceId surface, std::uint32_t ix, std::uint32_t iz,
                                  std::uint32_t units) {
    add_snow(impl_->world,
             component_of<SnowSurface>(impl_->world, entity_of(surface),
                                       "add_settled_snow(surface)", "snow surface"),
             ix, iz, units);
}

void Simulation::add_settled_snow(CoverId cover, std::uint32_t ix, std::uint32_t iz,
                                  std::uint32_t units) {
    add_snow(impl_->world,
             component_of<SnowSurface>(impl_->world, entity_of(cover), "add_settled_snow(cover)",
                                       "snow cover"),
             ix, iz, units);
}

const SnowSurface& snow_surface(const Simulation& sim, SurfaceId surface) {
    return component_of<SnowSurface>(world_of(sim), entity_of(surface), "surface(surface)",
                                     "snow surface");
}

const SnowSurface& snow_surface(const Simulation& sim, CoverId cover) {
    return component_of<SnowSurface>(world_of(sim), entity_of(cover), "cover(cover)", "snow cover");
}

const SnowSurface& snow_surface(const Simulation& sim, Entity grid) {
    return component_of<SnowSurface>(world_of(sim), grid, "surface(entity)", "snow grid");
}

const Body& body_of(const Simulation& sim, BodyId body) {
    return component_of<Body>(world_of(sim), entity_of(body), "body(body)", "body");
}

SnowGrid Simulation::surface(SurfaceId surface) const {
    return grid_of(impl_->world, entity_of(surface), snow_surface(*this, surface));
}

SnowGrid Simulation::cover(CoverId cover) const {
    return grid_of(impl_->world, entity_of(cover), snow_surface(*this, cover));
}

std::size_t Simulation::snow_grid_count() const {
    return impl_->world.count<SnowSurface>();
}

SnowGrid Simulation::snow_grid(std::size_t index) const {
    std::optional<SnowGrid> found;
    std::size_t k = 0;
    impl_->world.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        if (k++ == index) {
            found = grid_of(impl_->world, e, s);
        }
    });
    if (!found) {
        throw SimulationError("snow_grid(index)",
                              "is past the last grid (" + std::to_string(k) + " grids)");
    }
    return *found;
}

BodyState Simulation::body(BodyId body) const {
    const Body& b = body_of(*this, body);
    BodyState out;
    out.shape = b.shape;
    out.position = b.position;
    out.radius = b.radius;
    out.half_extents = b.half_extents;
    out.half_height = b.half_height;
    out.snowball = b.snowball;
    out.carried = b.carried;
    return out;
}

const SimConfig& Simulation::config() const {
    return impl_->world.resource<SimConfig>();
}

std::uint64_t Simulation::tick_count() const {
    return impl_->world.resource<SimClock>().tick;
}

FlakesView Simulation::flakes() const {
    const FlakePool& f = impl_->world.resource<FlakePool>();
    const std::size_t n = f.slot_end;
    FlakesView v;
    v.x = std::span(f.px).first(n);
    v.y = std::span(f.py).first(n);
    v.z = std::span(f.pz).first(n);
    v.vx = std::span(f.vx).first(n);
    v.vy = std::span(f.vy).first(n);
    v.vz = std::span(f.vz).first(n);
    v.size = std::span(f.size).first(n);
    v.mass_units = std::span(f.mass_units).first(n);
    v.id = std::span(f.id).first(n);
    v.alive = f.alive;
    return v;
}

const SimCounters& Simulation::counters() const {
    return impl_->world.resource<SimCounters>();
}

void Simulation::set_integrator(Integrator i) {
    SimConfig c = impl_->world.resource<SimConfig>();
    c.integrator = i;
    throw_if(validate(c)); // an unknown value would match no rule and freeze every flake
    impl_->world.resource<SimConfig>().integrator = i;
}

void Simulation::tick() {
    impl_->schedule.run(impl_->world);
    ++impl_->world.resource<SimClock>().tick;
}

void Simulation::run(std::uint64_t ticks) {
    for (std::uint64_t i = 0; i < ticks; ++i) {
        tick();
    }
}

MassReport Simulation::mass() const {
    MassReport r;
    const auto& ledger = impl_->world.resource<MassLedger>();
    r.spawned = ledger.spawned;
    r.removed = ledger.removed();
    r.airborne = impl_->world.resource<FlakePool>().airborne_units();
    impl_->world.each<SnowSurface>(
        [&](Entity, const SnowSurface& s) { r.settled += s.settled_units(); });
    impl_->world.each<Body>([&](Entity, const Body& b) { r.carried += b.carried; });
    return r;
}

std::uint64_t Simulation::nonfinite_count() const {
    const FlakePool& f = impl_->world.resource<FlakePool>();
    std::uint64_t n = 0;
    for (std::uint32_t i = 0; i < f.capacity(); ++i) {
        if (!f.is_alive(i)) {
            continue;
        }
        for (const auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz}) {
            n += std::isfinite((*a)[i]) ? 0 : 1;
        }
    }
    if (const auto* w = impl_->world.try_resource<Wind>()) {
        for (int c = 0; c < 3; ++c) {
            n += std::isfinite(w->current[c]) ? 0 : 1;
        }
    }
    return n;
}

} // namespace snow
