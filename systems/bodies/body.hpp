/// @file body.hpp
/// @brief Moving (kinematic) bodies: spheres, boxes and upright capsules that
/// the host or a scripted path moves. They push flakes aside, carve trails
/// through settled snow with raised rims, and a snowball picks up what it
/// rolls over. Every unit they move stays in the ledger.
#pragma once

#include "ecs/host_memory.hpp"
#include "systems/core/field_rules.hpp"
#include "systems/core/limits.hpp"
#include "systems/core/units.hpp"

#include <glm/vec3.hpp>

#include <cstdint>

#include <snow/defs.hpp>

namespace snow {

/// A body's scripted path: its BodyMotion, in the host's memory.
struct BodyPath {
    Vector<glm::vec3> waypoints; ///< empty: no path
    float speed = 1.0f;          ///< m/s along the path
    bool loop = true;            ///< back to the first waypoint after the last; else stop
};
/// The path `motion` describes.
[[nodiscard]] BodyPath body_path(const BodyMotion& motion);

/// Component. `position` is this tick's, `previous` last tick's: trails and
/// flake tests sweep between them.
struct Body;
class ByteWriter;
class ByteReader;
/// A body's snapshot record: every field (the host may have changed any).
void save_state(ByteWriter& out, const Body& b);
/// Reads a record of save_state into `b` (throws SimulationError naming what is wrong).
void load_state(ByteReader& in, Body& b);

struct Body {
    BodyShape shape = BodyShape::sphere;
    float radius = 0.25f;
    glm::vec3 half_extents{0.25f};
    float half_height = 0.5f;
    bool on_ground = false;
    bool snowball = false;
    float compaction = 0.0f;
    float bare_radius = 0.25f; ///< a snowball's radius carrying nothing
    glm::vec3 position{0.0f};
    glm::vec3 previous{0.0f};
    glm::vec3 velocity{0.0f}; ///< used when there is no path and no target (m/s)
    bool has_target = false;  ///< move_body() set where it is next tick
    glm::vec3 target{0.0f};
    BodyPath motion;
    std::uint32_t segment = 0; ///< path: the waypoint it heads from
    float along = 0.0f;        ///< path: metres along that segment
    std::uint64_t carried = 0; ///< snowball: units picked up (ledger bucket `carried`)

    /// How far below and above its centre the body reaches at horizontal
    /// offset (dx, dz) from it, or false when (dx, dz) lies outside its
    /// footprint. An upright capsule is a walker: it treads on flat soles
    /// across its whole radius (a round bottom would clear only a strip
    /// √(2·radius·depth) wide in thin snow); its head is round.
    [[nodiscard]] bool extent_at(float dx, float dz, float& below, float& above) const;
    /// Half width of the footprint's bounding square (m).
    [[nodiscard]] float reach() const;
};

/// The body a definition describes, at its position, not moving.
[[nodiscard]] Body make_body(const BodyDef& def);
/// A snowball's radius for `units` carried on top of its bare radius.
[[nodiscard]] float snowball_radius(float bare_radius, std::uint64_t units);

/// `motion.*`: a scripted path (its waypoints are checked by validate()).
inline constexpr FieldRule<BodyMotion> motion_fields[] = {
    {"speed", &BodyMotion::speed, between(0, max_body_speed)},
    {"loop", &BodyMotion::loop},
};
/// `body.*` of every shape, then the size fields each shape uses (its
/// motion has its own table).
inline constexpr FieldRule<BodyDef> body_fields[] = {
    {"position", &BodyDef::position},
    {"compaction", &BodyDef::compaction, between(0, 1)},
};
inline constexpr FieldRule<BodyDef> box_body_fields[] = {
    {"half_extents", &BodyDef::half_extents, positive_up_to(max_body_size)},
};
inline constexpr FieldRule<BodyDef> sphere_body_fields[] = {
    {"radius", &BodyDef::radius, positive_up_to(max_body_size)},
};
inline constexpr FieldRule<BodyDef> capsule_body_fields[] = {
    {"radius", &BodyDef::radius, positive_up_to(max_body_size)},
    {"half_height", &BodyDef::half_height, between(0, max_body_size)},
};

[[nodiscard]] Invalid validate(const BodyMotion& motion);
/// Every shape's fields, then the size fields its shape uses and its motion.
[[nodiscard]] Invalid validate(const BodyDef& def);

} // namespace snow
