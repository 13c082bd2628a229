/// @file fuzz_units.hpp
/// @brief What one fuzz unit does and what it must get right, shared by the
/// fuzz targets (fuzz/*.cpp) and the test that replays their findings
/// (tests/game/scene/test_fuzz_findings.cpp).
#pragma once

#include "tests/scenes/sample_scenes.hpp"
#include <snow/scene.hpp>

#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <string_view>

namespace snow::fuzz {

/// The scene targets' host budget: a village's worth of work, so a unit that
/// declares all of it still runs in under 2 s under ASan and the fuzzer
/// spends its time on variety (docs/reliability.md "Bounded work"). Of the
/// shipped scenes, minimal and village fit; village_effects (a field of
/// 65536 cells) and park (a cover of 230400 cells) are refused.
inline WorkBudget budget() {
    WorkBudget b;
    b.snow_cells = 1u << 17;
    b.surfaces = 64;
    b.collider_triangles = 1u << 14;
    b.bodies = 8;
    b.flakes = 1u << 16;
    b.field_cells = 1u << 14;
    b.field_cell_sweeps = 1u << 17;
    b.occlusion_texels = 1u << 16;
    return b;
}

/// Loads `bytes` as a scene within budget() and ticks it twice. Empty when
/// the scene loaded and stayed balanced and finite, or was refused with an
/// error; otherwise what went wrong.
inline std::string scene_unit(std::string_view bytes) {
    SceneOverrides host;
    host.budget = budget();
    SceneLoadResult scene = load_scene_memory(bytes, "fuzz", host);
    if (!scene.sim) {
        return scene.error.empty() ? "refused without an error" : "";
    }
    scene.sim->tick();
    scene.sim->tick();
    if (!scene.sim->mass().balanced()) {
        return "mass out of balance after two ticks";
    }
    return scene.sim->nonfinite_count() == 0 ? "" : "non-finite state after two ticks";
}

/// The snapshot target's simulation: the stormy yard (flakes, surfaces, a
/// cover, bodies, a wind field, transport, the sky map) with 64 prefilled
/// flakes, 5 ticks in, so its snapshot stays small.
inline std::unique_ptr<Simulation> snapshot_scene() {
    auto sim = make_stormy_yard(1, nullptr, 64);
    for (int t = 0; t < 5; ++t) {
        sim->tick();
    }
    return sim;
}

/// Restores `bytes` into `sim` and ticks once. Empty when they were restored
/// and the tick stayed balanced and finite, or were refused with the state
/// unchanged; otherwise what went wrong.
inline std::string snapshot_unit(Simulation& sim, std::span<const std::byte> bytes) {
    const std::uint64_t before = sim.state_hash();
    try {
        sim.load_bytes(bytes);
    } catch (const SimulationError&) {
        return sim.state_hash() == before ? "" : "a refused snapshot changed the state";
    }
    sim.tick();
    if (!sim.mass().balanced()) {
        return "mass out of balance after restoring";
    }
    return sim.nonfinite_count() == 0 ? "" : "non-finite state after restoring";
}

} // namespace snow::fuzz
