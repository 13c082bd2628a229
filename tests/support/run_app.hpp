/// @file run_app.hpp
/// @brief Test support: run one of the project's programs as a user would and
/// collect its exit status and output.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace snow::test {

struct AppRun {
    int status = -1; ///< exit status; -1 if it did not exit normally
    std::string out; ///< stdout, plus stderr when asked for
};

/// Runs `SNOW_BINARY_DIR/<app> <args>` with `env` assignments in front
/// (e.g. "DISPLAY=:1"); stderr joins stdout when `with_stderr`, else is dropped.
inline AppRun run_app(const std::string& app, const std::string& args, const std::string& env = "",
                      bool with_stderr = true) {
    const std::string cmd = env + " " + std::string(SNOW_BINARY_DIR) + "/" + app + " " + args +
                            (with_stderr ? " 2>&1" : " 2>/dev/null");
    AppRun r;
    FILE* p = popen(cmd.c_str(), "r");
    if (p == nullptr) {
        return r;
    }
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), buf.size(), p) != nullptr) {
        r.out += buf.data();
    }
    const int raw = pclose(p);
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return r;
}

} // namespace snow::test
