// The Simulation's state as a whole: what state_hash() covers and what
// save_snapshot()/restore_snapshot() carry. A tick changes the clock, the ledger, the counters,
// the flake pool, the wind, the surfaces' snow (its compaction and the cells
// waiting for smoothing), each cover's base (it follows the geometry, in as
// many ticks as the flake pool allows), the bodies and the occlusion map;
// everything else is source data (source_versions.hpp), hashed but not saved,
// or a cache rebuilt from it.
#include "systems/api/simulation_internals.hpp"

#include "ecs/state_hash.hpp"
#include "systems/geometry/colliders.hpp"
#include "systems/wind/wind_field_solver.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <utility>

namespace snow {

namespace {

void hash_vec3(StateHasher& h, const glm::vec3& v) {
    h.value(v.x);
    h.value(v.y);
    h.value(v.z);
}

/// Field by field, so no padding byte enters the hash. Not the thread count:
/// 1 and 2 threads give the same state.
void hash_config(StateHasher& h, const SimConfig& c) {
    h.value(c.seed);
    h.value(c.dt);
    hash_vec3(h, c.gravity);
    h.value(c.integrator);
    hash_vec3(h, c.bounds.min);
    hash_vec3(h, c.bounds.max);
    h.value(c.max_flakes);
    h.value(c.smoothing_iterations);
}

void hash_ledger(StateHasher& h, const MassLedger& l) {
    for (const std::uint64_t v :
         {l.spawned, l.removed_bounds, l.removed_sphere, l.removed_bare, l.removed_surface}) {
        h.value(v);
    }
}

void hash_counters(StateHasher& h, const SimCounters& c) {
    for (const std::uint64_t v : {c.stiff_flake_ticks, c.landed, c.rolled, c.smoothing_iterations,
                                  c.spilled_units, c.occlusion_refreshes, c.carved_units}) {
        h.value(v);
    }
}

/// Alive slots and the free stack; the path starts are rewritten by the next
/// integrate before anything reads them, so they are not state.
void hash_pool(StateHasher& h, const FlakePool& f) {
    h.value(f.capacity());
    h.value(f.alive);
    h.value(f.max_alive);
    h.value(f.slot_end);
    h.value(f.next_id);
    for (std::uint32_t i = 0; i < f.slot_end; ++i) {
        if (!f.is_alive(i)) {
            continue;
        }
        h.value(i);
        for (const auto* a : {&f.px, &f.py, &f.pz, &f.vx, &f.vy, &f.vz, &f.k_over_m, &f.size}) {
            h.value((*a)[i]);
        }
        h.value(f.mass_units[i]);
        h.value(f.id[i]);
        if (f.holds_wind()) {
            for (const auto& a : f.held_wind) {
                h.value(a[i]);
            }
        }
    }
    h.span(std::span<const std::uint32_t>(f.free_stack));
}

void hash_wind(StateHasher& h, const Wind* w) {
    h.value(w != nullptr);
    if (w == nullptr) {
        return;
    }
    for (const glm::vec3& v : {w->base, w->current, w->deviation}) {
        hash_vec3(h, v);
    }
    for (const float v : {w->walk, w->max_deviation, w->gust_strength, w->gust_rate,
                          w->gust_duration, w->gust_left}) {
        h.value(v);
    }
}

void hash_emitters(StateHasher& h, const World& w) {
    h.value(static_cast<std::uint64_t>(w.count<Emitter>()));
    w.each<Emitter>([&](Entity e, const Emitter& m) {
        h.value(e.bits);
        for (const float v : {m.rate, m.mass_min_g, m.mass_max_g, m.size_min, m.size_max,
                              m.fall_speed_min, m.fall_speed_max}) {
            h.value(v);
        }
    });
}

/// What ticks change in a surface: its snow and its compaction, the cells
/// waiting for smoothing (they decide next tick's work) and the bound
/// deposit's prefilter uses.
void hash_snow(StateHasher& h, const World& w) {
    w.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        h.value(e.bits);
        h.span(std::span<const std::uint32_t>(s.snow));
        if (!s.compacted.empty()) { // never compacted: the hash is what it was before compaction
            h.span(std::span<const std::uint32_t>(s.compacted));
        }
        for (const std::uint32_t v : {s.dirty_x0, s.dirty_z0, s.dirty_x1, s.dirty_z1}) {
            h.value(v);
        }
        h.span(std::span<const CellBox>(s.tile_dirty));
        h.span(std::span<const std::uint32_t>(s.dirty_tiles));
        h.value(s.level_bound);
    });
}

/// A cover's base is state: it follows the geometry only as far as the flake
/// pool takes the snow it sheds, so it is hashed whole (the placement and
/// settings are in source_digest). Its column tops are a pure function of the
/// sources while it is current, so they are hashed only while it is stale;
/// its closed edges and drop cells are functions of those two.
void hash_covers(StateHasher& h, const World& w) {
    const SourceVersions versions = source_versions(w);
    w.each<SnowCover>([&](Entity e, const SnowCover& c) {
        h.value(e.bits);
        h.span(std::span<const std::int64_t>(w.get<SnowSurface>(e).base_level));
        const bool stale = !c.current(versions);
        h.value(stale);
        if (stale) {
            h.span(std::span<const float>(c.column_top));
        }
    });
}

/// Every field of every body: the pose and path progress ticks change, and
/// the shape, velocity, target and path the host sets.
void hash_bodies(StateHasher& h, const World& w) {
    h.value(static_cast<std::uint64_t>(w.count<Body>()));
    w.each<Body>([&](Entity e, const Body& b) {
        h.value(e.bits);
        h.value(b.shape);
        for (const float v :
             {b.radius, b.half_height, b.bare_radius, b.compaction, b.along, b.motion.speed}) {
            h.value(v);
        }
        for (const glm::vec3& v : {b.half_extents, b.position, b.previous, b.velocity, b.target}) {
            hash_vec3(h, v);
        }
        for (const bool v : {b.on_ground, b.snowball, b.has_target, b.motion.loop}) {
            h.value(v);
        }
        h.value(static_cast<std::uint64_t>(b.motion.waypoints.size()));
        for (const glm::vec3& v : b.motion.waypoints) {
            hash_vec3(h, v);
        }
        h.value(b.segment);
        h.value(b.carried);
    });
}

/// A declared wind field: its settings and grid, and its state (velocities,
/// the pressure the next projection starts from, inflow, step clock). What
/// derives from them (cell-centre velocities, the solver) is not hashed.
void hash_wind_field(StateHasher& h, const WindField* f) {
    h.value(f != nullptr);
    if (f == nullptr) {
        return;
    }
    const WindFieldDef& d = f->def;
    for (const std::uint32_t v :
         {d.cells_x, d.cells_y, d.cells_z, d.update_every, d.sample_every, d.pressure_iterations}) {
        h.value(v);
    }
    h.value(d.eddy_viscosity);
    hash_vec3(h, f->origin);
    hash_vec3(h, f->inv_cell);
    for (const auto& v : f->velocity) {
        h.span(std::span<const float>(v));
    }
    h.span(std::span<const float>(f->pressure));
    hash_vec3(h, f->inflow);
    h.value(f->wait);
    h.value(f->steps);
    if (const auto& t = f->transport) {
        for (const float v : {t->threshold, t->rate, t->max_fraction, t->height}) {
            h.value(v);
        }
    }
}

/// The camera, and the map where it is not a pure function of hashed state:
/// its lean (held with hysteresis) always, its texels while it is stale.
void hash_occlusion(StateHasher& h, const World& w) {
    const auto* cam = w.try_resource<OcclusionCamera>();
    h.value(cam != nullptr);
    if (cam != nullptr) {
        h.value(cam->resolution);
        h.value(cam->tilt);
    }
    const auto* map = w.try_resource<OcclusionMap>();
    const bool built = map != nullptr && map->built;
    h.value(built);
    if (!built) {
        return;
    }
    h.value(map->x0);
    h.value(map->z0);
    h.value(map->texel);
    h.value(map->width);
    h.value(map->height);
    h.value(map->wind_angle);
    h.value(map->shear_x);
    h.value(map->shear_z);
    const bool stale = map->built_from != source_versions(w);
    h.value(stale);
    if (stale) {
        h.span(std::span<const float>(map->top_y));
        h.span(std::span<const std::uint32_t>(map->top_id));
    }
}

/// The source data: colliders, surface placement and owners, cover settings
/// (a cover's base is state: hash_covers).
std::uint64_t source_digest(const World& w) {
    StateHasher h;
    w.each<BoxCollider>([&](Entity e, const BoxCollider& b) {
        h.value(e.bits);
        hash_vec3(h, b.box.min);
        hash_vec3(h, b.box.max);
    });
    w.each<SphereCollider>([&](Entity e, const SphereCollider& s) {
        h.value(e.bits);
        hash_vec3(h, s.center);
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
        if (s.slide_units != 0) { // a surface that never slides hashes as before the rule
            h.value(s.slide_units);
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

std::uint64_t Simulation::state_hash() const {
    const World& world = impl_->world;
    StateHasher h;
    h.value(world.resource<SimClock>().tick);
    hash_config(h, world.resource<SimConfig>());
    hash_ledger(h, world.resource<MassLedger>());
    hash_counters(h, world.resource<SimCounters>());
    hash_pool(h, world.resource<FlakePool>());
    hash_wind(h, world.try_resource<Wind>());
    hash_wind_field(h, world.try_resource<WindField>());
    hash_emitters(h, world);
    hash_snow(h, world);
    hash_covers(h, world);
    hash_bodies(h, world);
    hash_occlusion(h, world);
    const SourceVersions versions = source_versions(world);
    Impl::SourceDigest& digest = impl_->sources_digest;
    if (!digest.valid || digest.of != versions) {
        digest = {true, versions, source_digest(world)};
    }
    h.value(digest.value);
    return h.digest();
}

std::uint64_t Simulation::Impl::scene_fingerprint() const {
    StateHasher h;
    hash_config(h, world.resource<SimConfig>());
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
