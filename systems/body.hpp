/// @file body.hpp
/// @brief Moving (kinematic) bodies: spheres, boxes and upright capsules that
/// the host or a scripted path moves. They push flakes aside, carve trails
/// through settled snow with raised rims, and a snowball picks up what it
/// rolls over. Every unit they move stays in the ledger.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace snow {

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
    /// Each tick its lowest point is put on the highest bare ground (surface
    /// or cover base) under its centre, as a walker or a rolling ball; else
    /// its height is its own (path or host).
    bool on_ground = false;
    /// Picks up the snow it rolls over instead of pushing it aside; its
    /// radius grows with what it carries (packed snow).
    bool snowball = false;
    BodyMotion motion;
};

/// Density (kg/m^3) of the snow a snowball packs; sets its growth.
inline constexpr double packed_snow_density = 400.0;

/// Component. `position` is this tick's, `previous` last tick's: trails and
/// flake tests sweep between them.
struct Body {
    BodyShape shape = BodyShape::sphere;
    float radius = 0.25f;
    glm::vec3 half_extents{0.25f};
    float half_height = 0.5f;
    bool on_ground = false;
    bool snowball = false;
    float bare_radius = 0.25f; ///< a snowball's radius carrying nothing
    glm::vec3 position{0.0f};
    glm::vec3 previous{0.0f};
    glm::vec3 velocity{0.0f}; ///< used when there is no path and no target (m/s)
    bool has_target = false;  ///< move_body() set where it is next tick
    glm::vec3 target{0.0f};
    BodyMotion motion;
    std::uint32_t segment = 0; ///< path: the waypoint it heads from
    float along = 0.0f;        ///< path: metres along that segment
    std::uint64_t carried = 0; ///< snowball: units picked up (ledger bucket `carried`)

    /// Lowest point of the body, its centre at height centre_y, above
    /// horizontal offset (dx, dz) from its centre, or false when (dx, dz)
    /// lies outside its footprint.
    [[nodiscard]] bool bottom_at(float centre_y, float dx, float dz, float& y) const;
    /// Half width of the footprint's bounding square (m).
    [[nodiscard]] float reach() const;
};

/// Returns an error naming the bad field, or an empty string.
[[nodiscard]] std::string validate(const BodyDef& def);
/// Returns an error naming the bad field, or an empty string.
[[nodiscard]] std::string validate(const BodyMotion& motion);
/// The body a definition describes, at its position, not moving.
[[nodiscard]] Body make_body(const BodyDef& def);
/// A snowball's radius for `units` carried on top of its bare radius.
[[nodiscard]] float snowball_radius(float bare_radius, std::uint64_t units);

} // namespace snow
