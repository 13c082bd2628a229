// snow_game: the playable snow scene (window), or a headless render to PNGs.
#include "game/play/game_app.hpp"
#include "game/play/game_options.hpp"

#include <cstdio>

int main(int argc, char** argv) {
    snow::GameOptions options;
    try {
        options = snow::parse_game_options(argc, argv);
    } catch (const snow::cli::UsageError& e) {
        std::fprintf(stderr, "snow_game: %s\n", e.message.c_str());
        return 2;
    }
    if (options.help) {
        snow::cli::print_usage(snow::game_usage);
        return 0;
    }
    return snow::run_game(options);
}
