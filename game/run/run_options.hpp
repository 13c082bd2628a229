/// @file run_options.hpp
/// @brief What a snow_run run is asked to do: its command line, parsed
/// strictly (a bad value is one UsageError naming the flag).
#pragma once

#include "game/app/cli_args.hpp"

#include <snow/scene.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace snow {

struct RunOptions {
    std::optional<std::string> scene; ///< glTF file; default the built-in village
    std::uint64_t ticks = 200;
    bool json = false; ///< --report json (else text)
    std::optional<std::string> export_glb;
    std::optional<std::string> export_depth;
    std::optional<std::string> load_state;
    std::optional<std::string> save_state;
    SceneOverrides overrides;
    bool help = false; ///< --help: print run_usage and exit 0
};

/// snow_run's usage text.
extern const cli::Usage run_usage;

/// Reads snow_run's command line; throws cli::UsageError naming a bad flag or value.
[[nodiscard]] RunOptions parse_run_options(int argc, char** argv);

} // namespace snow
