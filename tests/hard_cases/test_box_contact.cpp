// Hard case 7: flakes that start exactly on a box's faces, edges and corners
// (the coordinates of the box itself, where every "inside" test is a tie),
// at rest, falling, moving into the box, out of it, or along it. No flake may
// ever be strictly inside the box after a tick, nothing may become NaN, the
// mass stays exact, and in the end every flake has landed or been removed.
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"

#include <string>
#include <vector>

namespace snow {
namespace {

/// A raised box (a table top): its bottom face is in the air, so flakes on it can fall.
constexpr Aabb box{{-1.0f, 0.5f, -1.0f}, {1.0f, 2.0f, 1.0f}};

/// Inside the open box (a point on its boundary is not).
bool strictly_inside(const glm::vec3& p) {
    return p.x > box.min.x && p.x < box.max.x && p.y > box.min.y && p.y < box.max.y &&
           p.z > box.min.z && p.z < box.max.z;
}

/// Points exactly on the box: its 26 face centres, edge midpoints and corners,
/// plus off-centre points on each face.
std::vector<glm::vec3> boundary_points() {
    std::vector<glm::vec3> pts;
    const glm::vec3 lo = box.min, hi = box.max;
    const glm::vec3 mid = 0.5f * (lo + hi);
    for (int sx = -1; sx <= 1; ++sx) {
        for (int sy = -1; sy <= 1; ++sy) {
            for (int sz = -1; sz <= 1; ++sz) {
                if (sx == 0 && sy == 0 && sz == 0) {
                    continue;
                }
                auto pick = [](int s, float l, float m, float h) {
                    return s < 0 ? l : s > 0 ? h : m;
                };
                pts.push_back({pick(sx, lo.x, mid.x, hi.x), pick(sy, lo.y, mid.y, hi.y),
                               pick(sz, lo.z, mid.z, hi.z)});
            }
        }
    }
    const float u = 0.37f, v = -0.61f;
    pts.push_back({u, hi.y, v}); // top
    pts.push_back({u, lo.y, v}); // bottom
    pts.push_back({lo.x, 1.1f, v});
    pts.push_back({hi.x, 1.9f, u});
    pts.push_back({u, 0.6f, lo.z});
    pts.push_back({v, 1.3f, hi.z});
    return pts;
}

/// Outward direction of the box at a boundary point (sum of the faces it lies on).
glm::vec3 outward(const glm::vec3& p) {
    glm::vec3 n{0.0f};
    for (int a = 0; a < 3; ++a) {
        n[a] = p[a] == box.min[a] ? -1.0f : p[a] == box.max[a] ? 1.0f : 0.0f;
    }
    return n;
}

TEST(HardCaseBoxContact, FlakesBornOnFacesEdgesAndCornersNeverEndInside) {
    for (const Integrator integ : {Integrator::explicit_euler, Integrator::exponential}) {
        SCOPED_TRACE(integrator_name(integ));
        SimConfig cfg;
        cfg.seed = 7;
        cfg.integrator = integ;
        cfg.bounds = {{-4.0f, -0.5f, -4.0f}, {4.0f, 4.0f, 4.0f}};
        cfg.max_flakes = 1024;
        Simulation sim(cfg);
        SurfaceDef g;
        g.x0 = g.z0 = -4.0f;
        g.size_x = g.size_z = 8.0f;
        g.cell = 0.1f;
        g.spills = false;
        const SurfaceId ground = sim.add_surface(g);
        const ColliderId solid = sim.add_box(box);
        SurfaceDef r;
        r.x0 = box.min.x;
        r.z0 = box.min.z;
        r.size_x = r.size_z = 2.0f;
        r.cell = 0.1f;
        r.base_y = box.max.y;
        r.spills = false;
        const SurfaceId roof = sim.add_surface(r, solid);

        std::uint32_t placed = 0;
        // The roof covers [min, max) on x and z, like every grid: the top's
        // max-x and max-z edges are bare geometry, where a landing is removed.
        std::uint64_t bare_edge_units = 0;
        for (const glm::vec3& p : boundary_points()) {
            const glm::vec3 n = outward(p);
            const bool bare_edge = p.y == box.max.y && (p.x == box.max.x || p.z == box.max.z);
            for (const glm::vec3 v : {glm::vec3{0.0f}, glm::vec3{0.0f, -1.0f, 0.0f}, -2.0f * n,
                                      2.0f * n, glm::vec3{1.0f, 0.0f, 0.5f}, -30.0f * n}) {
                const std::uint32_t units = 1 + placed % 5;
                hard::place_flake(sim, p, v, 9.81f, units);
                bare_edge_units += bare_edge ? units : 0;
                ++placed;
            }
        }
        const FlakePool& f = flake_pool(sim);
        for (int t = 0; t < 600; ++t) {
            sim.tick();
            ASSERT_TRUE(hard::healthy(sim));
            for (std::uint32_t i = 0; i < f.slot_end; ++i) {
                ASSERT_FALSE(f.is_alive(i) && strictly_inside({f.px[i], f.py[i], f.pz[i]}))
                    << "slot " << i << " inside the box at tick " << t << ": (" << f.px[i] << ", "
                    << f.py[i] << ", " << f.pz[i] << ")";
            }
        }
        EXPECT_EQ(f.alive, 0u) << "flakes still in the air (stuck on a face?)";
        const auto& ledger = world_of(sim).resource<MassLedger>();
        const std::uint64_t roof_units = hard::cell_stats(hard::surface(sim, roof)).sum;
        const std::uint64_t ground_units = hard::cell_stats(hard::surface(sim, ground)).sum;
        EXPECT_GT(roof_units, 0u);
        EXPECT_GT(ground_units, 0u);
        EXPECT_EQ(ledger.removed_bounds, 0u);
        EXPECT_LE(ledger.removed_bare, bare_edge_units);
        const std::string name(integrator_name(integ));
        RecordProperty(name + "_roof_units", std::to_string(roof_units));
        RecordProperty(name + "_ground_units", std::to_string(ground_units));
        RecordProperty(name + "_bare_units", std::to_string(ledger.removed_bare));
    }
}

} // namespace
} // namespace snow
