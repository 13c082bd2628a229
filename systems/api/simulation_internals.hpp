/// @file simulation_internals.hpp
/// @brief What the public Simulation (<snow/snow.hpp>) hides, for snow's own
/// code only (never installed): its World and Schedule, the typed ids'
/// entities, and in-memory snapshots. The renderer, the scene loader and
/// the apps read the World through world_of(); tests and benchmarks of
/// single systems also write it (InternalAccess::world) to arrange a state
/// no facade call makes. Code that drives a running simulation uses the
/// facade's validated calls instead.
#pragma once

#include "ecs/entity.hpp"
#include "ecs/job_pool.hpp"
#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "systems/api/snapshot.hpp"
#include "systems/api/systems.hpp"
#include "systems/bodies/body.hpp"
#include "systems/core/source_versions.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <cstdint>
#include <memory>

#include <snow/snow.hpp>

namespace snow {

/// Made with new, in the host's memory (HostAllocated), as all it holds.
struct Simulation::Impl : HostAllocated {
    World world;
    Schedule schedule;
    std::unique_ptr<JobPool> jobs; ///< the built-in pool, when the host gave no task system

    /// state_hash()'s digest of the sources, recomputed when their versions
    /// change (so state_hash() must not run on two threads at once).
    struct SourceDigest {
        bool valid = false;
        SourceVersions of;
        std::uint64_t value = 0;
    };
    SourceDigest sources_digest;

    void build_schedule();
    /// Readies every system's ticks for the scene as it stands (the
    /// prepare_* of systems.hpp): no tick allocates. Called by each call that
    /// changes the scene's sources or state; waits while `batched`.
    void prepare();
    /// A loader is adding a whole scene (SceneBatch): prepare() runs once at
    /// its end, not once per piece (each rebuilds every system's derived
    /// data, so per piece a scene of N pieces costs N²).
    bool batched = false;
    /// A digest of the settings and the source data (docs/design.md): a
    /// byte snapshot loads only where it matches.
    [[nodiscard]] std::uint64_t scene_fingerprint() const;
};

/// While it lives, the facade calls that add to `sim` leave prepare() to
/// finish(): for loaders adding a whole scene. Never ticks in between. If
/// finish() is not reached (an error), `sim` must be thrown away.
class SceneBatch {
  public:
    explicit SceneBatch(Simulation& sim);
    ~SceneBatch();
    SceneBatch(const SceneBatch&) = delete;
    SceneBatch& operator=(const SceneBatch&) = delete;
    /// Readies the simulation for its first tick (one prepare()).
    void finish();

  private:
    Simulation::Impl& impl_;
};

struct InternalAccess {
    [[nodiscard]] static Simulation::Impl& impl(Simulation& sim) { return *sim.impl_; }
    [[nodiscard]] static const Simulation::Impl& impl(const Simulation& sim) { return *sim.impl_; }
    [[nodiscard]] static World& world(Simulation& sim) { return sim.impl_->world; }
};

/// The Simulation's World, read only.
[[nodiscard]] inline const World& world_of(const Simulation& sim) {
    return InternalAccess::impl(sim).world;
}
[[nodiscard]] inline const Schedule& schedule_of(const Simulation& sim) {
    return InternalAccess::impl(sim).schedule;
}
[[nodiscard]] inline const FlakePool& flake_pool(const Simulation& sim) {
    return world_of(sim).resource<FlakePool>();
}

/// The entity behind a typed id, and back (no check: the facade checks).
template <typename Kind>
[[nodiscard]] constexpr Entity entity_of(Id<Kind> id) {
    return Entity{id.bits};
}
template <typename IdType>
[[nodiscard]] constexpr IdType id_of(Entity e) {
    return IdType{e.bits};
}

/// The SnowSurface of a surface or cover, and a body (throws SimulationError
/// for a stale or null id, like the facade's reads).
[[nodiscard]] const SnowSurface& snow_surface(const Simulation& sim, SurfaceId surface);
[[nodiscard]] const SnowSurface& snow_surface(const Simulation& sim, CoverId cover);
[[nodiscard]] const Body& body_of(const Simulation& sim, BodyId body);
/// The SnowSurface of any surface or cover entity (tests that walk the World).
[[nodiscard]] const SnowSurface& snow_surface(const Simulation& sim, Entity grid);

/// Everything a tick changes, in memory: restore_snapshot() onto the same
/// scene continues bit for bit as the saved run did (for any thread count).
[[nodiscard]] std::unique_ptr<Snapshot> save_snapshot(const Simulation& sim);
/// Throws SimulationError, changing nothing, for a snapshot of another scene.
void restore_snapshot(Simulation& sim, const Snapshot& snapshot);

} // namespace snow
