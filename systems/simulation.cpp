#include "systems/simulation.hpp"

#include "ecs/state_hash.hpp"
#include "systems/jobs.hpp"
#include "systems/validation.hpp"
#include "systems/wind_field_solver.hpp"

#include <cmath>
#include <optional>

namespace snow {

namespace {

void throw_if(const std::string& error) {
    if (!error.empty()) {
        throw SnowError(error);
    }
}

bool flakes_alive(const World& w) {
    return w.resource<FlakePool>().alive > 0;
}

bool same_grid(const WindField& a, const WindField& b) {
    return a.n[0] == b.n[0] && a.n[1] == b.n[1] && a.n[2] == b.n[2] && a.origin == b.origin &&
           a.inv_cell == b.inv_cell;
}

} // namespace

Simulation::Simulation(const SimConfig& config) {
    throw_if(validate(config));
    world_.set_resource<SimConfig>(config);
    world_.set_resource<SimClock>();
    world_.set_resource<MassLedger>();
    world_.set_resource<SimCounters>();
    world_.set_resource<GeometryVersion>();
    world_.set_resource<FlakePool>().reset(config.max_flakes);
    jobs_ = std::make_unique<JobPool>(config.threads);
    world_.set_resource<Jobs>(Jobs{jobs_.get()});
    build_schedule();
}

Simulation::~Simulation() = default;

void Simulation::build_schedule() {
    // Order is the tick's data flow (DESIGN.md); needs make absent effects free.
    const Requirement flakes = flakes_alive;
    schedule_.add("spawn", spawn_system, {needs<Emitter>()});
    schedule_.add("wind", wind_system, {needs<Wind>()});
    schedule_.add("wind_field", wind_field_system, {needs<WindField>()});
    schedule_.add("integrate", integrate_system, {flakes});
    schedule_.add("collide", collide_system, {flakes});
    schedule_.add("deposit", deposit_system, {needs<SnowSurface>(), flakes});
    schedule_.add("redistribute", redistribute_system, {needs<SnowSurface>()});
    schedule_.add("spill", spill_system, {needs<SnowSurface>()});
    schedule_.add("occlusion", occlusion_system, {needs<OcclusionCamera>()});
}

void Simulation::bump_geometry() {
    ++world_.resource<GeometryVersion>().version;
}

Entity Simulation::add_emitter(const Emitter& e) {
    throw_if(validate(e));
    const Entity id = world_.create();
    world_.add<Emitter>(id, e);
    return id;
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
    world_.set_resource<WindField>(make_wind_field(def, config().bounds));
    world_.erase_resource<WindFieldSolver>(); // obstacles are marked for the new grid
}

void Simulation::clear_wind_field() {
    world_.erase_resource<WindField>();
    world_.erase_resource<WindFieldSolver>();
}

Entity Simulation::add_surface(const SurfaceDef& def, Entity owner) {
    if (!owner.is_null() && !world_.alive(owner)) {
        throw SnowError("surface owner is not a living entity");
    }
    std::string error;
    SnowSurface surface = make_surface(def, error);
    throw_if(error);
    const Entity id = world_.create();
    world_.add<SnowSurface>(id, std::move(surface));
    world_.add<SurfaceOf>(id, SurfaceOf{owner});
    if (!owner.is_null()) {
        world_.add<SnowHolder>(owner);
    }
    bump_geometry();
    return id;
}

Entity Simulation::add_box(const Aabb& box) {
    std::string e;
    check::finite3(e, "box.min", box.min);
    check::finite3(e, "box.max", box.max);
    check::ordered(e, "box.min.x", box.min.x, "box.max.x", box.max.x);
    check::ordered(e, "box.min.y", box.min.y, "box.max.y", box.max.y);
    check::ordered(e, "box.min.z", box.min.z, "box.max.z", box.max.z);
    throw_if(e);
    const Entity id = world_.create();
    world_.add<BoxCollider>(id, BoxCollider{box});
    bump_geometry();
    return id;
}

Entity Simulation::add_sphere(const glm::vec3& center, float radius) {
    std::string e;
    check::finite3(e, "sphere.center", center);
    check::positive(e, "sphere.radius", radius);
    throw_if(e);
    const Entity id = world_.create();
    world_.add<SphereCollider>(id, SphereCollider{center, radius});
    bump_geometry();
    return id;
}

Entity Simulation::add_mesh_collider(std::vector<glm::vec3> triangles) {
    std::string e;
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
    // Flakes meet meshes only through the sky map (seed 004): a mesh needs one.
    if (!world_.has_resource<OcclusionCamera>()) {
        world_.set_resource<OcclusionCamera>();
    }
    bump_geometry();
    return id;
}

void Simulation::set_occlusion(const OcclusionCamera& cam) {
    std::string e;
    if (cam.resolution < 1 || cam.resolution > 4096) {
        check::fail(e, "occlusion.resolution", "in [1, 4096]", cam.resolution);
    }
    check::finite(e, "occlusion.tilt", cam.tilt);
    check::at_most(e, "occlusion.tilt (magnitude, radians)", std::abs(cam.tilt), 1.2);
    throw_if(e);
    world_.set_resource<OcclusionCamera>(cam);
    bump_geometry();
}

void Simulation::set_fog(const Fog& fog) {
    throw_if(validate(fog));
    world_.set_resource<Fog>(fog);
}

void Simulation::set_spectral(const SpectralSnow& s) {
    throw_if(validate(s));
    world_.set_resource<SpectralSnow>(s);
}

void Simulation::remove(Entity e) {
    if (!world_.alive(e)) {
        throw SnowError("remove: stale or null entity handle");
    }
    auto& ledger = world_.resource<MassLedger>();
    // Surfaces lying on a removed solid go with it; their snow leaves the books as removed.
    std::vector<Entity> doomed{e};
    world_.each<SurfaceOf>([&](Entity s, const SurfaceOf& of) {
        if (of.owner == e) {
            doomed.push_back(s);
        }
    });
    for (const Entity d : doomed) {
        if (const auto* s = world_.try_get<SnowSurface>(d)) {
            ledger.removed_surface += s->settled_units();
        }
        world_.destroy(d);
    }
    bump_geometry();
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

std::uint64_t Simulation::state_hash() const {
    StateHasher h;
    h.value(world_.resource<SimClock>().tick);
    const auto& ledger = world_.resource<MassLedger>();
    h.value(ledger.spawned);
    h.value(ledger.removed());
    const FlakePool& f = world_.resource<FlakePool>();
    for (std::uint32_t i = 0; i < f.capacity(); ++i) {
        if (!f.is_alive(i)) {
            continue;
        }
        h.value(i);
        for (const auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz, &f.k_over_m, &f.size}) {
            h.value((*a)[i]);
        }
        h.value(f.mass_units[i]);
    }
    h.span(std::span<const std::uint32_t>(f.free_stack));
    world_.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        h.value(e.bits);
        h.span(std::span<const std::uint32_t>(s.snow));
    });
    if (const auto* w = world_.try_resource<Wind>()) {
        h.value(w->current);
        h.value(w->deviation);
        h.value(w->gust_left);
    }
    if (const auto* f = world_.try_resource<WindField>()) {
        for (const auto& v : f->velocity) {
            h.span(std::span<const float>(v));
        }
        h.span(std::span<const float>(f->pressure));
        h.value(f->inflow);
        h.value(f->wait);
        h.value(f->steps);
    }
    return h.digest();
}

MassReport Simulation::mass() const {
    MassReport r;
    const auto& ledger = world_.resource<MassLedger>();
    r.spawned = ledger.spawned;
    r.removed = ledger.removed();
    r.airborne = world_.resource<FlakePool>().airborne_units();
    world_.each<SnowSurface>([&](Entity, const SnowSurface& s) { r.settled += s.settled_units(); });
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

std::unique_ptr<Snapshot> Simulation::save() const {
    auto s = std::make_unique<Snapshot>();
    s->flakes = world_.resource<FlakePool>();
    s->clock = world_.resource<SimClock>();
    s->ledger = world_.resource<MassLedger>();
    if (const auto* w = world_.try_resource<Wind>()) {
        s->wind = *w;
    }
    if (const auto* f = world_.try_resource<WindField>()) {
        s->wind_field = *f;
    }
    world_.each<SnowSurface>(
        [&](Entity e, const SnowSurface& surf) { s->surfaces.emplace_back(e, surf); });
    return s;
}

void Simulation::restore(const Snapshot& s) {
    for (const auto& [e, surf] : s.surfaces) {
        if (!world_.has<SnowSurface>(e)) {
            throw SnowError("restore: snapshot belongs to a different scene (surface missing)");
        }
    }
    FlakePool& pool = world_.resource<FlakePool>();
    pool = s.flakes;
    pool.free_stack.reserve(pool.capacity()); // keep release() allocation-free
    world_.resource<SimClock>() = s.clock;
    world_.resource<MassLedger>() = s.ledger;
    if (s.wind) {
        world_.set_resource<Wind>(*s.wind);
    } else {
        world_.erase_resource<Wind>();
    }
    if (s.wind_field) {
        if (const auto* f = world_.try_resource<WindField>();
            f == nullptr || !same_grid(*f, *s.wind_field)) {
            world_.erase_resource<WindFieldSolver>(); // obstacles are re-marked for its grid
        }
        world_.set_resource<WindField>(*s.wind_field);
    } else {
        clear_wind_field();
    }
    for (const auto& [e, surf] : s.surfaces) {
        world_.get<SnowSurface>(e) = surf;
    }
}

} // namespace snow
