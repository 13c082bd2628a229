/// @file simulation.hpp
/// @brief The Simulation: a World, its Schedule and a job pool. The one
/// object an embedder creates (no GL needed), and the only writer of its
/// World: every change goes through a validated call below.
#pragma once

#include "ecs/schedule.hpp"
#include "ecs/world.hpp"
#include "systems/api/fog.hpp"
#include "systems/api/snapshot.hpp"
#include "systems/api/spectral_snow.hpp"
#include "systems/bodies/body.hpp"
#include "systems/core/mass_ledger.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/core/sim_counters.hpp"
#include "systems/core/simulation_error.hpp"
#include "systems/core/source_versions.hpp"
#include "systems/flakes/emitter.hpp"
#include "systems/flakes/flake_pool.hpp"
#include "systems/geometry/geometry.hpp"
#include "systems/sky/occlusion.hpp"
#include "systems/snowpack/snow_cover.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include "systems/wind/wind.hpp"
#include "systems/wind/wind_field.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

namespace snow {

class JobPool;

/// Every call that takes user values validates them first and throws
/// SimulationError naming the field; a call that throws changes nothing.
class Simulation {
  public:
    explicit Simulation(const SimConfig& config = {});
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    // -- building the scene --
    Entity add_emitter(const Emitter& e);
    /// Changes one emitter's rate (flakes per second), same rules as Emitter::rate.
    void set_emitter_rate(Entity emitter, float rate);
    void set_wind(const Wind& w);
    void clear_wind();
    /// A wind field over the bounds that the colliders shape; the global wind
    /// (if set) blows in on its upwind sides. Replaces any field there was.
    void set_wind_field(const WindFieldDef& def);
    void clear_wind_field();
    /// Snow the field's wind moves (docs/wind_field.md "Transport"); needs a
    /// field and stays with it when set_wind_field replaces it.
    void set_wind_transport(const WindTransportDef& def);
    void clear_wind_transport();
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
    /// Moves a box collider to `box`. A box that carries a snow surface cannot
    /// move (its snow would hang in the air): remove it and add a new one.
    void move_box(Entity box_collider, const Aabb& box);
    Entity add_sphere(const glm::vec3& center, float radius);
    /// A triangle mesh (3 vertices each). Adds a default OcclusionCamera if
    /// there is none: flakes meet meshes through its map, which refreshes at
    /// the end of each tick in which geometry changed.
    Entity add_mesh_collider(std::vector<glm::vec3> triangles);
    void set_occlusion(const OcclusionCamera& cam);
    void set_fog(const Fog& fog);
    void clear_fog();
    void set_spectral(const SpectralSnow& s);
    /// Removes an entity; snow settled on its surfaces counts as removed.
    void remove(Entity e);

    // -- adding snow by hand (its mass is booked as spawned) --
    /// One airborne flake; returns its pool slot, or nothing when the pool is full.
    std::optional<std::uint32_t> place_flake(const FlakeSpec& flake);
    /// `units` of settled snow on cell (ix, iz) of a surface; redistribution
    /// smooths it from the next tick on.
    void add_settled_snow(Entity surface, std::uint32_t ix, std::uint32_t iz, std::uint32_t units);

    // -- stepping --
    /// Advances exactly one tick of config().dt.
    void tick();
    void run(std::uint64_t ticks);

    // -- reading --
    /// Every component and resource, read only.
    [[nodiscard]] const World& world() const { return world_; }
    [[nodiscard]] const SimConfig& config() const { return world_.resource<SimConfig>(); }
    [[nodiscard]] std::uint64_t tick_count() const { return world_.resource<SimClock>().tick; }
    [[nodiscard]] const FlakePool& flakes() const { return world_.resource<FlakePool>(); }
    /// The snow surface of a surface entity (depth per cell: SnowSurface::depth(i)).
    [[nodiscard]] const SnowSurface& surface(Entity surface) const;
    /// A moving body as this tick left it (position, radius, snow carried).
    [[nodiscard]] const Body& body(Entity body) const;
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

    /// Sets the integrator (the rest of the config is fixed at creation).
    void set_integrator(Integrator i);

    /// Everything a tick changes; restore() onto the same scene continues
    /// bit for bit as the saved run did (for any thread count).
    [[nodiscard]] std::unique_ptr<Snapshot> save() const;
    /// Throws SimulationError, changing nothing, for a snapshot of another scene.
    void restore(const Snapshot& s);
    /// What save() holds, as versioned bytes (docs/embedding.md "Snapshots"):
    /// for save games, replays and lockstep, in this process or another.
    [[nodiscard]] std::vector<std::byte> save_bytes() const;
    /// Restores bytes of save_bytes() taken from the same scene and settings
    /// (loaded afresh or running). Throws SimulationError naming what is
    /// wrong — cut short, corrupted, another format version, another scene —
    /// and then changes nothing.
    void load_bytes(std::span<const std::byte> bytes);

  private:
    friend struct InternalAccess; // systems/api/internal_access.hpp: tests of single systems

    void build_schedule();
    /// A digest of the settings and the source data (docs/design.md): a
    /// byte snapshot loads only where it matches.
    [[nodiscard]] std::uint64_t scene_fingerprint() const;
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
