/// @file occlusion_raster.hpp
/// @brief The CPU rasteriser of the occlusion ("sky") map of [SKY]: per
/// texel the highest geometry along the (possibly tilted) projection and the
/// entity it belongs to. The occlusion system and the snow cover
/// (snow_cover.hpp) both draw through it.
#pragma once

#include "ecs/world.hpp"
#include "systems/geometry/geometry.hpp"
#include "systems/sky/occlusion_map.hpp"
#include "systems/snowpack/snow_surface.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>

namespace snow {

/// Writes geometry into a map whose layout (origin, texel, size, shear) is
/// set and whose texels are cleared: a texel keeps the highest y seen (the
/// first writer wins ties).
class Rasteriser {
  public:
    explicit Rasteriser(OcclusionMap& m);

    /// Texel centres inside the projected triangle get its interpolated height.
    void triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, std::uint32_t id);
    /// All six faces, so a tilted view also sees the windward wall.
    void box(const Aabb& b, std::uint32_t id);
    /// Exact: the highest point where each texel's ray meets the sphere.
    void sphere(const glm::vec3& c, float r, std::uint32_t id);
    /// A surface's bare top as two triangles (its snow is not geometry).
    void surface(const SnowSurface& s, std::uint32_t id);

  private:
    /// Texel-space coordinates of a world point along the projection.
    void project(const glm::vec3& p, double& u, double& v) const;
    void plot(std::size_t t, float y, std::uint32_t id);

    OcclusionMap& m_;
    double inv_texel_;
    double sx_, sz_;
};

/// Rasterises every collider of the world, then every declared surface's bare
/// top (a surface on a solid speaks for that solid, so collision sees the
/// owner; the ground speaks for itself). Colliders are drawn first, so they
/// keep their ids on ties. Surfaces for which `skip` holds are left out (the
/// callers skip covers: a cover is snow over the geometry, not geometry).
/// Lays the texels out anew for the map's width × height first (-inf / id 0
/// where nothing is).
void rasterise_geometry(const World& w, OcclusionMap& m, bool (*skip)(const World&, Entity));

} // namespace snow
