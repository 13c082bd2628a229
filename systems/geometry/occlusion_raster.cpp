// occlusion_raster: triangles, boxes, spheres and surface tops into the sky
// map of [SKY], in double precision, texel centres sampled.
#include "systems/geometry/occlusion_raster.hpp"

#include "systems/geometry/colliders.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace snow {

namespace {

/// Texels whose centres (i + 0.5) lie in [lo, hi], clamped to [0, n); false if none.
bool texel_range(double lo, double hi, std::uint32_t n, std::uint32_t& first, std::uint32_t& last) {
    const double a = std::max(std::ceil(lo - 0.5), 0.0);
    const double b = std::min(std::floor(hi - 0.5), static_cast<double>(n) - 1.0);
    if (!(a <= b)) {
        return false;
    }
    first = static_cast<std::uint32_t>(a);
    last = static_cast<std::uint32_t>(b);
    return true;
}

} // namespace

Rasteriser::Rasteriser(OcclusionMap& m)
    : m_(m), inv_texel_(1.0 / m.texel), sx_(m.shear_x), sz_(m.shear_z) {}

void Rasteriser::project(const glm::vec3& p, double& u, double& v) const {
    u = (static_cast<double>(p.x) + sx_ * p.y - m_.x0) * inv_texel_;
    v = (static_cast<double>(p.z) + sz_ * p.y - m_.z0) * inv_texel_;
}

void Rasteriser::plot(std::size_t t, float y, std::uint32_t id) {
    if (y > m_.top_y[t]) {
        m_.top_y[t] = y;
        m_.top_id[t] = id;
    }
}

void Rasteriser::triangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
                          std::uint32_t id) {
    double ua = 0, va = 0, ub = 0, vb = 0, uc = 0, vc = 0;
    project(a, ua, va);
    project(b, ub, vb);
    project(c, uc, vc);
    const double area = (ub - ua) * (vc - va) - (uc - ua) * (vb - va);
    if (!(std::fabs(area) > 1e-12)) {
        return; // seen edge-on (a wall under a vertical view)
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

void Rasteriser::box(const Aabb& b, std::uint32_t id) {
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

void Rasteriser::sphere(const glm::vec3& c, float r, std::uint32_t id) {
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

void Rasteriser::surface(const SnowSurface& s, std::uint32_t id) {
    const std::array<glm::vec3, 4> q = surface_base_corners(s);
    triangle(q[0], q[1], q[2], id);
    triangle(q[0], q[2], q[3], id);
}

void rasterise_geometry(const World& w, OcclusionMap& m, bool (*skip)(const World&, Entity)) {
    const std::size_t texels = static_cast<std::size_t>(m.width) * m.height;
    m.top_y.assign(texels, -std::numeric_limits<float>::infinity());
    m.top_id.assign(texels, 0);
    Rasteriser r(m);
    w.each<BoxCollider>([&](Entity e, const BoxCollider& b) { r.box(b.box, e.bits); });
    w.each<SphereCollider>(
        [&](Entity e, const SphereCollider& s) { r.sphere(s.center, s.radius, e.bits); });
    w.each<MeshCollider>([&](Entity e, const MeshCollider& mesh) {
        for (std::size_t i = 0; i + 2 < mesh.triangles.size(); i += 3) {
            r.triangle(mesh.triangles[i], mesh.triangles[i + 1], mesh.triangles[i + 2], e.bits);
        }
    });
    w.each<SnowSurface>([&](Entity e, const SnowSurface& s) {
        if (skip(w, e)) {
            return;
        }
        const auto* of = w.try_get<SurfaceOf>(e);
        r.surface(s, of != nullptr && !of->owner.is_null() ? of->owner.bits : e.bits);
    });
}

} // namespace snow
