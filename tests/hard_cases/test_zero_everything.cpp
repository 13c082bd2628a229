// Hard case 9: nothing to do. No emitter (zero flakes), a wind resource whose
// base and walk are zero, and zero gravity. 1000 ticks must stay finite and
// exact; flakes placed at rest in still, weightless air must not move at all
// and nothing may land (g/c = 0: the terminal velocity is exactly zero),
// bit for bit, with every integrator.
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"
#include "tests/support/find_flake.hpp"

#include <vector>

namespace snow {
namespace {

struct EmptyScene {
    std::unique_ptr<Simulation> sim;
    SurfaceId ground, roof;
};

/// Ground and a roofed box; zero gravity, still wind (base 0, walk 0), no emitter.
EmptyScene empty_scene(Integrator integ) {
    SimConfig cfg;
    cfg.seed = 9;
    cfg.integrator = integ;
    cfg.gravity = {0.0f, 0.0f, 0.0f};
    cfg.bounds = {{-4.0f, -0.5f, -4.0f}, {4.0f, 4.0f, 4.0f}};
    cfg.max_flakes = 64;
    EmptyScene s{std::make_unique<Simulation>(cfg), {}, {}};
    SurfaceDef g;
    g.x0 = g.z0 = -4.0f;
    g.size_x = g.size_z = 8.0f;
    g.cell = 0.1f;
    g.spills = false;
    s.ground = s.sim->add_surface(g);
    const ColliderId box = s.sim->add_box({{-1.0f, 0.0f, -1.0f}, {1.0f, 1.0f, 1.0f}});
    SurfaceDef r;
    r.x0 = r.z0 = -1.0f;
    r.size_x = r.size_z = 2.0f;
    r.cell = 0.1f;
    r.base_y = 1.0f;
    s.roof = s.sim->add_surface(r, box);
    Wind w;
    w.base = w.current = glm::vec3{0.0f};
    w.walk = 0.0f;
    s.sim->set_wind(w);
    return s;
}

constexpr Integrator all_integrators[] = {Integrator::explicit_euler,
                                          Integrator::semi_implicit_euler, Integrator::exponential,
                                          Integrator::rk4, Integrator::automatic};

TEST(HardCaseNothing, NoFlakesNoWindNoGravityThousandTicks) {
    for (const Integrator integ : all_integrators) {
        SCOPED_TRACE(integrator_name(integ));
        EmptyScene s = empty_scene(integ);
        const std::uint64_t start = s.sim->state_hash();
        for (int t = 0; t < 1000; ++t) {
            s.sim->tick();
            ASSERT_TRUE(hard::healthy(*s.sim));
        }
        const MassReport m = s.sim->mass();
        EXPECT_EQ(m.spawned, 0u);
        EXPECT_EQ(m.settled, 0u);
        EXPECT_EQ(flake_pool(*s.sim).alive, 0u);
        const Wind& w = world_of(*s.sim).resource<Wind>();
        EXPECT_EQ(w.current, glm::vec3(0.0f)); // walk 0: the deviation never leaves zero
        EXPECT_NE(s.sim->state_hash(), start); // only the clock moved...
        EXPECT_EQ(s.sim->tick_count(), 1000u);
        // ... and the systems that need flakes never ran (docs/design.md "What is declared runs").
        for (const auto& sys : schedule_of(*s.sim).stats()) {
            if (sys.name == "spawn" || sys.name == "flakes") {
                EXPECT_EQ(sys.calls, 0u) << sys.name;
            }
        }
    }
}

TEST(HardCaseNothing, FlakesAtRestInWeightlessStillAirNeverMoveOrLand) {
    for (const Integrator integ : all_integrators) {
        SCOPED_TRACE(integrator_name(integ));
        EmptyScene s = empty_scene(integ);
        // Above the roof, 5 mm above it (outside deposit's 1 mm contact
        // tolerance), 1 cm above the ground, beside the box.
        const std::vector<glm::vec3> at = {
            {0.0f, 2.0f, 0.0f}, {0.5f, 1.005f, 0.5f}, {3.0f, 0.01f, 3.0f}, {-2.0f, 0.5f, 0.0f}};
        for (const glm::vec3& p : at) {
            hard::place_flake(*s.sim, p, glm::vec3{0.0f}, 9.81f, 10);
        }
        for (int t = 0; t < 1000; ++t) {
            s.sim->tick();
            ASSERT_TRUE(hard::healthy(*s.sim));
        }
        const FlakePool& f = flake_pool(*s.sim);
        EXPECT_EQ(f.alive, at.size());
        EXPECT_EQ(s.sim->mass().settled, 0u);
        for (std::uint32_t id = 0; id < at.size(); ++id) { // placed first: ids 0, 1, ...
            const auto s = test::slot_of(f, id);
            ASSERT_TRUE(s) << "flake " << id;
            const std::uint32_t i = *s;
            EXPECT_EQ(glm::vec3(f.px[i], f.py[i], f.pz[i]), at[id]) << "flake " << id;
            EXPECT_EQ(glm::vec3(f.vx[i], f.vy[i], f.vz[i]), glm::vec3(0.0f)) << "flake " << id;
        }
        EXPECT_EQ(world_of(*s.sim).resource<MassLedger>().removed(), 0u);
    }
}

} // namespace
} // namespace snow
