// Every finding of the fuzz campaigns (docs/reliability.md "Fuzzing") is
// kept in fuzz/regressions/TARGET and replayed here through the same unit the
// fuzz target runs (fuzz/fuzz_units.hpp): each must load and tick cleanly or
// be refused with one error. CI runs this under ASan + UBSan too.
#include "fuzz/fuzz_units.hpp"
#include "tests/game/scene/scene_test_files.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace snow {
namespace {

namespace fs = std::filesystem;

/// The kept findings of `target` (none yet: git keeps no empty folder).
std::vector<fs::path> findings(const std::string& target) {
    std::vector<fs::path> files;
    const fs::path folder = std::string(SNOW_SOURCE_DIR) + "/fuzz/regressions/" + target;
    if (fs::is_directory(folder)) {
        for (const auto& e : fs::directory_iterator(folder)) {
            files.push_back(e.path());
        }
    }
    return files;
}

TEST(FuzzFindings, ScenesLoadOrAreRefusedCleanly) {
    std::size_t replayed = 0;
    for (const char* target : {"gltf", "glb"}) {
        for (const fs::path& file : findings(target)) {
            SCOPED_TRACE(file.string());
            EXPECT_EQ(fuzz::scene_unit(test::read_text(file.string())), "");
            ++replayed;
        }
    }
    EXPECT_GT(replayed, 0u);
}

TEST(FuzzFindings, SnapshotsRestoreOrAreRefusedCleanly) {
    const auto sim = fuzz::snapshot_scene();
    for (const fs::path& file : findings("snapshot")) {
        SCOPED_TRACE(file.string());
        const std::string bytes = test::read_text(file.string());
        EXPECT_EQ(fuzz::snapshot_unit(
                      *sim, {reinterpret_cast<const std::byte*>(bytes.data()), bytes.size()}),
                  "");
    }
    // A snapshot of the scene itself restores and runs on as the scene does:
    // the unit does not refuse everything.
    const auto fresh = fuzz::snapshot_scene();
    EXPECT_EQ(fuzz::snapshot_unit(*sim, fresh->save_bytes()), "");
    fresh->tick();
    EXPECT_EQ(sim->state_hash(), fresh->state_hash());
}

} // namespace
} // namespace snow
