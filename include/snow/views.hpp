/// @file views.hpp
/// @brief How a host names and reads what a Simulation holds: typed ids
/// (Box2D's b2BodyId) — each names one kind of thing, so passing a surface
/// where a body belongs does not compile, and each carries a generation, so
/// an id of something removed is refused (snow::SimulationError) instead of
/// reaching its successor; a default-constructed id is null — and read-only
/// views over the simulation's own arrays (valid until the next call that
/// changes it) and plain reports. Self-contained: the standard library and
/// GLM only.
#pragma once

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>

#include <snow/defs.hpp>

namespace snow {

/// One kind of handle; `Tag` only tells the kinds apart.
template <typename Tag>
struct Id {
    std::uint32_t bits = 0; ///< slot and generation, opaque to the host
    [[nodiscard]] constexpr bool is_null() const { return bits == 0; }
    friend constexpr bool operator==(Id, Id) = default;
};

using EmitterId = Id<struct EmitterTag>;   ///< Simulation::add_emitter
using SurfaceId = Id<struct SurfaceTag>;   ///< Simulation::add_surface
using CoverId = Id<struct CoverTag>;       ///< Simulation::add_cover
using BodyId = Id<struct BodyTag>;         ///< Simulation::add_body
using ColliderId = Id<struct ColliderTag>; ///< add_box, add_sphere, add_mesh_collider

/// The invariant `spawned == airborne + settled + carried + removed`, all in
/// integer mass units (docs/design.md "Mass"); `carried` is the snow
/// snowballs picked up.
struct MassReport {
    std::uint64_t spawned = 0;
    std::uint64_t airborne = 0;
    std::uint64_t settled = 0;
    std::uint64_t carried = 0;
    std::uint64_t removed = 0;
    [[nodiscard]] bool balanced() const {
        return spawned == airborne + settled + carried + removed;
    }
};

/// What the systems did so far (landings, rolls, spills...), for run reports
/// and HUDs; not part of the state hash.
struct SimCounters {
    std::uint64_t stiff_flake_ticks = 0; ///< flake-ticks where explicit Euler was unsafe
    std::uint64_t landed = 0;            ///< flakes that became snow
    std::uint64_t rolled = 0;            ///< of those, how many rolled ([ZCL §IV] rules 2/3)
    std::uint64_t smoothing_iterations = 0;
    std::uint64_t spilled_units = 0;
    std::uint64_t occlusion_refreshes = 0;
    std::uint64_t carved_units = 0; ///< units moved out of body footprints
};

/// The base level of a cell with no ground under it (a cover over a gap).
inline constexpr std::int64_t no_ground_level = -(std::int64_t{1} << 61);

/// The height (m) of `levels` steps of `unit_height`, rounded once from
/// double: every height of the snow is computed this way.
[[nodiscard]] inline float level_height(std::int64_t levels, float unit_height) {
    return static_cast<float>(static_cast<double>(levels) * unit_height);
}

/// The airborne flakes, one slot each in structure-of-arrays order. Slots
/// run to `slots()`; a slot holds a flake iff its mass_units is not 0.
struct FlakesView {
    std::span<const float> x, y, z;            ///< position (m)
    std::span<const float> vx, vy, vz;         ///< velocity (m/s)
    std::span<const float> size;               ///< diameter (m)
    std::span<const std::uint32_t> mass_units; ///< 0: a free slot
    /// Each flake's own number: slots are reordered every few ticks, so a
    /// host follows a flake by its id, not by its slot.
    std::span<const std::uint32_t> id;
    std::uint32_t alive = 0; ///< flakes in the slots
    [[nodiscard]] std::size_t slots() const { return mass_units.size(); }
    [[nodiscard]] bool is_alive(std::size_t slot) const { return mass_units[slot] != 0; }
    [[nodiscard]] glm::vec3 position(std::size_t slot) const { return {x[slot], y[slot], z[slot]}; }
    [[nodiscard]] glm::vec3 velocity(std::size_t slot) const {
        return {vx[slot], vy[slot], vz[slot]};
    }
};

/// A surface's or a cover's snow: a grid of nx × nz cells of `cell` metres
/// from (x0, z0), row-major with x fastest. Each cell holds `units` of
/// settled snow, less what bodies packed down (`compacted`, empty when none
/// was); each unit stands `unit_height` metres at fresh density, on the bare
/// top `base_level` (in unit_height steps; no_ground_level where none).
struct SnowGrid {
    SurfaceId surface; ///< set for a surface ...
    CoverId cover;     ///< ... or for a cover
    ColliderId owner;  ///< the solid a surface lies on; null on the ground
    float x0 = 0.0f, z0 = 0.0f, cell = 0.0f;
    std::uint32_t nx = 0, nz = 0;
    float unit_height = 0.0f;
    std::span<const std::uint32_t> units;
    std::span<const std::uint32_t> compacted;
    std::span<const std::int64_t> base_level;
    /// Changes whenever base_level does (a cover follows the geometry under it).
    std::uint64_t base_version = 0;
    [[nodiscard]] std::size_t cell_count() const { return units.size(); }
    [[nodiscard]] std::size_t index(std::uint32_t ix, std::uint32_t iz) const {
        return static_cast<std::size_t>(iz) * nx + ix;
    }
    /// Snow depth (m) of cell i.
    [[nodiscard]] float depth(std::size_t i) const {
        const std::int64_t packed = compacted.empty() ? 0 : std::int64_t{compacted[i]};
        return level_height(std::int64_t{units[i]} - packed, unit_height);
    }
    [[nodiscard]] bool has_ground(std::size_t i) const { return base_level[i] != no_ground_level; }
    /// Height (m) of cell i's bare top; meaningless without ground.
    [[nodiscard]] float base_y(std::size_t i) const {
        return level_height(base_level[i], unit_height);
    }
};

/// A moving body as the last tick left it.
struct BodyState {
    BodyShape shape = BodyShape::sphere;
    glm::vec3 position{0.0f}; ///< centre (m)
    float radius = 0.0f;      ///< sphere and capsule; a snowball's grows with its snow
    glm::vec3 half_extents{0.0f};
    float half_height = 0.0f;
    bool snowball = false;
    std::uint64_t carried = 0; ///< snowball: units picked up (MassReport::carried)
};

} // namespace snow
