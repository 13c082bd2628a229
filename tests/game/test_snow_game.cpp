// snow_game as a player starts it: headless frames to PNG, a window under
// Xvfb that reacts to injected keys (pause, step) and exits cleanly, and
// exit status 2 for a bad command line.
#include "tests/support/run_app.hpp"
#include "tests/support/xvfb.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

namespace {

snow::test::AppRun run_game(const std::string& env, const std::string& args) {
    return snow::test::run_app("game/snow_game", args, env);
}

TEST(SnowGame, HeadlessWritesFramesAndSaysWhere) {
    const std::filesystem::path dir =
        std::filesystem::path(SNOW_BINARY_DIR) / "test_out" / "game_frames";
    std::filesystem::remove_all(dir);
    const snow::test::AppRun r =
        run_game("MESA_SHADER_CACHE_DISABLE=true",
                 "--headless --frames 3 --size 160x120 --out " + dir.string());
    ASSERT_EQ(r.status, 0) << r.out;
    for (const char* f : {"frame_00000.png", "frame_00001.png", "frame_00002.png"}) {
        EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
    }
    EXPECT_NE(r.out.find("wrote 3 frames to"), std::string::npos) << r.out;
}

TEST(SnowGame, WindowUnderXvfbReactsToInjectedKeys) {
    const auto xvfb_binary = snow::test::Xvfb::find();
    if (!xvfb_binary) {
        GTEST_SKIP() << "Xvfb is not installed: the window test cannot run (apt-get install xvfb)";
    }
    snow::test::Xvfb server;
    std::string display, error;
    ASSERT_TRUE(server.start(*xvfb_binary, display, error)) << error;
    const snow::test::AppRun r = run_game("MESA_SHADER_CACHE_DISABLE=true DISPLAY=" + display,
                                          "--size 320x240 --inject 3:P,5:N,6:N,8:ESC");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("snow_game: window"), std::string::npos) << r.out;
    const std::regex paused("paused at tick ([0-9]+)");
    const std::regex stepped("stepped to tick ([0-9]+)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, paused)) << r.out;
    const long at = std::stol(m[1]);
    std::vector<long> steps;
    for (auto it = std::sregex_iterator(r.out.begin(), r.out.end(), stepped);
         it != std::sregex_iterator(); ++it) {
        steps.push_back(std::stol((*it)[1]));
    }
    ASSERT_EQ(steps.size(), 2u) << r.out;
    EXPECT_EQ(steps[0], at + 1); // paused: only the steps advance the simulation
    EXPECT_EQ(steps[1], at + 2);
    EXPECT_NE(r.out.find("done after 8 frames, tick " + std::to_string(at + 2)), std::string::npos)
        << r.out;
}

TEST(SnowGame, BadArgumentsExitWithStatus2) {
    for (const char* bad : {"--bogus", "--frames 0", "--size 12", "--quality ultra", "--inject 3:Z",
                            "--scene /nonexistent.gltf --headless"}) {
        EXPECT_EQ(run_game("MESA_SHADER_CACHE_DISABLE=true", bad).status, 2) << bad;
    }
}

} // namespace
