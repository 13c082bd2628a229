/// @file defs.hpp
/// @brief The settings a host gives the simulation (Box2D's def structs):
/// plain values with defaults, checked by the Simulation call that takes
/// them (a bad value throws snow::SimulationError naming its field).
/// Self-contained: the standard library and GLM only.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

#include <snow/task_system.hpp>

namespace snow {

/// Axis-aligned box, min <= max on every axis.
struct Aabb {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};
    [[nodiscard]] bool contains(const glm::vec3& p) const {
        return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y && p.z >= min.z &&
               p.z <= max.z;
    }
    [[nodiscard]] glm::vec3 size() const { return max - min; }
};

/// How flakes move each tick (docs/design.md "Numerical stability").
enum class Integrator : std::uint8_t {
    explicit_euler,      ///< v += a·dt, p += v·dt ([WF], [ZCL]); guarded when stiff
    semi_implicit_euler, ///< implicit drag, then p += v_new·dt (never overshoots)
    exponential,         ///< exact update for gravity + linear drag to constant wind
    rk4,                 ///< classical Runge-Kutta, the accuracy reference
    automatic,           ///< explicit Euler where k·dt/m <= 0.5, exponential elsewhere
};

/// The simulation's settings, fixed at creation (the integrator may change).
struct SimConfig {
    std::uint64_t seed = 1;
    float dt = 1.0f / 60.0f;               ///< fixed tick length (s)
    glm::vec3 gravity{0.0f, -9.81f, 0.0f}; ///< m/s^2
    Integrator integrator = Integrator::explicit_euler;
    Aabb bounds{{-10.0f, -1.0f, -10.0f}, {10.0f, 12.0f, 10.0f}}; ///< flakes leaving it are removed
    std::uint32_t max_flakes = 50000;
    /// Threads of the built-in pool (the caller is one of them); ignored
    /// when the host gives its own task_system.
    unsigned threads = 1;
    /// The host's task system (not owned; it must outlive the Simulation).
    /// Null: the built-in pool. Results are the same either way.
    TaskSystem* task_system = nullptr;
    /// Smoothing sub-iterations per surface per tick [WF §3]; a pile still
    /// moving after that many continues next tick.
    std::uint32_t smoothing_iterations = 64;
    /// Air temperature (°C), fixed for the run: fresh snow lands at the
    /// density this gives (docs/references.md [HP98]) and settles faster the
    /// warmer it is [And76].
    float air_temperature = -5.0f;
    /// Seconds between two settling steps of every cell [And76]: the cost
    /// of settling falls with it, its accuracy barely (docs/accuracy.md).
    float settle_interval = 10.0f;
};

/// The particle types an emitter can make, each with its own mass and fall
/// speed by size (Locatelli & Hobbs 1974, Table 1; docs/references.md [LH74]).
enum class CrystalType : std::uint8_t {
    dendrite_aggregate, ///< aggregates of unrimed radiating assemblages of dendrites
    rimed_aggregate,    ///< aggregates of densely rimed radiating assemblages of dendrites
};

/// Component. Flakes appear on the top and the upwind sides of the
/// simulation bounds [WF §5]. Each simulated flake is a parcel standing for
/// many real flakes of one size: sizes follow the exponential spectrum of
/// snowfall [GM58], mass and fall speed follow the size [LH74], and the
/// parcels together carry the declared snowfall.
struct Emitter {
    float rate = 2000.0f;          ///< parcels per second: the cost, not the amount of snow
    float snowfall_kg_m2_h = 3.0f; ///< snow reaching the ground (kg/m²/h = mm/h of water)
    CrystalType crystal = CrystalType::dendrite_aggregate;
    float size_mean = 0.004f; ///< 1/Λ of the spectrum N0·e^(−ΛD) (m)
    float size_min = 0.001f;  ///< sizes are clipped to [size_min, size_max] (m)
    float size_max = 0.02f;
};

/// One airborne flake placed by hand (Simulation::place_flake): tests,
/// benchmarks at a fixed load, or an embedder's own emitter.
struct FlakeSpec {
    glm::vec3 position{0.0f};
    glm::vec3 velocity{0.0f};
    float k_over_m = 9.81f;       ///< drag over mass (1/s); 9.81 falls at 1 m/s in still air
    float size = 0.01f;           ///< diameter (m), for rendering
    std::uint32_t mass_units = 1; ///< 1 .. max_flake_units
};

/// World resource. Without it there is no wind system and air is still.
struct Wind {
    glm::vec3 base{2.0f, 0.0f, 0.0f};    ///< mean wind (m/s)
    glm::vec3 current{2.0f, 0.0f, 0.0f}; ///< this tick's wind (state)
    glm::vec3 deviation{0.0f};           ///< state: random-walk offset from base
    float walk = 0.2f;                   ///< random-walk step size (m/s per sqrt(s))
    float max_deviation = 1.0f;          ///< |current - base| stays below this (m/s)
    float gust_strength = 0.0f;          ///< extra speed of a gust along base (m/s)
    float gust_rate = 0.0f;              ///< gusts started per second
    float gust_duration = 1.5f;          ///< seconds
    float gust_left = 0.0f;              ///< state: seconds of the running gust
};

/// Settings to declare a field; see Simulation::set_wind_field().
struct WindFieldDef {
    std::uint32_t cells_x = 64, cells_y = 16, cells_z = 64; ///< grid over SimConfig::bounds
    std::uint32_t update_every = 4;                         ///< ticks between solver steps
    std::uint32_t sample_every = 32;       ///< ticks between a flake's samples (held_wind.hpp)
    std::uint32_t pressure_iterations = 8; ///< red-black SOR sweeps per step (fixed)
    float eddy_viscosity = 0.1f;           ///< turbulent mixing (m²/s); 0: none
    /// The sides at z min and z max are walls the air slides along, as in a
    /// wind tunnel along x: the field is a slice of something that runs on
    /// across the wind (a long fence, a street). The wind's z part is not let
    /// in. false: those sides are open, or take the wind in.
    bool tunnel = false;
};

/// Settings of the transport; see Simulation::set_wind_transport(). The
/// saltation flux follows from the field's wind by a log law; its threshold
/// from the snow's density (docs/wind_field.md "Transport").
struct WindTransportDef {
    /// Aerodynamic roughness length z0 (m) of the snow surface in the log
    /// law u* = κ·U(z)/ln(z/z0). The default, 1 mm, is drifting snow's z0 at
    /// u* ≈ 0.4 m/s by Pomeroy & Gray's saltation-layer roughness.
    float roughness = 1.0e-3f;
    /// Height z (m) above the snow top at which the field's wind U(z) is
    /// read; above `roughness`.
    float height = 0.25f;
    /// Seconds of drifting per second of air: the flux moves this many times
    /// the snow each step, as morphological models speed a bed's evolution
    /// while its flow stays the same (MORFAC, docs/references.md [Roe06]). 1:
    /// real time; a fast-forward to a drift's equilibrium takes more.
    float fast_forward = 1.0f;
    /// Length (m) over which the flux closes the gap to what the wind can
    /// move, e-fold: it builds up along a fetch and drops its surplus over
    /// this length where the air slows. Blowing snow reaches 90% of its
    /// saturated rate over 30–60 m of fetch (docs/references.md [Kob72]).
    float adjustment_length = 20.0f;
};

/// Settings to create a surface; see make_surface().
struct SurfaceDef {
    float x0 = 0.0f, z0 = 0.0f;         ///< world position of the grid corner (min x, min z)
    float size_x = 1.0f, size_z = 1.0f; ///< extent (m)
    float cell = 0.05f;                 ///< cell edge (m)
    float base_y = 0.0f;                ///< height of the bare top for a flat surface (m)
    float slope_x = 0.0f;               ///< d(base)/dx, for tilted tops (m/m)
    float slope_z = 0.0f;               ///< d(base)/dz
    float edge_limit = 0.1f;            ///< snow depth (m) at an edge above which excess spills
    bool spills = true;                 ///< false for the ground: its edges keep their snow
    float laplacian_limit = 20.0f;      ///< cap on |∇²h| (1/m), [WF §3]
    /// Tilted tops that spill: snow holds on by friction and adhesion; a line
    /// of cells down the slope whose weight along the slope beats both
    /// slides off its low edge as one slab (a roof shedding its snow).
    float slide_friction = 0.85f; ///< μ between snow and this surface (tan of the friction angle)
    float slide_adhesion = 18.0f; ///< shear (Pa) the snow's bond to the surface holds
    /// Angle of repose (degrees): snow on steeper slopes of its total height
    /// slides down. Loose dry snow stands at 37–53° (docs/references.md [NSA]).
    float repose_deg = 45.0f;
};

/// Settings to create a cover; see Simulation::add_cover().
struct CoverDef {
    float min_x = -1.0f, min_z = -1.0f; ///< world rectangle the cover spans (m)
    float max_x = 1.0f, max_z = 1.0f;
    float cell = 0.1f;        ///< cell edge (m)
    float edge_limit = 0.02f; ///< snow depth (m) at a drop above which the excess spills
    float drop_limit = 0.15f; ///< a base step (m) larger than this between neighbours is an edge
    float laplacian_limit = 20.0f; ///< cap on |∇²h| of the total height (1/m), [WF §3]
    float repose_deg = 40.0f;      ///< snow on steeper total slopes slides down (degrees)
};

/// The shape of a moving body.
enum class BodyShape : std::uint8_t { sphere, box, capsule };

/// A scripted path: the body moves along the waypoints at `speed`.
struct BodyMotion {
    std::vector<glm::vec3> waypoints; ///< empty: no path
    float speed = 1.0f;               ///< m/s along the path
    bool loop = true;                 ///< back to the first waypoint after the last; else stop
};

/// Settings to create a body; see Simulation::add_body().
struct BodyDef {
    BodyShape shape = BodyShape::sphere;
    glm::vec3 position{0.0f};      ///< centre (m)
    float radius = 0.25f;          ///< sphere and capsule radius (m)
    glm::vec3 half_extents{0.25f}; ///< box half size (m)
    float half_height = 0.5f;      ///< capsule: half length of its vertical core segment (m)
    /// Each tick its lowest point is put on the bare ground (surface or
    /// cover base) under its centre, as a walker or a rolling ball: the
    /// highest within its radius above where its feet were (it steps up that
    /// far and passes under a roof), else the lowest (it climbs out); else
    /// its height is its own (path or host).
    bool on_ground = false;
    /// Picks up the snow it rolls over instead of pushing it aside; its
    /// radius grows with what it carries (packed snow).
    bool snowball = false;
    /// Fraction in [0, 1] of the snow in its way that it packs down under it
    /// instead of pushing it aside (a boot, a tyre): the same units stand
    /// lower, at up to max_packing times the fresh snow's density. 0 pushes
    /// it all into the rims.
    float compaction = 0.0f;
    BodyMotion motion;
};

/// World resource: settings. Without it, no occlusion system runs.
struct OcclusionCamera {
    /// Texels per side over the simulation bounds (at most max_occlusion_resolution).
    std::uint32_t resolution = 256;
    float tilt = 0.0f; ///< radians; projection leans along the wind (|tilt| <= max_occlusion_tilt)
};

} // namespace snow
