#include "tests/scenes/ground_wind.hpp"

#include "systems/api/simulation_internals.hpp"
#include "systems/wind/wind_field.hpp"
#include "tests/support/steady_field.hpp"

#include <cmath>
#include <vector>

namespace snow {

namespace {

constexpr float free_stream = 2.0f; // m/s along +x
constexpr float h = 2.0f;           // the cube's edge (m)
constexpr float cell = 0.25f;       // the field's horizontal cell edge (m)

/// The 12 triangles of the closed surface of box b.
std::vector<glm::vec3> shell(const Aabb& b) {
    const auto corner = [&](int i) {
        return glm::vec3{(i & 1) != 0 ? b.max.x : b.min.x, (i & 2) != 0 ? b.max.y : b.min.y,
                         (i & 4) != 0 ? b.max.z : b.min.z};
    };
    // Each face as 4 corners (bit 1: x, 2: y, 4: z) around it.
    const int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                             {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    std::vector<glm::vec3> t;
    for (const auto& q : faces) {
        for (const int i : {q[0], q[1], q[2], q[0], q[2], q[3]}) {
            t.push_back(corner(i));
        }
    }
    return t;
}

} // namespace

GroundCubeWake ground_cube_wake(CubeShape shape, double spin_up_s, double mean_s) {
    // 24 × 8 × 12 m over a ground at y = 0, the bounds floor 0.5 m under it;
    // 96 × 16 × 48 cells (0.25 × 0.5 × 0.25 m), the cube 6 m from the inflow.
    SimConfig cfg;
    cfg.bounds = {{-6.0f, -0.5f, -6.0f}, {18.0f, 7.5f, 6.0f}};
    Simulation sim(cfg);
    SurfaceDef ground;
    ground.x0 = cfg.bounds.min.x;
    ground.z0 = cfg.bounds.min.z;
    ground.size_x = cfg.bounds.size().x;
    ground.size_z = cfg.bounds.size().z;
    ground.cell = cell;
    ground.spills = false;
    sim.add_surface(ground);
    const Aabb cube{{0.0f, 0.0f, -0.5f * h}, {h, h, 0.5f * h}};
    if (shape == CubeShape::box) {
        sim.add_box(cube);
    } else {
        sim.add_mesh_collider(shell(cube));
    }
    const test::FieldGrid grid{96, 16, 48, 4};
    test::blow_steadily_through_field(sim, free_stream, grid);

    std::vector<glm::vec3> inside, line;
    for (float x = cube.min.x + 0.5f * cell; x < cube.max.x; x += cell) {
        for (float z = cube.min.z + 0.5f * cell; z < cube.max.z; z += cell) {
            inside.push_back({x, 0.1f, z});
            inside.push_back({x, 0.25f, z});
        }
    }
    for (float x = cube.max.x + 0.5f * cell; x < cube.max.x + 5.0f * h; x += cell) {
        line.push_back({x, 0.25f, 0.0f});
    }
    const auto ticks = [&](double seconds) {
        return static_cast<int>(std::lround(seconds / static_cast<double>(cfg.dt)));
    };
    sim.run(ticks(spin_up_s));
    const WindField& f = world_of(sim).resource<WindField>();
    const int every = static_cast<int>(grid.update_every);
    const int samples = ticks(mean_s) / every;
    double inside_speed = 0.0;
    std::vector<double> line_u(line.size(), 0.0);
    for (int s = 0; s < samples; ++s) {
        sim.run(every);
        for (const glm::vec3& p : inside) {
            const glm::vec3 v = f.at(p.x, p.y, p.z);
            inside_speed += std::sqrt(static_cast<double>(v.x * v.x + v.z * v.z));
        }
        for (std::size_t i = 0; i < line.size(); ++i) {
            line_u[i] += static_cast<double>(f.at(line[i].x, line[i].y, line[i].z).x);
        }
    }
    GroundCubeWake w;
    w.inside_over_free = inside_speed / (static_cast<double>(samples) *
                                         static_cast<double>(inside.size()) * free_stream);
    std::size_t i = 0;
    while (i < line.size() && line_u[i] >= 0.0) {
        ++i;
    }
    if (i < line.size()) {
        w.reversal_over_h = (line[i].x - cube.max.x) / h;
    }
    while (i < line.size() && line_u[i] < 0.0) {
        ++i;
    }
    if (i < line.size()) {
        w.reattachment_over_h = (line[i].x - cube.max.x) / h;
    }
    return w;
}

} // namespace snow
