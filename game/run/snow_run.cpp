// snow_run: the headless simulation CLI. Runs a scene for N ticks and prints
// the state hash, the exact mass balance and what each system cost; bakes
// the settled snow out on request (--export, --export-depth).
#include "game/app/builtin_scene.hpp"
#include "game/app/cli_args.hpp"
#include "game/export/snapshot_file.hpp"
#include "game/export/snow_export.hpp"
#include "game/run/run_report.hpp"
#include <snow/scene.hpp>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <unistd.h>

namespace {

constexpr const char* usage_head = R"(usage: snow_run [options]
  --scene FILE        glTF scene (default: the built-in village scene)
  --ticks N           ticks to simulate (default 200)
)";
constexpr const char* usage_tail = R"(  --report json|text  what to print at the end (default text)
  --export FILE.glb   after the run, write the settled snow as glTF 2.0 meshes
  --export-depth DIR  after the run, write each surface's depth as a 16-bit PNG
                      (millimetres) and a JSON sidecar into DIR
  --load-state FILE   before the run, restore a snapshot of the same scene
                      (written by --save-state); --ticks then runs on from it
  --save-state FILE   after the run, write the simulation's snapshot (bytes)
  --help              this text
Exit status: 0 ok, 2 bad arguments, bad scene, a snapshot that cannot be
read or an output path that cannot be written, 1 other failure.
)";

struct Options {
    std::optional<std::string> scene;
    std::uint64_t ticks = 200;
    bool json = false;
    std::optional<std::string> export_glb;
    std::optional<std::string> export_depth;
    std::optional<std::string> load_state;
    std::optional<std::string> save_state;
    snow::SceneOverrides overrides;
};

/// Reads one of snow_run's own flags into `o`; false for a flag it does not take.
bool read_flag(std::string_view f, snow::cli::ArgReader& args, Options& o) {
    using namespace snow::cli;
    if (f == "--ticks") {
        o.ticks = parse_uint(f, args.value(), 0, 1'000'000'000'000ull);
    } else if (f == "--report") {
        const std::string_view r = args.value();
        if (r != "json" && r != "text") {
            throw UsageError{"--report: expected json or text, got '" + std::string(r) + "'"};
        }
        o.json = r == "json";
    } else if (f == "--export" || f == "--export-depth" || f == "--load-state" ||
               f == "--save-state") {
        const std::string_view path = args.value();
        if (path.empty()) {
            throw UsageError{std::string(f) + ": expected a path"};
        }
        auto& slot = f == "--export"         ? o.export_glb
                     : f == "--export-depth" ? o.export_depth
                     : f == "--load-state"   ? o.load_state
                                             : o.save_state;
        slot = std::string(path);
    } else {
        return false;
    }
    return true;
}

Options parse(int argc, char** argv) {
    Options o;
    snow::cli::read_command_line(
        argc, argv, {usage_head, usage_tail}, {o.scene, o.overrides},
        [&](std::string_view f, snow::cli::ArgReader& args) { return read_flag(f, args, o); });
    return o;
}

/// Restores --load-state's snapshot into `sim`; prints the error naming the
/// flag and returns false when it cannot (`sim` is then unchanged).
bool load_state(const Options& o, snow::Simulation& sim) {
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
bool write_exports(const Options& o, const snow::Simulation* sim) {
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
    Options opt;
    try {
        opt = parse(argc, argv);
    } catch (const snow::cli::UsageError& e) {
        std::fprintf(stderr, "snow_run: %s\n", e.message.c_str());
        return 2;
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
