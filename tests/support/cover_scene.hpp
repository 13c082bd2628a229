/// @file cover_scene.hpp
/// @brief Test support: a snowed-on scene with a cover, built in code (a
/// ground mesh smaller than the cover, so its outer ring is void; a sphere; a
/// box with drops at its sides; a declared roof rectangle the cover yields to).
#pragma once

#include "systems/api/simulation_internals.hpp"

#include <memory>
#include <vector>

namespace snow::test {

struct CoverScene {
    std::unique_ptr<Simulation> sim;
    CoverId cover;
    SurfaceId roof;           ///< a declared surface on a box
    float ground_half = 2.0f; ///< the ground mesh spans [-ground_half, ground_half]²
};

inline CoverScene snowed_cover_scene(int ticks) {
    SimConfig c;
    c.seed = 11;
    c.bounds = {{-3.0f, -1.0f, -3.0f}, {3.0f, 5.0f, 3.0f}};
    c.max_flakes = 30000;
    CoverScene s;
    s.sim = std::make_unique<Simulation>(c);
    Simulation& sim = *s.sim;
    const float g = s.ground_half;
    sim.add_mesh_collider(
        {{-g, 0.0f, -g}, {g, 0.0f, -g}, {g, 0.0f, g}, {-g, 0.0f, -g}, {g, 0.0f, g}, {-g, 0.0f, g}});
    sim.add_sphere({-0.8f, 0.6f, -0.8f}, 0.5f);
    sim.add_box({{0.4f, 0.0f, 0.4f}, {1.2f, 0.6f, 1.2f}});
    const ColliderId shed = sim.add_box({{-1.4f, 0.0f, 0.6f}, {-0.6f, 0.8f, 1.4f}});
    SurfaceDef roof;
    roof.x0 = -1.4f;
    roof.z0 = 0.6f;
    roof.size_x = roof.size_z = 0.8f;
    roof.cell = 0.1f;
    roof.base_y = 0.8f;
    s.roof = sim.add_surface(roof, shed);
    CoverDef d;
    d.min_x = d.min_z = -2.5f;
    d.max_x = d.max_z = 2.5f;
    d.cell = 0.05f;
    s.cover = sim.add_cover(d);
    Emitter e;
    e.rate = 6000.0f;
    sim.add_emitter(e);
    sim.run(static_cast<std::uint64_t>(ticks));
    return s;
}

} // namespace snow::test
