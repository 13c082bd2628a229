// snow_game as a player starts it: headless frames to PNG, a window under
// Xvfb that reacts to injected keys (pause, step) and exits cleanly, the walk
// camera's player walking forward on injected keys and leaving a trench (in
// a window and headless), the time-lapse's files, and exit status 2 for a
// bad command line.
#include "tests/support/run_app.hpp"
#include "tests/support/xvfb.hpp"

#include <gtest/gtest.h>

#include <snow/render.hpp>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <regex>
#include <sstream>
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

TEST(SnowGame, AovWritesSnowAndShadowMasksBesideEachFrame) {
    const std::filesystem::path dir =
        std::filesystem::path(SNOW_BINARY_DIR) / "test_out" / "game_aov";
    std::filesystem::remove_all(dir);
    const snow::test::AppRun r =
        run_game("MESA_SHADER_CACHE_DISABLE=true",
                 "--headless --frames 2 --size 160x120 --aov --scene " SNOW_SOURCE_DIR
                 "/assets/scenes/village_effects.gltf --out " +
                     dir.string());
    ASSERT_EQ(r.status, 0) << r.out;
    for (const char* f : {"frame_00001.png", "frame_00001_snow.png", "frame_00001_shadow.png"}) {
        ASSERT_TRUE(std::filesystem::exists(dir / f)) << f;
        const snow::Image image = snow::read_png(dir / f);
        EXPECT_EQ(image.width, 160) << f;
        EXPECT_EQ(image.height, 120) << f;
    }
    // Snow lies in view, and so do the buildings' shadows from the scene's sun.
    for (const char* f : {"frame_00001_snow.png", "frame_00001_shadow.png"}) {
        const snow::Image mask = snow::read_png(dir / f);
        std::size_t white = 0;
        for (std::size_t i = 0; i < mask.rgba.size(); i += 4) {
            white += mask.rgba[i] >= 128 ? 1u : 0u;
        }
        EXPECT_GT(white, 160u * 120u / 50u) << f;
    }
    const snow::test::AppRun windowed =
        run_game("MESA_SHADER_CACHE_DISABLE=true", "--aov --frames 1");
    EXPECT_EQ(windowed.status, 2) << windowed.out;
    EXPECT_NE(windowed.out.find("--aov: needs --headless"), std::string::npos) << windowed.out;
    EXPECT_EQ(std::count(windowed.out.begin(), windowed.out.end(), '\n'), 1) << windowed.out;
}

/// snow_game in a window on a private Xvfb server; nothing when Xvfb is not installed.
std::optional<snow::test::AppRun> run_game_in_xvfb(const std::string& args) {
    const auto xvfb_binary = snow::test::Xvfb::find();
    if (!xvfb_binary) {
        return std::nullopt;
    }
    snow::test::Xvfb server;
    std::string display, error;
    if (!server.start(*xvfb_binary, display, error)) {
        ADD_FAILURE() << error;
        return snow::test::AppRun{};
    }
    return run_game("MESA_SHADER_CACHE_DISABLE=true DISPLAY=" + display, args);
}

constexpr const char* no_xvfb =
    "Xvfb is not installed: the window test cannot run (apt-get install xvfb)";

TEST(SnowGame, WindowUnderXvfbReactsToInjectedKeys) {
    const auto run = run_game_in_xvfb("--size 320x240 --inject 3:P,5:N,6:N,8:ESC");
    if (!run) {
        GTEST_SKIP() << no_xvfb;
    }
    const snow::test::AppRun& r = *run;
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

/// What the game says of the player's walk at the end of a run.
struct Walk {
    double walked = 0.0, on_trail = 0.0, beside = 0.0;
    int samples = 0;
};
std::optional<Walk> walk_report(const std::string& out) {
    const std::regex line("player walked ([0-9.]+) m from .*; snow on its trail ([0-9.]+) mm, 1 "
                          "m beside it ([0-9.]+) mm \\(([0-9]+) samples\\)");
    std::smatch m;
    if (!std::regex_search(out, m, line)) {
        return std::nullopt;
    }
    return Walk{std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stoi(m[4])};
}

/// The village after 10 s of a fast-forwarded snowfall (150 kg/m²/h, about
/// 4 mm): the
/// player holds W from the first frame and Esc ends the run.
const std::string walk_args = "--size 160x120 --quality low --snowfall 150 --max-flakes 300000 "
                              "--warmup 300 --inject 0:W:90,100:ESC";

void expect_trench(const snow::test::AppRun& r, double at_least_m) {
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("walk camera"), std::string::npos) << r.out;
    const auto walk = walk_report(r.out);
    ASSERT_TRUE(walk) << r.out;
    EXPECT_GT(walk->walked, at_least_m) << r.out;
    EXPECT_GE(walk->samples, 2) << r.out;
    EXPECT_GT(walk->beside, 0.5) << "snow to walk through: " << r.out;
    EXPECT_LT(walk->on_trail, 0.5 * walk->beside) << "a trench behind the player: " << r.out;
}

TEST(SnowGame, HeadlessPlayerWalksForwardAndLeavesATrench) {
    const std::filesystem::path dir =
        std::filesystem::path(SNOW_BINARY_DIR) / "test_out" / "game_walk";
    const snow::test::AppRun r = run_game("MESA_SHADER_CACHE_DISABLE=true",
                                          "--headless --out " + dir.string() + " " + walk_args);
    // Headless frames are 1/30 s: 90 frames of W at 1.4 m/s are 4.2 m.
    expect_trench(r, 4.1);
    const auto walk = walk_report(r.out);
    ASSERT_TRUE(walk);
    EXPECT_LT(walk->walked, 4.3);
}

TEST(SnowGame, HeadlessPlayerWalksUnderThePorchRoof) {
    // From the default start (1, 9) the player heads for the house: 260
    // frames of W (12 m) take it under the porch roof (z 0.2 to -2.2, 2 m
    // up) and out beyond it, on the ground all the way.
    const std::filesystem::path dir =
        std::filesystem::path(SNOW_BINARY_DIR) / "test_out" / "game_porch";
    const snow::test::AppRun r =
        run_game("MESA_SHADER_CACHE_DISABLE=true",
                 "--headless --out " + dir.string() +
                     " --size 160x120 --quality low --frames 280 --inject 0:W:260,270:ESC");
    ASSERT_EQ(r.status, 0) << r.out;
    const std::regex to("player walked ([0-9.]+) m from .* to \\(([-0-9.]+), ([-0-9.]+)\\)");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, to)) << r.out;
    EXPECT_GT(std::stod(m[1]), 12.0) << r.out;
    const double x = std::stod(m[2]), z = std::stod(m[3]);
    EXPECT_GT(x, -0.45 + 0.25) << "under the porch roof, not along the house: " << r.out;
    EXPECT_LT(x, 1.6) << r.out;
    EXPECT_LT(z, -2.2) << "past the porch: " << r.out;
}

TEST(SnowGame, WindowUnderXvfbPlayerWalksForwardAndLeavesATrench) {
    // A window's ticks follow the wall clock, so a walk held for some frames
    // would be as long as the frame rate makes it (2 m here, 14 m under
    // ASan, where the old trail had filled in again). Paused, each N steps
    // one tick with W held: 90 ticks, 4.2 m, at any frame rate.
    std::ostringstream args;
    args << "--size 160x120 --quality low --snowfall 150 --max-flakes 300000 --warmup 300 "
            "--inject 0:P,1:W:100";
    for (int frame = 2; frame < 92; ++frame) {
        args << ',' << frame << ":N";
    }
    args << ",95:ESC";
    const auto run = run_game_in_xvfb(args.str());
    if (!run) {
        GTEST_SKIP() << no_xvfb;
    }
    const snow::test::AppRun& r = *run;
    EXPECT_NE(r.out.find("snow_game: window"), std::string::npos) << r.out;
    expect_trench(r, 4.1);
    const auto walk = walk_report(r.out);
    ASSERT_TRUE(walk);
    EXPECT_LT(walk->walked, 4.3);
}

TEST(SnowGame, TimelapseWritesFramesAndAContactSheet) {
    const std::filesystem::path dir =
        std::filesystem::path(SNOW_BINARY_DIR) / "test_out" / "game_timelapse";
    std::filesystem::remove_all(dir);
    // The time-lapse's settings, shortened: 9 frames of 64 ticks, 6 moments.
    const snow::test::AppRun r = run_game("MESA_SHADER_CACHE_DISABLE=true",
                                          "--timelapse --frames 9 --size 160x96 --snowfall 15 "
                                          "--walk-once-at 3 --contact-sheet 6 --out " +
                                              dir.string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("fly camera"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("done after 9 frames, tick 576;"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("the walker sets off"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("contact sheet (6 moments)"), std::string::npos) << r.out;
    const std::filesystem::path sheet = dir / "contact_sheet.png";
    ASSERT_TRUE(std::filesystem::exists(sheet)) << r.out;
    const snow::Image image = snow::read_png(sheet);
    EXPECT_EQ(image.width, 4 * 160 + 5 * 4); // 160 px frames need no shrinking
    EXPECT_EQ(image.height, 2 * 96 + 3 * 4);
    EXPECT_TRUE(std::filesystem::exists(dir / "frame_00008.png"));
}

TEST(SnowGame, KeyInjectionNamingNoKeyIsOneError) {
    for (const char* bad : {"--inject 10", "--inject 10:", "--inject ''", "--inject 4:P,,6:N"}) {
        const snow::test::AppRun r =
            run_game("MESA_SHADER_CACHE_DISABLE=true", std::string("--headless ") + bad);
        EXPECT_EQ(r.status, 2) << bad << ": " << r.out;
        EXPECT_NE(r.out.find("names no key"), std::string::npos) << bad << ": " << r.out;
        EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << bad << ": " << r.out;
    }
}

TEST(SnowGame, DefaultCameraWalksWhereTheSceneHasSnowGround) {
    const snow::test::AppRun village =
        run_game("MESA_SHADER_CACHE_DISABLE=true", "--headless --frames 1 --size 64x48 --out " +
                                                       std::string(SNOW_BINARY_DIR) +
                                                       "/test_out/game_camera");
    EXPECT_NE(village.out.find("walk camera"), std::string::npos) << village.out;
    const snow::test::AppRun plain =
        run_game("MESA_SHADER_CACHE_DISABLE=true",
                 "--headless --frames 1 --size 64x48 --scene " + std::string(SNOW_SOURCE_DIR) +
                     "/assets/testdata/plain.gltf --out " + std::string(SNOW_BINARY_DIR) +
                     "/test_out/game_camera");
    EXPECT_EQ(plain.status, 0) << plain.out;
    EXPECT_NE(plain.out.find("fly camera"), std::string::npos) << plain.out;
}

TEST(SnowGame, VDrawsTheWindFieldWhereTheSceneHasOne) {
    const std::string out = " --out " + std::string(SNOW_BINARY_DIR) + "/test_out/game_wind";
    const snow::test::AppRun effects =
        run_game("MESA_SHADER_CACHE_DISABLE=true",
                 "--headless --frames 2 --size 64x48 --inject 0:V --scene " +
                     std::string(SNOW_SOURCE_DIR) + "/assets/scenes/village_effects.gltf" + out);
    EXPECT_EQ(effects.status, 0) << effects.out;
    EXPECT_NE(effects.out.find("wind field arrows on"), std::string::npos) << effects.out;
    const snow::test::AppRun village = run_game(
        "MESA_SHADER_CACHE_DISABLE=true", "--headless --frames 1 --size 64x48 --inject 0:V" + out);
    EXPECT_NE(village.out.find("declares no wind field"), std::string::npos) << village.out;
}

TEST(SnowGame, BadArgumentsExitWithStatus2) {
    for (const char* bad :
         {"--bogus", "--frames 0", "--size 12", "--quality ultra", "--inject 3:Z", "--inject 1:W:0",
          "--camera drone", "--time-scale 8", "--snowfall 0", "--contact-sheet 1",
          "--scene /nonexistent.gltf --headless", "--look-from 1,2", "--look-at 0,1,inf",
          "--headless --frames 1 --look-from 0,1.5,-1 --look-at 0,1.5,-1",
          "--camera walk --headless --frames 1 --scene " SNOW_SOURCE_DIR
          "/assets/testdata/plain.gltf"}) { // plain.gltf: no snow to walk on
        EXPECT_EQ(run_game("MESA_SHADER_CACHE_DISABLE=true", bad).status, 2) << bad;
    }
}

} // namespace
