#include "game/run/run_options.hpp"

namespace snow {

namespace {

constexpr const char* run_usage_head = R"(usage: snow_run [options]
  --scene FILE        glTF scene (default: the built-in village scene)
  --ticks N           ticks to simulate (default 200)
)";
constexpr const char* run_usage_tail =
    R"(  --report json|text  what to print at the end (default text)
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

/// Reads one of snow_run's own flags into `o`; false for a flag it does not take.
bool read_flag(std::string_view f, cli::ArgReader& args, RunOptions& o) {
    using namespace cli;
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

} // namespace

const cli::Usage run_usage{run_usage_head, run_usage_tail};

RunOptions parse_run_options(int argc, char** argv) {
    RunOptions o;
    cli::read_command_line(
        argc, argv, {o.scene, o.overrides, o.help},
        [&](std::string_view f, cli::ArgReader& args) { return read_flag(f, args, o); });
    return o;
}

} // namespace snow
