/// @file ids.hpp
/// @brief Typed handles to what a Simulation holds (Box2D's b2BodyId): each
/// names one kind of thing, so passing a surface where a body belongs does
/// not compile, and each carries a generation, so a handle to something
/// removed is refused (snow::SimulationError) instead of reaching its
/// successor. A default-constructed id is null. Self-contained.
#pragma once

#include <cstdint>

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

} // namespace snow
