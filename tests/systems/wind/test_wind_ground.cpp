// The wind field's ground (issue #30, item 6): the cells at or below a ground
// surface are solid, so the air flows over the terrain and never under or
// through a building; air a closed shell encloses is solid too. Numbers
// against Martinuzzi & Tropea 1993 [MT93]: reattachment about 1.6 h behind a
// surface-mounted cube (docs/references.md, docs/wind_field.md).
#include "systems/api/simulation_internals.hpp"
#include "systems/wind/wind_field_solver.hpp"
#include "tests/scenes/ground_wind.hpp"
#include "tests/support/rect_surface.hpp"
#include "tests/support/steady_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace snow {
namespace {

const WindField& field(const Simulation& sim) {
    return world_of(sim).resource<WindField>();
}

const GroundCubeWake& box_wake() {
    static const GroundCubeWake w = ground_cube_wake(CubeShape::box);
    return w;
}

bool solid_at(const Simulation& sim, float x, float y, float z) {
    const WindField& f = field(sim);
    const auto cell = [&](int a, float v) {
        return static_cast<std::int32_t>((v - f.origin[a]) * f.inv_cell[a]) + 1;
    };
    const auto& s = world_of(sim).resource<WindFieldSolver>();
    return s.solid[static_cast<std::size_t>(f.centre.index(cell(0, x), cell(1, y), cell(2, z)))] !=
           0;
}

TEST(WindGround, CellsAtOrBelowASlopedGroundAreSolid) {
    // 1 m cells up; a ground over x in [0, 8] rising 0.25 m per m from
    // y = 1 at x = 0; the bounds floor at 0, bare of ground for x < 0.
    SimConfig cfg;
    cfg.bounds = {{-8.0f, 0.0f, -4.0f}, {8.0f, 8.0f, 4.0f}};
    Simulation sim(cfg);
    test::blow_steadily_through_field(sim, 2.0f, {16, 8, 8, 1});
    sim.tick();
    EXPECT_FALSE(solid_at(sim, 0.5f, 0.5f, 0.5f)); // no ground yet
    SurfaceDef ground;
    ground.x0 = 0.0f;
    ground.z0 = -4.0f;
    ground.size_x = ground.size_z = 8.0f;
    ground.cell = 0.5f;
    ground.base_y = 1.0f;
    ground.slope_x = 0.25f;
    ground.spills = false;
    sim.add_surface(ground);
    sim.tick(); // a new surface re-marks the cells
    for (float x = 0.5f; x < 8.0f; x += 1.0f) {
        // The bare top of the ground cell under the column's centre, rounded
        // to a cell face.
        const float centre = std::floor(x / ground.cell) * ground.cell + 0.5f * ground.cell;
        const float top = std::floor(1.0f + 0.25f * centre + 0.5f);
        for (float y = 0.5f; y < 8.0f; y += 1.0f) {
            EXPECT_EQ(solid_at(sim, x, y, 0.5f), y < top) << "x " << x << " y " << y;
        }
    }
    EXPECT_FALSE(solid_at(sim, -0.5f, 0.5f, 0.5f)); // off the ground: the floor is the floor
}

TEST(WindGround, ADriftRaisesTheGroundTheAirFlowsOver) {
    // 1 m cells up over a flat ground at y = 1; 1.6 m of snow on its cells
    // under x in [2, 4): their columns fill up to the snow top (2.6, rounded
    // to the face at 3) before the next step, the others stay at 1.
    SimConfig cfg;
    cfg.bounds = {{-8.0f, 0.0f, -4.0f}, {8.0f, 8.0f, 4.0f}};
    Simulation sim(cfg);
    test::blow_steadily_through_field(sim, 2.0f, {16, 8, 8, 1});
    const SurfaceId id =
        sim.add_surface(test::rect_surface(-8.0f, -4.0f, 16.0f, 8.0f, 1.0f, false));
    sim.tick();
    EXPECT_FALSE(solid_at(sim, 2.5f, 1.5f, 0.5f));
    const SnowSurface& s = snow_surface(sim, id);
    const auto units = static_cast<std::uint32_t>(std::lround(1.6 / s.unit_height));
    for (std::uint32_t iz = 0; iz < s.nz; ++iz) {
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            const float x = s.x0 + (static_cast<float>(ix) + 0.5f) * s.cell;
            if (x >= 2.0f && x < 4.0f) {
                sim.add_settled_snow(id, ix, iz, units);
            }
        }
    }
    sim.tick();
    for (const float x : {2.5f, 3.5f}) {
        EXPECT_TRUE(solid_at(sim, x, 1.5f, 0.5f)) << x;
        EXPECT_TRUE(solid_at(sim, x, 2.5f, 0.5f)) << x;
        EXPECT_FALSE(solid_at(sim, x, 3.5f, 0.5f)) << x;
    }
    EXPECT_FALSE(solid_at(sim, 1.5f, 1.5f, 0.5f)) << "bare ground beside it";
    EXPECT_TRUE(sim.mass().balanced());
}

TEST(WindGround, OpenGroundAboveTheFloorKeepsTheFreeStreamDownToItsTop) {
    // The ground is a wall the air slides along, as the floor is: read just
    // above it, the wind is the free stream (no slowdown without a law).
    SimConfig cfg;
    cfg.bounds = {{-6.0f, -0.5f, -6.0f}, {18.0f, 7.5f, 6.0f}};
    Simulation sim(cfg);
    SurfaceDef ground = test::rect_surface(-6.0f, -6.0f, 24.0f, 12.0f, 0.0f, false);
    ground.cell = 0.25f;
    sim.add_surface(ground);
    test::blow_steadily_through_field(sim, 2.0f, {48, 16, 24, 4});
    sim.run(600);
    float worst = 0.0f;
    for (float x = -5.5f; x < 18.0f; x += 1.0f) {
        for (const float y : {0.01f, 0.1f, 0.25f, 1.0f, 4.0f}) {
            for (float z = -5.5f; z < 6.0f; z += 1.0f) {
                const glm::vec3 v = field(sim).at(x, y, z);
                worst = std::max({worst, std::abs(v.x - 2.0f), std::abs(v.y), std::abs(v.z)});
            }
        }
    }
    EXPECT_LT(worst, 1e-4f);
}

TEST(WindGround, NoWindInsideAClosedBoxOnTheGround) {
    // Before the ground, air blew under the box in the bounds' lowest layer.
    EXPECT_LE(box_wake().inside_over_free, 0.05);
    RecordProperty("inside_over_free", std::to_string(box_wake().inside_over_free));
}

TEST(WindGround, NoWindInsideAClosedMeshBuildingOnTheGround) {
    // The shell's inside is air no open side reaches: solid.
    const GroundCubeWake w = ground_cube_wake(CubeShape::mesh, 4.0, 2.0);
    EXPECT_LE(w.inside_over_free, 0.05);
    RecordProperty("inside_over_free", std::to_string(w.inside_over_free));
}

TEST(WindGround, ReversedAirBehindASurfaceMountedCubeReattachesAt1_2To2Heights) {
    // [MT93]: reattachment at about 1.6 h; the air turns back right behind
    // the lee face (within half a height, past the corner vortex at its foot).
    const GroundCubeWake& w = box_wake();
    ASSERT_GE(w.reversal_over_h, 0.0) << "no reversed air behind the cube";
    EXPECT_LT(w.reversal_over_h, 0.5);
    ASSERT_GE(w.reattachment_over_h, 0.0) << "no reattachment within 5 h";
    EXPECT_GE(w.reattachment_over_h, 1.2);
    EXPECT_LE(w.reattachment_over_h, 2.0);
    RecordProperty("reattachment_over_h", std::to_string(w.reattachment_over_h));
}

} // namespace
} // namespace snow
