// Exact snapshots on every scene of assets/scenes (the code-built storm is in
// tests/systems/api/test_snapshot.cpp): load, run 300 ticks, save, run on (1000 ticks) as the
// reference, restore and run the same ticks again; the state hash agrees on
// every tick and the flakes and snow at the end, bit for bit.
#include "tests/hard_cases/hard_case_util.hpp"
#include "tests/support/snapshot_check.hpp"
#include <snow/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace snow::test {
namespace {

constexpr std::uint64_t ahead_ticks = hard::scaled<std::uint64_t>(1000, 200);

/// Every .gltf file of assets/scenes, by file name.
std::vector<std::string> scene_files() {
    std::vector<std::string> names;
    for (const auto& entry :
         std::filesystem::directory_iterator(std::string(SNOW_SOURCE_DIR) + "/assets/scenes")) {
        if (entry.path().extension() == ".gltf") {
            names.push_back(entry.path().filename().string());
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

class SceneSnapshot : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneSnapshot, ContinuesBitForBitAfterARestore) {
    SceneLoadResult r =
        load_scene_file(std::string(SNOW_SOURCE_DIR) + "/assets/scenes/" + GetParam());
    ASSERT_NE(r.sim, nullptr) << r.error;
    expect_restore_replays(*r.sim, 300, ahead_ticks);
    EXPECT_TRUE(r.sim->mass().balanced());
}

INSTANTIATE_TEST_SUITE_P(Assets, SceneSnapshot, ::testing::ValuesIn(scene_files()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             std::string name = info.param.substr(0, info.param.find('.'));
                             for (char& ch : name) {
                                 ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
                             }
                             return name;
                         });

TEST(SceneSnapshotAssets, AllFourScenesAreCovered) {
    EXPECT_GE(scene_files().size(), 4u);
}

} // namespace
} // namespace snow::test
