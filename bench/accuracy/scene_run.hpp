/// @file scene_run.hpp
/// @brief One timed snowfall on a scene file with a given set of knobs.
#pragma once

#include "bench/accuracy/depth_field.hpp"
#include "systems/api/systems.hpp"
#include "systems/core/mass_ledger.hpp"
#include "systems/core/sim_config.hpp"

#include <cstdint>
#include <string>

namespace snow::accuracy {

/// What the scene study varies (applied as SceneOverrides).
struct SceneKnobs {
    float dt = 1.0f / 60.0f;
    Integrator integrator = Integrator::explicit_euler;
    float cell_scale = 1.0f;       ///< multiplies every surface's cell edge
    std::uint32_t smoothing = 64;  ///< SimConfig::smoothing_iterations
    std::uint32_t occlusion = 256; ///< occlusion map texels per side

    bool operator==(const SceneKnobs&) const = default;
};

/// "dt=1/60 euler cell×1 smooth=64 occl=256".
[[nodiscard]] std::string knob_label(const SceneKnobs& k);

struct SceneRun {
    SceneKnobs knobs;
    std::uint64_t seed = 0;
    std::uint64_t ticks = 0;
    double cpu_ms_per_tick = 0.0; ///< thread CPU time of Simulation::run / ticks
    MassReport mass;              ///< units at the end
    MassLedger ledger;            ///< where the removed units went
    SimCounters counters;
    DepthField field;

    /// CPU ms per simulated second: what a real-time loop pays at this dt.
    [[nodiscard]] double cpu_ms_per_second() const {
        return cpu_ms_per_tick / static_cast<double>(knobs.dt);
    }
};

/// Loads `scene` with the knobs and seed, simulates `seconds` (rounded to
/// whole ticks) on one thread and captures the depth field. `steady_wind`
/// turns the wind's random walk off (the wind stays at its base). Throws
/// std::runtime_error with the loader's message if the scene does not load.
[[nodiscard]] SceneRun run_scene(const std::string& scene, const SceneKnobs& k, std::uint64_t seed,
                                 float seconds, bool steady_wind);

} // namespace snow::accuracy
