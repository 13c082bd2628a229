// Occlusion refresh ([SKY] sky map, issue #8): the cost of one full
// rebuild, which the occlusion system does only when geometry or the wind's
// lean changed. The yard plus a bumpy roof mesh of 2·32² triangles and a
// small shed that moves between two spots, so every iteration rebuilds.
#include "bench_scene.hpp"

#include "systems/api/simulation_internals.hpp"

#include <cmath>
#include <vector>

namespace snow::bench {
namespace {

/// A 32 × 32 quad grid over x, z in [-6, 6], 3 to 4 m high (gentle bumps).
std::vector<glm::vec3> bumpy_roof() {
    constexpr int q = 32;
    auto at = [](int i, int j) {
        const float x = -6.0f + 12.0f * static_cast<float>(i) / q;
        const float z = -6.0f + 12.0f * static_cast<float>(j) / q;
        return glm::vec3{x, 3.5f + 0.5f * std::sin(x) * std::cos(z), z};
    };
    std::vector<glm::vec3> tris;
    for (int j = 0; j < q; ++j) {
        for (int i = 0; i < q; ++i) {
            tris.insert(tris.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            tris.insert(tris.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return tris;
}

void occlusion_refresh(benchmark::State& state) {
    YardOptions o;
    o.emitter_rate = 0.0f;
    auto sim = make_yard(o);
    sim->add_mesh_collider(bumpy_roof());
    OcclusionCamera cam;
    cam.resolution = static_cast<std::uint32_t>(state.range(0));
    sim->set_occlusion(cam);
    const Aabb spots[2] = {{{5.0f, 0.0f, -7.0f}, {6.0f, 1.0f, -6.0f}},
                           {{5.5f, 0.0f, -7.0f}, {6.5f, 1.0f, -6.0f}}};
    const ColliderId shed = sim->add_box(spots[0]);
    World& w = InternalAccess::world(*sim);
    std::uint64_t i = 0;
    for (auto _ : state) {
        sim->move_box(shed, spots[++i % 2]); // geometry changed: the next refresh rebuilds
        occlusion_system(w);
    }
    state.counters["refreshes"] = static_cast<double>(sim->counters().occlusion_refreshes) /
                                  static_cast<double>(state.iterations());
}

} // namespace

BENCHMARK(occlusion_refresh)
    ->Name("BM_OcclusionRefresh")
    ->ArgNames({"resolution"})
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);

} // namespace snow::bench
