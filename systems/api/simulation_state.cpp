// The Simulation's state as a whole: what state_hash() covers and what
// save_snapshot()/restore_snapshot() carry. A tick changes the clock, the ledger, the counters,
// the flake pool, the wind, the surfaces' snow (its compaction and the cells
// waiting for smoothing), each cover's base (it follows the geometry, in as
// many ticks as the flake pool allows), the bodies and the occlusion map;
// everything else is source data (source_versions.hpp), hashed but not saved,
// or a cache rebuilt from it.
#include "systems/api/simulation_internals.hpp"

#include "ecs/state_hash.hpp"
#include "systems/api/state_records.hpp"
#include "systems/flakes/emitter.hpp"
#include "systems/geometry/colliders.hpp"
#include "systems/wind/wind_field_solver.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <utility>

namespace snow {

namespace {

/// The source data: colliders, surface placement and owners, cover settings
/// (a cover's base is state: its hash_state).
std::uint64_t source_digest(const World& w) {
    StateHasher h;
    ByteWriter out(h);
    w.each<BoxCollider>([&](Entity e, const BoxCollider& b) {
        h.value(e.bits);
        out(b.box.min);
        out(b.box.max);
        if (b.porosity != 0.0f) { // a solid box hashes as before porosity
            h.value(b.porosity);
        }
    });
    w.each<SphereCollider>([&](Entity e, const SphereCollider& s) {
        h.value(e.bits);
        out(s.center);
        h.value(s.radius);
    });
    w.each<MeshCollider>([&](Entity e, const MeshCollider& m) {
        h.value(e.bits);
        h.span(std::span<const glm::vec3>(m.triangles));
    });
    w.each<SnowHolder>([&](Entity e, const SnowHolder&) { h.value(e.bits); });
    w.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        h.value(e.bits);
        const auto* of = w.try_get<SurfaceOf>(e);
        h.value(of != nullptr ? of->owner.bits : null_entity.bits);
        h.value(s.x0);
        h.value(s.z0);
        h.value(s.cell);
        h.value(s.nx);
        h.value(s.nz);
        h.value(s.unit_height);
        const auto* cover = w.try_get<SnowCover>(e);
        h.value(cover != nullptr ? cover->drop_limit : -1.0f);
        if (cover == nullptr) {
            h.span(std::span<const std::int64_t>(s.base_level));
        }
        h.value(s.edge_limit_units);
        h.value(s.laplacian_limit_units);
        h.value(s.talus_units);
        if (s.slide_drive > 0.0f) { // a surface that never slides hashes as before the rule
            h.value(s.slide_drive);
            h.value(s.slide_adhesion);
            h.value(s.slide_along_x);
            h.value(s.slide_to_high);
        }
        h.value(s.spills);
    });
    return h.digest();
}

/// Throws, before restore_snapshot() changes anything, unless the world holds a
/// component T on exactly the entities the snapshot saved one for.
template <typename T>
void same_entities(const World& w, const Vector<std::pair<Entity, T>>& saved, const char* what) {
    if (saved.size() != w.count<T>()) {
        throw SimulationError(std::string("restore: snapshot belongs to a different scene (") +
                              what + " count)");
    }
    for (const auto& [e, component] : saved) {
        if (!w.has<T>(e)) {
            throw SimulationError(std::string("restore: snapshot belongs to a different scene (") +
                                  what + " missing)");
        }
    }
}

} // namespace

// Each type's hash_state (or, where the hash is its snapshot record, the
// record itself) sits beside the type; this is the list and its order.
std::uint64_t Simulation::state_hash() const {
    const World& world = impl_->world;
    const SourceVersions versions = source_versions(world);
    StateHasher h;
    ByteWriter records(h);
    h.value(world.resource<SimClock>().tick);
    hash_state(h, world.resource<SimConfig>());
    ledger_record(records, world.resource<MassLedger>(), world.resource<SimCounters>());
    hash_state(h, world.resource<FlakePool>());
    write_optional(records, world.try_resource<Wind>());
    const auto* field = world.try_resource<WindField>();
    h.value(field != nullptr);
    if (field != nullptr) {
        hash_state(h, *field);
    }
    h.value(static_cast<std::uint64_t>(world.count<Emitter>()));
    world.each<Emitter>([&](Entity e, const Emitter& m) {
        h.value(e.bits);
        hash_state(h, m);
    });
    world.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        h.value(e.bits);
        hash_state(h, s);
    });
    world.each<SnowCover>([&](Entity e, const SnowCover& c) {
        h.value(e.bits);
        hash_state(h, c, world.get<SnowSurface>(e), !c.current(versions));
    });
    write_each<Body>(records, world);
    const auto* cam = world.try_resource<OcclusionCamera>();
    h.value(cam != nullptr);
    if (cam != nullptr) {
        h.value(cam->resolution);
        h.value(cam->tilt);
    }
    const auto* map = world.try_resource<OcclusionMap>();
    const bool built = map != nullptr && map->built;
    h.value(built);
    if (built) {
        hash_state(h, *map, map->built_from != versions);
    }
    Impl::SourceDigest& digest = impl_->sources_digest;
    if (!digest.valid || digest.of != versions) {
        digest = {true, versions, source_digest(world)};
    }
    h.value(digest.value);
    return h.digest();
}

std::uint64_t Simulation::Impl::scene_fingerprint() const {
    StateHasher h;
    hash_state(h, world.resource<SimConfig>());
    h.value(source_digest(world));
    return h.digest();
}

std::unique_ptr<Snapshot> save_snapshot(const Simulation& sim) {
    const World& world = world_of(sim);
    auto s = std::make_unique<Snapshot>();
    s->flakes = world.resource<FlakePool>();
    s->clock = world.resource<SimClock>();
    s->ledger = world.resource<MassLedger>();
    s->counters = world.resource<SimCounters>();
    if (const auto* w = world.try_resource<Wind>()) {
        s->wind = *w;
    }
    if (const auto* f = world.try_resource<WindField>()) {
        s->wind_field = *f;
    }
    if (const auto* map = world.try_resource<OcclusionMap>(); map != nullptr && map->built) {
        s->sky_map = *map;
    }
    world.each<SnowSurface>(
        [&](Entity e, const SnowSurface& surf) { s->surfaces.emplace_back(e, surf); });
    world.each<SnowCover>([&](Entity e, const SnowCover& c) { s->covers.emplace_back(e, c); });
    world.each<Body>([&](Entity e, const Body& b) { s->bodies.emplace_back(e, b); });
    return s;
}

void restore_snapshot(Simulation& sim, const Snapshot& s) {
    World& world = InternalAccess::world(sim);
    if (s.flakes.capacity() != world.resource<FlakePool>().capacity()) {
        throw SimulationError("restore: snapshot belongs to a different scene (flake capacity)");
    }
    same_entities(world, s.surfaces, "surface");
    same_entities(world, s.covers, "cover");
    same_entities(world, s.bodies, "body");
    FlakePool& pool = world.resource<FlakePool>();
    pool = s.flakes;
    pool.free_stack.reserve(pool.capacity()); // keep release() allocation-free
    world.resource<SimClock>() = s.clock;
    world.resource<MassLedger>() = s.ledger;
    world.resource<SimCounters>() = s.counters;
    if (!s.wind) {
        world.erase_resource<Wind>();
    } else if (auto* w = world.try_resource<Wind>()) {
        *w = *s.wind;
    } else {
        world.set_resource<Wind>(*s.wind);
    }
    if (s.wind_field) {
        // The solver is rebuilt: its next build applies the obstacles to the
        // restored velocities, as the saved run did when the solids changed.
        world.erase_resource<WindFieldSolver>();
        world.set_resource<WindField>(*s.wind_field);
    } else {
        sim.clear_wind_field();
    }
    // The map's texels are rewritten: its version moves on past every one a
    // cache may have seen (it never goes back), whatever the saved one was.
    auto* map = world.try_resource<OcclusionMap>();
    if (s.sky_map || map != nullptr) {
        const std::uint64_t seen = map != nullptr ? map->version : 0;
        if (map == nullptr) {
            map = &world.set_resource<OcclusionMap>();
        }
        *map = s.sky_map ? *s.sky_map : OcclusionMap{};
        map->version = std::max(seen, s.sky_map ? s.sky_map->version : 0) + 1;
    }
    for (const auto& [e, surf] : s.surfaces) {
        SnowSurface& now = world.get<SnowSurface>(e);
        // A cover's base may differ from the saved one: then its version moves
        // on past both (it never goes back), so no cache of it matches by accident.
        const std::uint64_t seen = now.base_version;
        const bool same_base = now.base_level == surf.base_level;
        now = surf;
        now.base_version = same_base ? seen : std::max(seen, surf.base_version) + 1;
    }
    for (const auto& [e, cover] : s.covers) {
        world.get<SnowCover>(e) = cover;
    }
    for (const auto& [e, body] : s.bodies) {
        world.get<Body>(e) = body;
    }
    InternalAccess::impl(sim).prepare(); // the restored arrays may have less room
}

} // namespace snow
