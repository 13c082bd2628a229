/// @file cli_args.hpp
/// @brief Strict parsing of command-line values shared by snow_run and snow_game:
/// a bad value gives one message naming the flag, never a silent default.
#pragma once

#include <snow/scene.hpp>

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace snow::cli {

/// Thrown for a bad command line; the apps print what() and exit with status 2.
struct UsageError {
    std::string message;
};

/// Whole-string unsigned integer in [min, max]; throws UsageError naming `flag`.
[[nodiscard]] std::uint64_t parse_uint(std::string_view flag, std::string_view text,
                                       std::uint64_t min, std::uint64_t max);
/// Whole-string finite number in (0, max]; throws UsageError naming `flag`.
[[nodiscard]] double parse_positive(std::string_view flag, std::string_view text, double max);

/// Whole-string "X,Y,Z" of finite numbers, each within ±max_abs; throws
/// UsageError naming `flag`.
[[nodiscard]] glm::vec3 parse_vec3(std::string_view flag, std::string_view text, double max_abs);

/// Walks argv; `value()` takes the argument after the current flag.
class ArgReader {
  public:
    ArgReader(int argc, char** argv) : argc_(argc), argv_(argv) {}
    [[nodiscard]] bool next();
    [[nodiscard]] std::string_view flag() const { return flag_; }
    /// The value following the current flag; throws UsageError if missing.
    [[nodiscard]] std::string_view value();
    [[noreturn]] void unknown() const;

  private:
    int argc_;
    char** argv_;
    int i_ = 0;
    std::string_view flag_;
};

/// The scene flags both apps take (--seed, --threads, --dt, --integrator,
/// --max-flakes, --wind, --auto-snow), as their usage lines.
inline constexpr const char* override_usage =
    R"(  --seed S            random seed (default: the scene's)
  --threads T         worker threads, >= 1 (default: the scene's, usually 1)
  --dt SECONDS        fixed tick length, 0 < dt <= 1 (default: the scene's)
  --integrator NAME   euler | semi_implicit | exponential | rk4 | auto
  --max-flakes N      flake pool size, 1 to 16777216 (default: the scene's)
  --wind X,Y,Z        the global wind's mean, m/s (default: the scene's)
  --auto-snow         snow on a plain scene: its meshes become colliders under a
                      snow cover, with an emitter, occlusion camera and camera
                      where the scene declares none (docs/scenes.md)
)";

/// If the current flag is one of override_usage's, reads its value into `o`
/// and returns true; false for any other flag. Throws UsageError on a bad value.
[[nodiscard]] bool read_override(ArgReader& args, SceneOverrides& o);

/// An app's usage text: its own lines before and after override_usage.
struct Usage {
    const char* head;
    const char* tail;
};

/// Prints `usage` (its head, override_usage, its tail) to stdout.
void print_usage(const Usage& usage);

/// What both apps read alike: the scene file, the overrides and whether
/// --help was asked for (the app then prints its usage and exits 0).
struct SceneArgs {
    std::optional<std::string>& scene;
    SceneOverrides& overrides;
    bool& help;
};

/// If the current flag is one both apps take (override_usage's, --scene
/// FILE, --help or -h), reads it into `into` and returns true; false for any
/// other flag.
[[nodiscard]] bool read_shared(ArgReader& args, const SceneArgs& into);

/// Reads the whole command line, up to a --help: the flags both apps take
/// into `into`, every other flag by `own(flag, args)`, which returns false
/// for one it does not know (a UsageError naming it). Never exits, so the
/// parsers can be fuzzed (fuzz/fuzz_cli.cpp).
template <typename Own>
void read_command_line(int argc, char** argv, const SceneArgs& into, Own&& own) {
    ArgReader args(argc, argv);
    while (!into.help && args.next()) {
        if (!read_shared(args, into) && !own(args.flag(), args)) {
            args.unknown();
        }
    }
}

} // namespace snow::cli
