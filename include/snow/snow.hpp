/// @file snow.hpp
/// @brief The simulation API (target snow::sim, no GL): create a Simulation
/// from its def (or from a glTF file with <snow/scene.hpp>), change it only
/// through its validated calls, step it at a fixed dt (FixedStep turns host
/// frames into ticks), read it back through views (<snow/views.hpp>), save
/// and load it as bytes. Everything it throws is a snow::SimulationError.
/// Its memory comes from the host's allocator (<snow/allocator.hpp>).
/// Self-contained: the standard library and GLM only. See docs/embedding.md.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <snow/allocator.hpp>
#include <snow/defs.hpp>
#include <snow/error.hpp>
#include <snow/task_system.hpp>
#include <snow/views.hpp>

namespace snow {

/// The one object an embedder creates, and the only writer of its state.
/// Every call that takes user values validates them first and throws
/// SimulationError naming the field; a call that throws changes nothing.
/// Ids of another Simulation, or of something removed, are refused.
class Simulation {
  public:
    explicit Simulation(const SimConfig& config = {});
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    // -- building the scene --
    EmitterId add_emitter(const Emitter& e);
    /// Changes one emitter's rate (parcels per second), same rules as Emitter::rate.
    void set_emitter_rate(EmitterId emitter, float rate);
    /// Replaces all of one emitter's settings, same rules as add_emitter().
    void set_emitter(EmitterId emitter, const Emitter& e);
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
    /// A snow surface; `owner` is the solid it lies on (null for the ground).
    /// Flakes reaching an owner's top are kept only where one of its surfaces
    /// covers that point.
    SurfaceId add_surface(const SurfaceDef& def, ColliderId owner = {});
    /// A snow cover over a rectangle: snow lies on whatever geometry is under
    /// it (its base follows the highest geometry of each column, rebuilt at
    /// the start of a tick after geometry changed). Columns whose top is a
    /// declared surface stay with that surface.
    CoverId add_cover(const CoverDef& def);
    /// A moving body (sphere, box, upright capsule): pushes flakes aside,
    /// carves trails through snow, a snowball picks snow up. Not part of
    /// the static geometry (no sky map or cover rebuild when it moves).
    BodyId add_body(const BodyDef& def);
    /// Where the body is next tick (swept from where it is now).
    void move_body(BodyId body, const glm::vec3& position);
    /// Velocity (m/s) of a body without a path or a move_body target.
    void set_body_velocity(BodyId body, const glm::vec3& velocity);
    /// A scripted path for the body, from its first waypoint on.
    void set_body_motion(BodyId body, const BodyMotion& motion);
    /// Puts a snowball's snow back on the cell under it; returns the units.
    std::uint64_t drop_snowball(BodyId body);
    /// A box collider; `porosity` in [0, 1) makes it a slat fence the wind
    /// blows through against a pressure loss (0: solid).
    ColliderId add_box(const Aabb& box, float porosity = 0.0f);
    /// Moves a box collider to `box`. A box that carries a snow surface cannot
    /// move (its snow would hang in the air): remove it and add a new one.
    void move_box(ColliderId box, const Aabb& to);
    ColliderId add_sphere(const glm::vec3& center, float radius);
    /// A triangle mesh (3 vertices each). Adds a default OcclusionCamera if
    /// there is none: flakes meet meshes through its map, which refreshes at
    /// the end of each tick in which geometry changed.
    ColliderId add_mesh_collider(std::vector<glm::vec3> triangles);
    void set_occlusion(const OcclusionCamera& cam);
    /// Removes it; snow settled on it (and on the surfaces lying on a
    /// removed collider, which go with it) counts as removed.
    void remove(EmitterId emitter);
    void remove(SurfaceId surface);
    void remove(CoverId cover);
    void remove(BodyId body);
    void remove(ColliderId collider);

    // -- adding snow by hand (its mass is booked as spawned) --
    /// One airborne flake; returns its slot, or nothing when the pool is full.
    std::optional<std::uint32_t> place_flake(const FlakeSpec& flake);
    /// `units` of settled snow on cell (ix, iz) of a surface or cover;
    /// redistribution smooths it from the next tick on.
    void add_settled_snow(SurfaceId surface, std::uint32_t ix, std::uint32_t iz,
                          std::uint32_t units);
    void add_settled_snow(CoverId cover, std::uint32_t ix, std::uint32_t iz, std::uint32_t units);

    // -- stepping --
    /// Advances exactly one tick of config().dt.
    void tick();
    void run(std::uint64_t ticks);
    /// Sets the integrator (the rest of the config is fixed at creation).
    void set_integrator(Integrator i);

    // -- reading (views stay valid until the next call that changes the simulation) --
    [[nodiscard]] const SimConfig& config() const;
    [[nodiscard]] std::uint64_t tick_count() const;
    [[nodiscard]] FlakesView flakes() const;
    [[nodiscard]] SnowGrid surface(SurfaceId surface) const;
    [[nodiscard]] SnowGrid cover(CoverId cover) const;
    /// Every snow grid, surfaces and covers (their order changes only when
    /// one is removed).
    [[nodiscard]] std::size_t snow_grid_count() const;
    [[nodiscard]] SnowGrid snow_grid(std::size_t index) const;
    [[nodiscard]] BodyState body(BodyId body) const;
    [[nodiscard]] const SimCounters& counters() const;
    [[nodiscard]] MassReport mass() const;
    /// 64-bit hash of all simulation state: clock, settings, ledger, counters,
    /// flakes, surfaces (snow and pending smoothing), wind, emitters, the
    /// occlusion camera and map, and every collider. Not the thread count
    /// or task system, nor caches that are pure functions of hashed state.
    [[nodiscard]] std::uint64_t state_hash() const;
    /// NaN/inf values in flake and wind state (0 for a healthy run).
    [[nodiscard]] std::uint64_t nonfinite_count() const;

    // -- snapshots (docs/embedding.md "Snapshots") --
    /// Everything a tick changes, as versioned bytes: for save games,
    /// replays and lockstep, in this process or another.
    [[nodiscard]] std::vector<std::byte> save_bytes() const;
    /// Restores bytes of save_bytes() taken from the same scene and settings
    /// (loaded afresh or running): the run continues bit for bit, for any
    /// thread count. Throws SimulationError naming what is wrong — cut short,
    /// corrupted, another format version, another scene — and then changes
    /// nothing.
    void load_bytes(std::span<const std::byte> bytes);

    struct Impl; ///< systems/api/simulation_internals.hpp

  private:
    friend struct InternalAccess;
    std::unique_ptr<Impl> impl_;
};

/// The fixed-timestep accumulator between a host's variable frames and the
/// simulation's fixed tick: each frame, advance() says how many ticks are
/// due; the remainder carries to the next frame.
class FixedStep {
  public:
    /// Ticks of `dt` seconds, at most `max_ticks_per_frame` per frame: after a
    /// stall (a breakpoint, a dragged window) the backlog beyond that is
    /// dropped, so a slow frame never makes the next ones slower still.
    /// Throws SimulationError for a dt that is not finite and > 0, or a cap of 0.
    explicit FixedStep(double dt, std::uint32_t max_ticks_per_frame = 8);

    /// Adds `seconds` of host time; returns the ticks to run now. Throws
    /// SimulationError for a negative or non-finite `seconds`.
    [[nodiscard]] std::uint32_t advance(double seconds);

    /// Host time not simulated yet (s), below dt after every advance().
    [[nodiscard]] double remainder() const { return accumulated_; }
    [[nodiscard]] double dt() const { return dt_; }

  private:
    double dt_;
    std::uint32_t max_ticks_;
    double accumulated_ = 0.0;
};

} // namespace snow
