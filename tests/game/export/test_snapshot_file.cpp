// Byte snapshots across processes, as a user takes them: snow_run
// --save-state in one process, --load-state in another, on every shipped
// scene; a damaged or foreign file is one clear error, exit 2.
#include "tests/support/run_app.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace {

snow::test::AppRun run(const std::string& args) {
    return snow::test::run_app("game/snow_run", args, "", false);
}

std::string hash_of(const snow::test::AppRun& r) {
    EXPECT_EQ(r.status, 0) << r.out;
    return nlohmann::json::parse(r.out)["state_hash"].get<std::string>();
}

std::string scene_path(const std::string& name) {
    return std::string(SNOW_SOURCE_DIR) + "/assets/scenes/" + name;
}

std::filesystem::path temp_file(const std::string& name) {
    return std::filesystem::path(SNOW_BINARY_DIR) / ("test_snapshot_" + name);
}

TEST(SnapshotFile, EveryShippedSceneGoesOnBitForBitInAnotherProcess) {
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(SNOW_SOURCE_DIR) + "/assets/scenes")) {
        if (entry.path().extension() != ".gltf") {
            continue;
        }
        const std::string scene = "--scene " + entry.path().string();
        const auto file = temp_file(entry.path().stem().string() + ".snap");
        const std::string whole = hash_of(run(scene + " --ticks 150 --report json"));
        const std::string saved =
            hash_of(run(scene + " --ticks 100 --report json --save-state " + file.string()));
        ASSERT_TRUE(std::filesystem::exists(file));
        const std::string split =
            hash_of(run(scene + " --ticks 50 --report json --load-state " + file.string()));
        EXPECT_EQ(split, whole) << entry.path();
        EXPECT_NE(saved, whole);
        std::filesystem::remove(file);
    }
}

TEST(SnapshotFile, ADamagedOrForeignFileIsOneErrorAndExit2) {
    const auto file = temp_file("damaged.snap");
    ASSERT_EQ(run("--ticks 30 --report json --save-state " + file.string()).status, 0);
    const auto size = std::filesystem::file_size(file);
    std::filesystem::resize_file(file, size - 10);
    snow::test::AppRun r =
        snow::test::run_app("game/snow_run", "--ticks 5 --load-state " + file.string(), "", true);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("--load-state"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("cut short"), std::string::npos) << r.out;

    ASSERT_EQ(run("--ticks 30 --report json --save-state " + file.string()).status, 0);
    r = snow::test::run_app(
        "game/snow_run", "--scene " + scene_path("minimal.gltf") + " --load-state " + file.string(),
        "", true);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("different scene"), std::string::npos) << r.out;

    r = snow::test::run_app("game/snow_run", "--load-state /nonexistent/x.snap", "", true);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("cannot be read"), std::string::npos) << r.out;
    r = snow::test::run_app("game/snow_run", "--save-state /nonexistent/x.snap", "", true);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.out.find("--save-state"), std::string::npos) << r.out;
    std::filesystem::remove(file);
}

} // namespace
