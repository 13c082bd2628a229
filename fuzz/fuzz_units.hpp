/// @file fuzz_units.hpp
/// @brief What one fuzz unit does and what it must get right, shared by the
/// fuzz targets (fuzz/*.cpp) and the test that replays their findings
/// (tests/game/scene/test_fuzz_findings.cpp).
#pragma once

#include "systems/api/snapshot_layout.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include <snow/scene.hpp>

#include <cstddef>
#include <cstring>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

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

/// The snapshot target's simulation: the yard with every kind of state at
/// its smallest (flakes aloft and landing, surfaces, a cover, a snowball and
/// a walker, a tilted sky map, a wind field that moves snow, gusts), 5 ticks
/// in, so that its snapshot stays small (under 50 KB) and units run fast.
inline std::unique_ptr<Simulation> snapshot_scene() {
    YardOptions o;
    o.ground_cells = 16;
    o.max_flakes = 512;
    o.prefill = 64;
    o.emitter_rate = 600.0f;
    auto sim = make_yard(o);
    Wind wind;
    wind.base = wind.current = {2.0f, 0.0f, 0.5f};
    wind.gust_strength = 3.0f;
    wind.gust_rate = 0.8f;
    sim->set_wind(wind);
    sim->add_mesh_collider({{3.0f, 1.0f, -6.0f}, {6.0f, 1.5f, -6.0f}, {4.5f, 2.5f, -3.0f}});
    OcclusionCamera cam;
    cam.resolution = 16;
    cam.tilt = 0.5f;
    sim->set_occlusion(cam);
    CoverDef cover;
    cover.min_x = 3.0f;
    cover.min_z = 3.5f;
    cover.max_x = 4.0f;
    cover.max_z = 4.5f;
    sim->add_cover(cover);
    BodyDef ball;
    ball.radius = 0.3f;
    ball.position = {-6.0f, 0.2f, -6.0f};
    ball.snowball = true;
    ball.motion = BodyMotion{{{-6.0f, 0.2f, -6.0f}, {-2.0f, 0.2f, -6.0f}}, 1.5f, true};
    sim->add_body(ball);
    BodyDef walker;
    walker.shape = BodyShape::capsule;
    walker.radius = 0.25f;
    walker.half_height = 0.6f;
    walker.on_ground = true;
    walker.position = {2.0f, 0.0f, -4.0f};
    walker.motion = BodyMotion{{{2.0f, 0.0f, -4.0f}, {6.0f, 0.0f, -4.0f}}, 1.5f, true};
    sim->add_body(walker);
    WindFieldDef field;
    field.cells_x = field.cells_z = 8;
    field.cells_y = 4;
    field.update_every = 2;
    sim->set_wind_field(field);
    sim->set_wind_transport({});
    for (int t = 0; t < 5; ++t) {
        sim->tick();
    }
    return sim;
}

/// Restores `bytes` into `sim` and ticks once. Empty when they were restored
/// and the tick stayed balanced and finite, or were refused with the state
/// unchanged; otherwise what went wrong.
inline std::string restore_and_tick(Simulation& sim, std::span<const std::byte> bytes) {
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

/// restore_and_tick on `bytes` as they are, then on them re-framed (the
/// current format, their payload length and checksum made to match,
/// snapshot_layout.hpp), so that mutated payloads, and findings kept from an
/// older format, reach the records instead of stopping at the frame.
inline std::string snapshot_unit(Simulation& sim, std::span<const std::byte> bytes) {
    if (std::string problem = restore_and_tick(sim, bytes); !problem.empty()) {
        return problem;
    }
    const std::size_t frame = snapshot_header_bytes + snapshot_checksum_bytes;
    if (bytes.size() < frame) {
        return "";
    }
    std::vector<std::byte> framed(bytes.begin(), bytes.end());
    const std::uint64_t payload = framed.size() - frame;
    std::memcpy(framed.data() + snapshot_magic.size(), &snapshot_format, sizeof snapshot_format);
    std::memcpy(framed.data() + snapshot_length_at, &payload, sizeof payload);
    const std::uint64_t sum =
        snapshot_checksum(std::span(framed).first(framed.size() - snapshot_checksum_bytes));
    std::memcpy(framed.data() + framed.size() - snapshot_checksum_bytes, &sum, sizeof sum);
    return restore_and_tick(sim, framed);
}

} // namespace snow::fuzz
