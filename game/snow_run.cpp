// snow_run: the headless simulation CLI. Runs a scene for N ticks and prints
// the state hash, the exact mass balance and what each system cost.
#include "game/builtin_scene.hpp"
#include "game/cli_args.hpp"
#include "game/run_report.hpp"
#include "game/scene/scene_loader.hpp"

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
  --help              this text
Exit status: 0 ok, 2 bad arguments or bad scene, 1 other failure.
)";

struct Options {
    std::optional<std::string> scene;
    std::uint64_t ticks = 200;
    bool json = false;
    snow::SceneOverrides overrides;
};

Options parse(int argc, char** argv) {
    using namespace snow::cli;
    Options o;
    ArgReader args(argc, argv);
    while (args.next()) {
        const std::string_view f = args.flag();
        if (read_override(args, o.overrides)) {
            continue;
        }
        if (f == "--help" || f == "-h") {
            std::fputs(usage_head, stdout);
            std::fputs(override_usage, stdout);
            std::fputs(usage_tail, stdout);
            std::exit(0);
        } else if (f == "--scene") {
            o.scene = std::string(args.value());
        } else if (f == "--ticks") {
            o.ticks = parse_uint(f, args.value(), 0, 1'000'000'000'000ull);
        } else if (f == "--report") {
            const std::string_view r = args.value();
            if (r != "json" && r != "text") {
                throw UsageError{"--report: expected json or text, got '" + std::string(r) + "'"};
            }
            o.json = r == "json";
        } else {
            args.unknown();
        }
    }
    return o;
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
