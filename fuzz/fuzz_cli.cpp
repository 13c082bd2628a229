// Fuzz target: the command-line parsers of snow_run and snow_game. The input
// is the argument list, NUL-separated; its first byte picks the app. A
// command line is either read or refused with one UsageError; anything else
// (another exception, a crash, an exit) fails.
#include "game/play/game_options.hpp"
#include "game/run/run_options.hpp"

#include <cstdint>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) {
        return -1;
    }
    const bool game = (data[0] & 1) != 0;
    std::vector<std::string> words{game ? "snow_game" : "snow_run"};
    std::string word;
    for (std::size_t i = 1; i < size; ++i) {
        if (data[i] == 0) {
            words.push_back(word);
            word.clear();
        } else {
            word.push_back(static_cast<char>(data[i]));
        }
    }
    if (size > 1) {
        words.push_back(word);
    }
    std::vector<char*> argv;
    for (std::string& w : words) {
        argv.push_back(w.data());
    }
    argv.push_back(nullptr);
    const int argc = static_cast<int>(words.size());
    try {
        if (game) {
            (void)snow::parse_game_options(argc, argv.data());
        } else {
            (void)snow::parse_run_options(argc, argv.data());
        }
    } catch (const snow::cli::UsageError&) {
    }
    return 0;
}
