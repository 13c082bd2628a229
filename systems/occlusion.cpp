// occlusion: the sky camera of [SKY]. An orthographic depth map from above
// over the bounds' XZ extent, rasterised on the CPU: per texel the highest
// geometry and its entity. With a tilt the rays lean downwind, like the flakes,
// so lee sides get less exposure ([SKY Limitations 2]: wind). Refreshed
// only when the geometry or the quantised wind direction changed.
#include "systems/occlusion.hpp"
#include "systems/colliders.hpp"
#include "systems/sim_config.hpp"
#include "systems/snow_cover.hpp"
#include "systems/snow_surface.hpp"
#include "systems/systems.hpp"
#include "systems/wind.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace snow {

namespace {

constexpr float neg_inf = -std::numeric_limits<float>::infinity();

/// Where and how the map is laid out; a change from the stored one means a refresh.
struct Layout {
    float x0 = 0.0f, z0 = 0.0f, texel = 1.0f;
    std::uint32_t width = 1, height = 1;
    float wind_angle = occlusion_no_lean;
    float shear_x = 0.0f, shear_z = 0.0f;
};

/// Wind direction quantised to occlusion_wind_steps, with hysteresis: the
/// stored direction is kept while the wind stays within 3/4 of a step of it,
/// so a wind wobbling on a step boundary does not refresh every tick.
float quantised_angle(double angle, float previous) {
    constexpr double two_pi = 2.0 * std::numbers::pi;
    const double step = two_pi / occlusion_wind_steps;
    if (previous != occlusion_no_lean) {
        double d = std::fabs(angle - previous);
        d = std::min(d, two_pi - d);
        if (d <= 0.75 * step) {
            return previous;
        }
    }
    const auto k =
        static_cast<std::uint32_t>(std::floor(angle / step + 0.5)) % occlusion_wind_steps;
    return static_cast<float>(k * step);
}

Layout layout_for(const World& w, const OcclusionCamera& cam, const OcclusionMap& previous) {
    Layout l;
    const Aabb& b = w.resource<SimConfig>().bounds;
    const glm::vec3 ext = b.size();
    const std::uint32_t res = std::max<std::uint32_t>(cam.resolution, 1);
    const float longest = std::max(ext.x, ext.z);
    l.x0 = b.min.x;
    l.z0 = b.min.z;
    // `resolution` texels along the longer side; square texels.
    l.texel = longest > 0.0f ? longest / static_cast<float>(res) : 1.0f;
    l.width =
        std::clamp<std::uint32_t>(static_cast<std::uint32_t>(std::ceil(ext.x / l.texel)), 1, res);
    l.height =
        std::clamp<std::uint32_t>(static_cast<std::uint32_t>(std::ceil(ext.z / l.texel)), 1, res);
    const auto* wind = w.try_resource<Wind>();
    if (cam.tilt == 0.0f || wind == nullptr) {
        return l;
    }
    const double wx = wind->current.x, wz = wind->current.z;
    if (!(wx * wx + wz * wz > 1e-12)) {
        return l; // calm (or non-finite): no direction to lean along
    }
    double angle = std::atan2(wz, wx);
    angle = angle < 0.0 ? angle + 2.0 * std::numbers::pi : angle;
    // A map never built has no direction to hold on to.
    const bool built = previous.geometry_version != OcclusionMap{}.geometry_version;
    l.wind_angle = quantised_angle(angle, built ? previous.wind_angle : occlusion_no_lean);
    const double t = std::tan(static_cast<double>(cam.tilt));
    l.shear_x = static_cast<float>(t * std::cos(static_cast<double>(l.wind_angle)));
    l.shear_z = static_cast<float>(t * std::sin(static_cast<double>(l.wind_angle)));
    return l;
}

bool up_to_date(const OcclusionMap& m, const Layout& l, std::uint64_t geometry_version) {
    return m.geometry_version == geometry_version && m.wind_angle == l.wind_angle &&
           m.shear_x == l.shear_x && m.shear_z == l.shear_z && m.x0 == l.x0 && m.z0 == l.z0 &&
           m.texel == l.texel && m.width == l.width && m.height == l.height;
}

/// Writes geometry into the map: a texel keeps the highest y seen (the first
/// writer wins ties, so colliders, drawn first, keep their ids).
class Rasteriser {
  public:
    explicit Rasteriser(OcclusionMap& m)
        : m_(m), inv_texel_(1.0 / m.texel), sx_(m.shear_x), sz_(m.shear_z) {}

    /// Texel-space coordinates of a world point along the projection.
    void project(const glm::vec3& p, double& u, double& v) const {
        u = (static_cast<double>(p.x) + sx_ * p.y - m_.x0) * inv_texel_;
        v = (static_cast<double>(p.z) + sz_ * p.y - m_.z0) * inv_texel_;
    }

    /// Texel centres inside the projected triangle get its interpolated height.
    void triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, std::uint32_t id) {
        double ua = 0, va = 0, ub = 0, vb = 0, uc = 0, vc = 0;
        project(a, ua, va);
        project(b, ub, vb);
        project(c, uc, vc);
        const double area = (ub - ua) * (vc - va) - (uc - ua) * (vb - va);
        if (!(std::fabs(area) > 1e-12)) {
            return; // seen edge-on (a wall under a vertical view), or not finite
        }
        const double inv_area = 1.0 / area;
        std::uint32_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
        if (!texel_range(std::min({ua, ub, uc}), std::max({ua, ub, uc}), m_.width, i0, i1) ||
            !texel_range(std::min({va, vb, vc}), std::max({va, vb, vc}), m_.height, j0, j1)) {
            return;
        }
        constexpr double eps = -1e-9; // texel centres on a shared edge belong to both sides
        for (std::uint32_t j = j0; j <= j1; ++j) {
            const double pv = j + 0.5;
            for (std::uint32_t i = i0; i <= i1; ++i) {
                const double pu = i + 0.5;
                const double wa = ((ub - pu) * (vc - pv) - (uc - pu) * (vb - pv)) * inv_area;
                const double wb = ((uc - pu) * (va - pv) - (ua - pu) * (vc - pv)) * inv_area;
                const double wc = ((ua - pu) * (vb - pv) - (ub - pu) * (va - pv)) * inv_area;
                if (wa >= eps && wb >= eps && wc >= eps) {
                    plot(static_cast<std::size_t>(j) * m_.width + i,
                         static_cast<float>(wa * a.y + wb * b.y + wc * c.y), id);
                }
            }
        }
    }

    /// All six faces, so a tilted view also sees the windward wall.
    void box(const Aabb& b, std::uint32_t id) {
        glm::vec3 corner[8];
        for (int k = 0; k < 8; ++k) {
            corner[k] = {(k & 1) ? b.max.x : b.min.x, (k & 2) ? b.max.y : b.min.y,
                         (k & 4) ? b.max.z : b.min.z};
        }
        // Faces as corner cycles; the top (+y) first.
        static constexpr int faces[6][4] = {{2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5},
                                            {0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}};
        for (const auto& f : faces) {
            triangle(corner[f[0]], corner[f[1]], corner[f[2]], id);
            triangle(corner[f[0]], corner[f[2]], corner[f[3]], id);
        }
    }

    /// Exact: the highest point where each texel's ray meets the sphere.
    void sphere(const glm::vec3& c, float r, std::uint32_t id) {
        // Ray of projected point (pu, pw): (pu − sx·y, y, pw − sz·y). With a, b the
        // projected offsets from the centre: A·y² − 2B·y + C = 0.
        const double A = 1.0 + sx_ * sx_ + sz_ * sz_;
        const double half = r * std::sqrt(A) * inv_texel_;
        double uc = 0, vc = 0;
        project(c, uc, vc);
        std::uint32_t i0 = 0, i1 = 0, j0 = 0, j1 = 0;
        if (!texel_range(uc - half, uc + half, m_.width, i0, i1) ||
            !texel_range(vc - half, vc + half, m_.height, j0, j1)) {
            return;
        }
        const double texel = m_.texel;
        for (std::uint32_t j = j0; j <= j1; ++j) {
            const double b = m_.z0 + (j + 0.5) * texel - c.z;
            for (std::uint32_t i = i0; i <= i1; ++i) {
                const double a = m_.x0 + (i + 0.5) * texel - c.x;
                const double B = a * sx_ + static_cast<double>(c.y) + b * sz_;
                const double C =
                    a * a + static_cast<double>(c.y) * c.y + b * b - static_cast<double>(r) * r;
                const double disc = B * B - A * C;
                if (disc >= 0.0) {
                    plot(static_cast<std::size_t>(j) * m_.width + i,
                         static_cast<float>((B + std::sqrt(disc)) / A), id);
                }
            }
        }
    }

    /// A surface's bare top as two triangles (its snow is not geometry).
    void surface(const SnowSurface& s, std::uint32_t id) {
        glm::vec3 q[4];
        if (surface_base_corners(s, q)) {
            triangle(q[0], q[1], q[2], id);
            triangle(q[0], q[2], q[3], id);
        }
    }

  private:
    /// Texels whose centres (i + 0.5) lie in [lo, hi], clamped to [0, n); false if none.
    static bool texel_range(double lo, double hi, std::uint32_t n, std::uint32_t& first,
                            std::uint32_t& last) {
        const double a = std::max(std::ceil(lo - 0.5), 0.0);
        const double b = std::min(std::floor(hi - 0.5), static_cast<double>(n) - 1.0);
        if (!(a <= b)) {
            return false;
        }
        first = static_cast<std::uint32_t>(a);
        last = static_cast<std::uint32_t>(b);
        return true;
    }

    void plot(std::size_t t, float y, std::uint32_t id) {
        if (y > m_.top_y[t]) {
            m_.top_y[t] = y;
            m_.top_id[t] = id;
        }
    }

    OcclusionMap& m_;
    double inv_texel_;
    double sx_, sz_;
};

bool finite3(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

void rasterise_geometry(const World& w, OcclusionMap& m) {
    Rasteriser r(m);
    w.each<BoxCollider>([&](Entity e, const BoxCollider& b) {
        if (finite3(b.box.min) && finite3(b.box.max)) {
            r.box(b.box, e.bits);
        }
    });
    w.each<SphereCollider>([&](Entity e, const SphereCollider& s) {
        if (finite3(s.center) && std::isfinite(s.radius) && s.radius > 0.0f) {
            r.sphere(s.center, s.radius, e.bits);
        }
    });
    w.each<MeshCollider>([&](Entity e, const MeshCollider& mesh) {
        for (std::size_t i = 0; i + 2 < mesh.triangles.size(); i += 3) {
            r.triangle(mesh.triangles[i], mesh.triangles[i + 1], mesh.triangles[i + 2], e.bits);
        }
    });
    // Surfaces last: a surface on a solid speaks for that solid (its id), so
    // collision sees the owner; the ground speaks for itself. A cover is snow
    // over the geometry, not geometry.
    w.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        if (w.has<SnowCover>(e)) {
            return;
        }
        const auto* of = w.try_get<SurfaceOf>(e);
        r.surface(s, of != nullptr && !of->owner.is_null() ? of->owner.bits : e.bits);
    });
}

bool surface_base_corners(const SnowSurface& s, glm::vec3 (&corners)[4]) {
    if (s.nx == 0 || s.nz == 0 || s.base_level.size() < static_cast<std::size_t>(s.nx) * s.nz) {
        return false;
    }
    // Plane through the corner cells' centres, extended to the grid's edges.
    const auto base = [&](std::uint32_t ix, std::uint32_t iz) {
        return static_cast<double>(s.base_level[s.index(ix, iz)]) * s.unit_height;
    };
    const double cell = s.cell;
    const double h00 = base(0, 0);
    const double gx = s.nx > 1 ? (base(s.nx - 1, 0) - h00) / ((s.nx - 1) * cell) : 0.0;
    const double gz = s.nz > 1 ? (base(0, s.nz - 1) - h00) / ((s.nz - 1) * cell) : 0.0;
    const double x0 = s.x0, z0 = s.z0, x1 = x0 + s.nx * cell, z1 = z0 + s.nz * cell;
    const auto at = [&](double x, double z) {
        const double y = h00 + (x - x0 - 0.5 * cell) * gx + (z - z0 - 0.5 * cell) * gz;
        return glm::vec3{static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)};
    };
    corners[0] = at(x0, z0);
    corners[1] = at(x1, z0);
    corners[2] = at(x1, z1);
    corners[3] = at(x0, z1);
    return true;
}

float occlusion_exposure(const OcclusionMap& map, float x, float y, float z, float tolerance) {
    std::uint32_t i = 0, j = 0;
    if (!occlusion_texel(map, x, y, z, i, j)) {
        return 1.0f; // nothing known above a point outside the map
    }
    return y >= map.top_y[static_cast<std::size_t>(j) * map.width + i] - tolerance ? 1.0f : 0.0f;
}

void surface_exposure(const OcclusionMap& map, const SnowSurface& s, std::vector<float>& out,
                      float tolerance) {
    out.resize(s.cell_count());
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const std::size_t i = s.index(ix, iz);
            const float x = s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell;
            const float z = s.z0 + (static_cast<float>(iz) + 0.5f) * s.cell;
            out[i] = occlusion_exposure(map, x, s.top_y(i), z, tolerance);
        }
    }
}

void occlusion_system(World& w) {
    const auto* cam = w.try_resource<OcclusionCamera>();
    if (cam == nullptr) {
        return;
    }
    auto* map = w.try_resource<OcclusionMap>();
    if (map == nullptr) {
        map = &w.set_resource<OcclusionMap>();
    }
    const auto* gv = w.try_resource<GeometryVersion>();
    const std::uint64_t version = gv != nullptr ? gv->version : 0;
    const Layout l = layout_for(w, *cam, *map);
    if (up_to_date(*map, l, version)) {
        return;
    }
    map->x0 = l.x0;
    map->z0 = l.z0;
    map->texel = l.texel;
    map->width = l.width;
    map->height = l.height;
    map->wind_angle = l.wind_angle;
    map->shear_x = l.shear_x;
    map->shear_z = l.shear_z;
    const std::size_t texels = static_cast<std::size_t>(l.width) * l.height;
    map->top_y.assign(texels, neg_inf);
    map->top_id.assign(texels, 0);
    rasterise_geometry(w, *map);
    map->geometry_version = version;
    ++map->version;
    if (auto* counters = w.try_resource<SimCounters>()) {
        ++counters->occlusion_refreshes;
    }
}

} // namespace snow
