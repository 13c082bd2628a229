// What snow_game shows and writes, read off the session without a window or
// GL: the HUD's facts, the moment labels and reports it prints, and the
// headless recording's frames and contact sheet.
#include "game/play/headless_recording.hpp"
#include "game/play/hud_info.hpp"
#include "game/play/session_report.hpp"
#include "tests/game/play/game_play.hpp"

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <filesystem>
#include <string>

namespace snow {
namespace {

using test::GamePlay;
using test::quick_game;

TEST(GameOutput, HudShowsTheSessionsState) {
    GamePlay g(quick_game(), "0:P,0:T,0:H");
    g.play();
    const HudInfo info = hud_info(*g.session, 42.0f);
    EXPECT_EQ(info.fps, 42.0f);
    EXPECT_TRUE(info.paused);
    EXPECT_TRUE(info.help);
    EXPECT_TRUE(info.fog_on);
    EXPECT_EQ(info.quality, "low");
    EXPECT_EQ(info.camera_mode, "walk");
    EXPECT_EQ(info.time_scale, 4u);
    EXPECT_EQ(info.ticks_per_frame, 0u) << "paused";
    EXPECT_EQ(info.last_message, "time x4");
    EXPECT_TRUE(info.depth_under.has_value()) << "the walk camera shows the snow underfoot";
    g.press(GLFW_KEY_O);
    EXPECT_FALSE(hud_info(*g.session, 0.0f).depth_under.has_value()) << "not when flying";
}

TEST(GameOutput, MomentLabelIsTheSimulatedTimeAndTheGroundsSnow) {
    GamePlay g(quick_game());
    EXPECT_EQ(moment_label(*g.session), "t 0:00  0.0 cm");
    g.play(60); // 60 ticks of 1/30 s
    EXPECT_EQ(moment_label(*g.session).rfind("t 0:02  ", 0), 0u) << moment_label(*g.session);
    GamePlay plain(quick_game("testdata/plain.gltf"));
    EXPECT_EQ(moment_label(*plain.session), "t 0:00") << "no ground: no depth";
    EXPECT_EQ(clock_text(125.4), "2:05");
}

TEST(GameOutput, ReportsSayWhereTheRunIsAndHowThePlayerWalked) {
    GamePlay g(quick_game(), "0:W:30");
    g.play(30); // 1 s
    const std::string tick = std::to_string(g.sim().tick_count());
    const std::string progress = progress_line(*g.session, 29, 60, 2.5);
    EXPECT_EQ(
        progress.rfind("snow_game: frame 30/60, tick " + tick + " (0:01 simulated, t 0:01 ", 0), 0u)
        << progress;
    EXPECT_NE(progress.find("2.5 ms/frame render\n"), std::string::npos) << progress;
    const std::string report = session_report(*g.session, 30);
    EXPECT_EQ(report.rfind("snow_game: done after 30 frames, tick " + tick + "; mass units", 0), 0u)
        << report;
    EXPECT_NE(report.find("\nsnow_game: player walked 1."), std::string::npos) << report;
    GamePlay plain(quick_game("testdata/plain.gltf"));
    EXPECT_EQ(session_report(*plain.session, 0).find("player"), std::string::npos)
        << "no player, no walk";
}

TEST(GameOutput, HeadlessRecordingWritesEveryFrameAndTheSheetsMoments) {
    const std::filesystem::path dir =
        std::filesystem::path(SNOW_BINARY_DIR) / "test_out" / "game_recording";
    std::filesystem::remove_all(dir);
    GameOptions o = quick_game();
    o.out_dir = dir.string();
    o.frames = 5;
    o.contact_sheet = 3;
    o.width = 32;
    GamePlay g(o);
    HeadlessRecording recording(o);
    Image image;
    image.width = 32;
    image.height = 24;
    image.rgba.assign(32 * 24 * 4, 128);
    for (std::uint64_t frame = 0; frame < 5; ++frame) {
        g.play();
        recording.add(image, *g.session, frame);
    }
    const std::string said = recording.finish();
    EXPECT_NE(said.find("wrote 5 frames to"), std::string::npos) << said;
    EXPECT_NE(said.find("contact sheet (3 moments)"), std::string::npos) << said;
    EXPECT_EQ(said.find("video"), std::string::npos) << "no video asked for: " << said;
    for (const char* f : {"frame_00000.png", "frame_00004.png", "contact_sheet.png"}) {
        EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "frame_00005.png"));
}

} // namespace
} // namespace snow
