// snow_accuracy: accuracy versus cost (issue #7). Measures the integrators on
// closed-form trajectories and the village scene's depth field against a fine
// reference while dt, cell size, smoothing iterations and occlusion resolution
// vary; picks the quality presets from the Pareto front; and measures the wind
// field's resolution and update interval against a fine field (issue #15). scripts/accuracy.sh
// runs it and turns its output into docs/accuracy.md and plots.
#include "bench/accuracy/report.hpp"
#include "ecs/staged_files.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <string_view>

namespace {

using namespace snow;
using namespace snow::accuracy;

constexpr const char* usage = R"(usage: snow_accuracy [options]
  --scene FILE     glTF scene (default: assets/scenes/village.gltf of the source tree)
  --out DIR        where CSV, .dat and report.md go (default accuracy-out; created)
  --seconds S      snowfall simulated by every scene run (default 60; the
                   wind-field runs take at most 30)
  --block M        block edge in metres of the main depth error (default 2)
  --quick          a small plan that finishes in seconds (smoke test, not for docs)
  --help           this text
Exit status: 0 ok, 2 bad arguments or an output folder that cannot be written,
1 failure.
)";

struct UsageError {
    std::string message;
};

float positive_number(std::string_view flag, const char* text) {
    char* end = nullptr;
    const float v = std::strtof(text, &end);
    if (end == text || *end != '\0' || !(v > 0.0f) || !(v < 1.0e6f)) {
        throw UsageError{std::string(flag) + ": expected a positive number, got '" + text + "'"};
    }
    return v;
}

struct Args {
    std::string scene = SNOW_SOURCE_DIR "/assets/scenes/village.gltf";
    std::string out = "accuracy-out";
    float seconds = 60.0f;
    float block = 2.0f;
    bool quick = false;
};

Args parse(int argc, char** argv) {
    Args a;
    for (int i = 1; i < argc; ++i) {
        const std::string_view f = argv[i];
        const auto value = [&]() -> const char* {
            if (i + 1 >= argc) {
                throw UsageError{std::string(f) + ": missing value"};
            }
            return argv[++i];
        };
        if (f == "--help") {
            std::fputs(usage, stdout);
            std::exit(0);
        } else if (f == "--scene") {
            a.scene = value();
        } else if (f == "--out") {
            a.out = value();
        } else if (f == "--seconds") {
            a.seconds = positive_number(f, value());
        } else if (f == "--block") {
            a.block = positive_number(f, value());
        } else if (f == "--quick") {
            a.quick = true;
        } else {
            throw UsageError{"unknown option '" + std::string(f) + "'"};
        }
    }
    return a;
}

constexpr Integrator all_integrators[] = {Integrator::explicit_euler,
                                          Integrator::semi_implicit_euler, Integrator::exponential,
                                          Integrator::rk4, Integrator::automatic};

TrajectoryOptions trajectory_plan(bool quick) {
    TrajectoryOptions o;
    o.integrators.assign(std::begin(all_integrators), std::end(all_integrators));
    o.dts = {1.0f / 240.0f, 1.0f / 120.0f, 1.0f / 60.0f, 1.0f / 30.0f, 1.0f / 20.0f, 1.0f / 15.0f};
    if (quick) {
        o.dts = {1.0f / 60.0f, 1.0f / 30.0f, 1.0f / 15.0f};
        o.flakes = 64;
        o.timing_flakes = 4096;
        o.timing_ticks = 20;
        o.timing_repeats = 2;
    }
    return o;
}

SceneStudyOptions scene_plan(const Args& a) {
    SceneStudyOptions o;
    o.scene = a.scene;
    o.seconds = a.seconds;
    o.block = a.block;
    o.dts = {1.0f / 240.0f, 1.0f / 120.0f, 1.0f / 60.0f, 1.0f / 30.0f, 1.0f / 15.0f};
    o.integrator_dts = {1.0f / 60.0f, 1.0f / 15.0f};
    o.integrators.assign(std::begin(all_integrators), std::end(all_integrators));
    o.cell_scales = {0.5f, 1.0f, 2.0f, 4.0f};
    o.smoothings = {1, 4, 64, 256};
    o.occlusions = {64, 128, 256, 512, 1024};
    o.grid_dts = {1.0f / 120.0f, 1.0f / 60.0f, 1.0f / 30.0f, 1.0f / 15.0f};
    o.grid_cell_scales = {0.5f, 1.0f, 2.0f};
    o.grid_occlusions = {128, 256};
    if (a.quick) {
        o.seconds = std::min(a.seconds, 2.0f);
        o.seeds = {2};
        o.reference_seeds = {101};
        o.floor_seeds = {2};
        o.reference = {1.0f / 60.0f, Integrator::exponential, 1.0f, 64, 256};
        o.dts = {1.0f / 30.0f};
        o.integrator_dts = {1.0f / 30.0f};
        o.integrators = {Integrator::rk4};
        o.cell_scales = {2.0f};
        o.smoothings = {4};
        o.occlusions = {128};
        o.grid_dts = {1.0f / 15.0f};
        o.grid_cell_scales = {2.0f};
        o.grid_occlusions = {128};
    }
    return o;
}

WindFieldStudyOptions wind_plan(const Args& a) {
    WindFieldStudyOptions o;
    o.scene = a.scene;
    o.seconds = std::min(a.seconds, 30.0f);
    o.warmup = o.seconds / 3.0f;
    if (a.quick) {
        o.seconds = std::min(a.seconds, 2.0f);
        o.warmup = 1.0f;
        o.reference = {1.0f, 4, 1};
        o.cell_scales = {0.5f};
        o.update_everys = {8};
        o.sample_everys = {1, WindFieldDef{}.sample_every};
    }
    return o;
}

int run(const Args& a) {
    const auto start = std::chrono::steady_clock::now();
    prepare_output_dir(a.out); // before the study, not after its hours
    StudyResults r;
    r.trajectory_options = trajectory_plan(a.quick);
    std::fprintf(stderr, "snow_accuracy: trajectories (%zu integrators x %zu dt)\n",
                 r.trajectory_options.integrators.size(), r.trajectory_options.dts.size());
    r.trajectory = run_trajectory_study(r.trajectory_options);
    r.large_pool_dt = 1.0f / 60.0f;
    r.large_pool_flakes = a.quick ? 65536 : 1u << 20;
    TrajectoryOptions large = r.trajectory_options;
    large.timing_ticks = a.quick ? 2 : 40;
    large.timing_repeats = a.quick ? 1 : 3;
    r.large_pool_ns = integrator_costs(large, r.large_pool_dt, r.large_pool_flakes);
    r.scene_options = scene_plan(a);
    std::fprintf(stderr, "snow_accuracy: scene %s, %.0f s of snowfall per run\n", a.scene.c_str(),
                 static_cast<double>(r.scene_options.seconds));
    r.scene = run_scene_study(r.scene_options, stderr);
    std::vector<std::size_t> all(r.scene.points.size());
    for (std::size_t i = 0; i < all.size(); ++i) {
        all[i] = i;
    }
    r.front = pareto_front(r.scene, all);
    r.presets = pick_presets(r.scene, r.trajectory);
    r.wind_options = wind_plan(a);
    std::fprintf(stderr, "snow_accuracy: wind field, %.0f s per run\n",
                 static_cast<double>(r.wind_options.seconds));
    r.wind = run_wind_field_study(r.wind_options, stderr);
    r.seconds_total =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_results(a.out, r);
    std::fprintf(stderr, "snow_accuracy: wrote %s/report.md (%.0f s)\n", a.out.c_str(),
                 r.seconds_total);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        return run(parse(argc, argv));
    } catch (const UsageError& e) {
        std::fprintf(stderr, "snow_accuracy: %s\n%s", e.message.c_str(), usage);
        return 2;
    } catch (const FileWriteError& e) {
        std::fprintf(stderr, "snow_accuracy: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "snow_accuracy: %s\n", e.what());
        return 1;
    }
}
