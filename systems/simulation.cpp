#include "systems/simulation.hpp"

#include "systems/jobs.hpp"
#include "systems/limits.hpp"
#include "systems/validation.hpp"

#include <cmath>

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

} // namespace

Simulation::Simulation(const SimConfig& config) {
    throw_if(validate(config));
    world_.set_resource<SimConfig>(config);
    world_.set_resource<SimClock>();
    world_.set_resource<MassLedger>();
    world_.set_resource<SimCounters>();
    world_.set_resource<SourceVersions>();
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
    schedule_.add("integrate", integrate_system, {flakes});
    schedule_.add("collide", collide_system, {flakes});
    schedule_.add("deposit", deposit_system, {needs<SnowSurface>(), flakes});
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

void Simulation::set_wind(const Wind& w) {
    throw_if(validate(w));
    world_.set_resource<Wind>(w);
}

void Simulation::clear_wind() {
    world_.erase_resource<Wind>();
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
    ++world_.resource<SourceVersions>().surfaces;
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
    ++world_.resource<SourceVersions>().solids;
    return id;
}

Entity Simulation::add_sphere(const glm::vec3& center, float radius) {
    std::string e;
    check::finite3(e, "sphere.center", center);
    check::positive(e, "sphere.radius", radius);
    throw_if(e);
    const Entity id = world_.create();
    world_.add<SphereCollider>(id, SphereCollider{center, radius});
    ++world_.resource<SourceVersions>().solids;
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
    auto& versions = world_.resource<SourceVersions>();
    if (!world_.has_resource<OcclusionCamera>()) {
        world_.set_resource<OcclusionCamera>();
        ++versions.occlusion;
    }
    ++versions.solids;
    return id;
}

void Simulation::set_occlusion(const OcclusionCamera& cam) {
    std::string e;
    if (cam.resolution < 1 || cam.resolution > max_occlusion_resolution) {
        check::fail(e, "occlusion.resolution",
                    "in [1, " + std::to_string(max_occlusion_resolution) + "]", cam.resolution);
    }
    check::finite(e, "occlusion.tilt", cam.tilt);
    check::at_most(e, "occlusion.tilt (magnitude, radians)", std::abs(cam.tilt),
                   max_occlusion_tilt);
    throw_if(e);
    world_.set_resource<OcclusionCamera>(cam);
    ++world_.resource<SourceVersions>().occlusion;
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
        world_.destroy(d);
    }
    versions.surfaces += surfaces_gone ? 1 : 0;
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
