/// @file simulation.hpp
/// @brief The Simulation: a World, its Schedule and a job pool. The one
/// object an embedder creates (no GL needed).
#pragma once

#include "ecs/job_pool.hpp"
#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "systems/body.hpp"
#include "systems/colliders.hpp"
#include "systems/emitter.hpp"
#include "systems/flake_pool.hpp"
#include "systems/fog.hpp"
#include "systems/mass_ledger.hpp"
#include "systems/occlusion.hpp"
#include "systems/sim_config.hpp"
#include "systems/snapshot.hpp"
#include "systems/snow_cover.hpp"
#include "systems/snow_surface.hpp"
#include "systems/source_versions.hpp"
#include "systems/spectral_snow.hpp"
#include "systems/systems.hpp"
#include "systems/visuals.hpp"
#include "systems/wind.hpp"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace snow {

/// Thrown for invalid arguments (NaN, negative sizes, ...); the message names
/// the field. The simulation is left exactly as it was.
class SnowError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class Simulation {
  public:
    /// Throws SnowError if the config is invalid.
    explicit Simulation(const SimConfig& config = {});
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    // -- building the scene (each validates and throws SnowError) --
    Entity add_emitter(const Emitter& e);
    void set_wind(const Wind& w);
    void clear_wind();
    /// A snow surface entity; `owner` is the solid it lies on (null for the
    /// ground). Flakes reaching an owner's top are kept only where one of its
    /// surfaces covers that point.
    Entity add_surface(const SurfaceDef& def, Entity owner = null_entity);
    /// A snow cover over a rectangle: snow lies on whatever geometry is under
    /// it (its base follows the highest geometry of each column, rebuilt at
    /// the start of a tick after geometry changed). Columns whose top is a
    /// declared surface stay with that surface.
    Entity add_cover(const CoverDef& def);
    /// A moving body (sphere, box, upright capsule): pushes flakes aside,
    /// carves trails through snow, a snowball picks snow up. Not part of
    /// the static geometry (no sky map or cover rebuild when it moves).
    Entity add_body(const BodyDef& def);
    /// Where body `e` is next tick (swept from where it is now).
    void move_body(Entity e, const glm::vec3& position);
    /// Velocity (m/s) of a body without a path or a move_body target.
    void set_body_velocity(Entity e, const glm::vec3& velocity);
    /// A scripted path for body `e`, from its first waypoint on.
    void set_body_motion(Entity e, const BodyMotion& motion);
    /// Puts a snowball's snow back on the cell under it; returns the units.
    std::uint64_t drop_snowball(Entity e);
    Entity add_box(const Aabb& box);
    Entity add_sphere(const glm::vec3& center, float radius);
    /// A triangle mesh (3 vertices each). Adds a default OcclusionCamera if
    /// there is none: flakes meet meshes through its map, which refreshes at
    /// the end of each tick in which geometry changed.
    Entity add_mesh_collider(std::vector<glm::vec3> triangles);
    void set_occlusion(const OcclusionCamera& cam);
    void set_fog(const Fog& fog);
    void set_spectral(const SpectralSnow& s);
    /// Removes an entity; snow settled on its surfaces counts as removed.
    void remove(Entity e);

    // -- stepping --
    /// Advances exactly one tick of config().dt.
    void tick();
    void run(std::uint64_t ticks);

    // -- reading --
    [[nodiscard]] World& world() { return world_; }
    [[nodiscard]] const World& world() const { return world_; }
    [[nodiscard]] const SimConfig& config() const { return world_.resource<SimConfig>(); }
    [[nodiscard]] std::uint64_t tick_count() const { return world_.resource<SimClock>().tick; }
    [[nodiscard]] const FlakePool& flakes() const { return world_.resource<FlakePool>(); }
    [[nodiscard]] const Schedule& schedule() const { return schedule_; }
    [[nodiscard]] const SimCounters& counters() const { return world_.resource<SimCounters>(); }
    /// 64-bit hash of all simulation state: clock, settings, ledger, counters,
    /// flakes, surfaces (snow and pending smoothing), wind, emitters, the
    /// occlusion camera and map, and every collider. Not the thread count,
    /// nor render-only settings (fog, spectral snow), nor caches that are
    /// pure functions of hashed state.
    [[nodiscard]] std::uint64_t state_hash() const;
    [[nodiscard]] MassReport mass() const;
    /// NaN/inf values in flake and wind state (0 for a healthy run).
    [[nodiscard]] std::uint64_t nonfinite_count() const;

    /// Sets the integrator (the rest of the config is fixed at creation);
    /// throws SnowError for a value outside Integrator.
    void set_integrator(Integrator i);

    /// Everything a tick changes; restore() onto the same scene continues
    /// bit for bit as the saved run did (for any thread count).
    [[nodiscard]] std::unique_ptr<Snapshot> save() const;
    /// Throws SnowError, changing nothing, for a snapshot of another scene.
    void restore(const Snapshot& s);

  private:
    void build_schedule();
    Body& body_for(Entity e, const char* call);

    /// state_hash()'s digest of the sources, recomputed when their versions
    /// change (so state_hash() must not run on two threads at once).
    struct SourceDigest {
        bool valid = false;
        SourceVersions of;
        std::uint64_t value = 0;
    };

    World world_;
    Schedule schedule_;
    std::unique_ptr<JobPool> jobs_;
    mutable SourceDigest source_digest_;
};

} // namespace snow
