// snow_run: the headless simulation CLI. Runs a scene for N ticks and prints
// the state hash, the exact mass balance and what each system cost; bakes
// the settled snow out on request (--export, --export-depth).
#include "game/app/builtin_scene.hpp"
#include "game/export/snapshot_file.hpp"
#include "game/export/snow_export.hpp"
#include "game/run/run_options.hpp"
#include "game/run/run_report.hpp"
#include <snow/scene.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <unistd.h>

namespace {

/// Restores --load-state's snapshot into `sim`; prints the error naming the
/// flag and returns false when it cannot (`sim` is then unchanged).
bool load_state(const snow::RunOptions& o, snow::Simulation& sim) {
    if (!o.load_state) {
        return true;
    }
    try {
        snow::load_snapshot_file(sim, *o.load_state);
        return true;
    } catch (const snow::Error& e) {
        std::fprintf(stderr, "snow_run: --load-state: %s\n", e.what());
        return false;
    }
}

/// Writes the exports asked for; with no `sim`, only checks that their paths
/// can be written. A failure is printed naming the flag and returns false.
bool write_exports(const snow::RunOptions& o, const snow::Simulation* sim) {
    const char* flag = "--export";
    try {
        if (o.export_glb) {
            sim ? snow::export_snow_glb(*sim, *o.export_glb)
                : snow::check_file_writable(*o.export_glb);
        }
        flag = "--export-depth";
        if (o.export_depth) {
            sim ? snow::export_snow_depth(*sim, *o.export_depth)
                : snow::prepare_output_dir(*o.export_depth);
        }
        flag = "--save-state";
        if (o.save_state) {
            sim ? snow::save_snapshot_file(*sim, *o.save_state)
                : snow::check_file_writable(*o.save_state);
        }
        return true;
    } catch (const snow::FileWriteError& e) {
        std::fprintf(stderr, "snow_run: %s: %s\n", flag, e.what());
        return false;
    }
}

} // namespace

int main(int argc, char** argv) {
    snow::RunOptions opt;
    try {
        opt = snow::parse_run_options(argc, argv);
    } catch (const snow::cli::UsageError& e) {
        std::fprintf(stderr, "snow_run: %s\n", e.message.c_str());
        return 2;
    }
    if (opt.help) {
        snow::cli::print_usage(snow::run_usage);
        return 0;
    }
    snow::SceneLoadResult scene = opt.scene
                                      ? snow::load_scene_file(*opt.scene, opt.overrides)
                                      : snow::load_scene_memory(snow::builtin_village_gltf(),
                                                                "builtin:village", opt.overrides);
    if (!scene.sim) {
        std::fprintf(stderr, "snow_run: %s\n", scene.error.c_str());
        return 2;
    }
    // Unwritable export paths fail now, not after the run.
    if (!write_exports(opt, nullptr) || !load_state(opt, *scene.sim)) {
        return 2;
    }
    try {
        snow::Simulation& sim = *scene.sim;
        // Progress on stderr for long runs, so stdout stays one report.
        const bool progress = opt.ticks >= 20000 && isatty(STDERR_FILENO);
        const auto t0 = std::chrono::steady_clock::now();
        for (std::uint64_t t = 0; t < opt.ticks; ++t) {
            sim.tick();
            if (progress && (t + 1) % (opt.ticks / 20) == 0) {
                std::fprintf(stderr, "\rsnow_run: %3llu%%", (t + 1) * 100ull / opt.ticks);
            }
        }
        if (progress) {
            std::fputc('\n', stderr);
        }
        const auto t1 = std::chrono::steady_clock::now();
        if (!write_exports(opt, &sim)) {
            return 2;
        }
        const snow::RunInfo info{scene.name, opt.ticks,
                                 std::chrono::duration<double, std::milli>(t1 - t0).count()};
        std::cout << (opt.json ? snow::run_report_json(sim, info)
                               : snow::run_report_text(sim, info))
                  << std::endl;
        return sim.mass().balanced() && sim.nonfinite_count() == 0 ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "snow_run: %s\n", e.what());
        return 1;
    }
}
