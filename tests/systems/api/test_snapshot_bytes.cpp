// Byte snapshots (Simulation::save_bytes / load_bytes): a restored run goes
// on bit for bit, in the same simulation or a fresh one of the same scene;
// bytes cut short, flipped, of another version or another scene are refused
// with one error naming what is wrong, and the simulation stays as it was.
#include "ecs/state_hash.hpp"
#include "systems/api/snapshot_layout.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include "tests/support/snapshot_check.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>

namespace snow {
namespace {

/// A small yard: a snapshot of a few kB, so every truncation can be tried.
std::unique_ptr<Simulation> small_yard() {
    YardOptions o;
    o.ground_cells = 16;
    o.max_flakes = 300;
    o.emitter_rate = 600.0f;
    return make_yard(o);
}

/// The checksum save_bytes ends with, recomputed after an edit (so the
/// records themselves are what a test puts to the reader).
void reseal(std::vector<std::byte>& bytes) {
    StateHasher h;
    h.bytes(bytes.data(), bytes.size() - 8);
    const std::uint64_t sum = h.digest();
    std::memcpy(bytes.data() + bytes.size() - 8, &sum, 8);
}

/// load_bytes refuses `bytes` with an error containing `words`, and `sim`
/// is left with the state hash it had.
void expect_refused(Simulation& sim, std::span<const std::byte> bytes, const std::string& words) {
    const std::uint64_t before = sim.state_hash();
    try {
        sim.load_bytes(bytes);
        ADD_FAILURE() << "accepted " << bytes.size() << " bytes";
    } catch (const SimulationError& e) {
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        EXPECT_EQ(std::string(e.field()).rfind("snapshot", 0), 0u) << e.field();
    }
    EXPECT_EQ(sim.state_hash(), before);
}

TEST(SnapshotBytes, AFreshSimulationOfTheSameSceneGoesOnBitForBit) {
    auto sim = make_stormy_yard(1);
    sim->run(120); // covers rebuilt, the field stepped, snowballs rolling, flakes landed
    const std::vector<std::byte> bytes = sim->save_bytes();
    const std::uint64_t saved = sim->state_hash();
    const std::vector<std::uint64_t> reference = test::hashes_per_tick(*sim, 90);
    const test::RunEnd reference_end = test::run_end(*sim);

    auto fresh = make_stormy_yard(2); // another thread count: the same state
    fresh->load_bytes(bytes);
    EXPECT_EQ(fresh->state_hash(), saved);
    EXPECT_EQ(test::hashes_per_tick(*fresh, 90), reference);
    EXPECT_TRUE(test::same_end(test::run_end(*fresh), reference_end));

    sim->load_bytes(bytes); // and back in the simulation that wrote them
    EXPECT_EQ(sim->state_hash(), saved);
    EXPECT_EQ(test::hashes_per_tick(*sim, 90), reference);
    EXPECT_EQ(fresh->save_bytes(), sim->save_bytes()); // the same bytes, too
}

TEST(SnapshotBytes, EveryTruncationIsRefusedAndChangesNothing) {
    auto sim = small_yard();
    sim->run(90);
    const std::vector<std::byte> bytes = sim->save_bytes();
    ASSERT_LT(bytes.size(), 64u * 1024u);
    sim->run(10);
    for (std::size_t n = 0; n < bytes.size(); ++n) {
        expect_refused(*sim, std::span(bytes).first(n), "cut short");
    }
    std::vector<std::byte> longer = bytes;
    longer.push_back(std::byte{0});
    expect_refused(*sim, longer, "past its end");
}

TEST(SnapshotBytes, FlippedBytesAreRefusedAndChangeNothing) {
    auto sim = small_yard();
    sim->run(90);
    const std::vector<std::byte> bytes = sim->save_bytes();
    sim->run(10);
    std::mt19937_64 rng(17);
    for (int trial = 0; trial < 1000; ++trial) {
        std::vector<std::byte> bad = bytes;
        const int flips = 1 + static_cast<int>(rng() % 4);
        for (int f = 0; f < flips; ++f) {
            bad[rng() % bad.size()] ^= std::byte(1u << (rng() % 8));
        }
        if (bad == bytes) {
            continue; // two flips of one bit: nothing to refuse
        }
        // The header's fields have errors of their own; everything else the checksum catches.
        const std::uint64_t before = sim->state_hash();
        EXPECT_THROW(sim->load_bytes(bad), SimulationError) << "trial " << trial;
        EXPECT_EQ(sim->state_hash(), before);
    }
}

TEST(SnapshotBytes, FlippedRecordsUnderAValidChecksumNeverBreakTheSimulation) {
    // Hostile bytes (a save file edited by hand): whatever the reader takes
    // in must keep every unit of mass and every index in range.
    auto sim = small_yard();
    sim->run(90);
    const std::vector<std::byte> bytes = sim->save_bytes();
    std::mt19937_64 rng(23);
    int accepted = 0;
    for (int trial = 0; trial < 600; ++trial) {
        std::vector<std::byte> bad = bytes;
        bad[32 + rng() % (bad.size() - 40)] ^= std::byte(1u << (rng() % 8)); // a record's byte
        reseal(bad);
        auto target = small_yard();
        try {
            target->load_bytes(bad);
        } catch (const SimulationError&) {
            continue;
        }
        ++accepted; // a flip in a value a run could have held: it must run on
        target->run(5);
        EXPECT_TRUE(target->mass().balanced()) << "trial " << trial;
    }
    EXPECT_LT(accepted, 600);
}

TEST(SnapshotBytes, AnotherVersionOrAnotherSceneIsNamed) {
    auto sim = small_yard();
    sim->run(30);
    std::vector<std::byte> bytes = sim->save_bytes();
    std::vector<std::byte> bad_magic = bytes;
    bad_magic[0] = std::byte{'X'};
    expect_refused(*sim, bad_magic, "not a snow snapshot");
    std::vector<std::byte> newer = bytes;
    newer[8] = static_cast<std::byte>(snapshot_format + 1); // a newer format
    reseal(newer);
    expect_refused(*sim, newer, "format version " + std::to_string(snapshot_format + 1));
    std::vector<std::byte> older = bytes;
    older[8] = static_cast<std::byte>(snapshot_format - 1); // an older one
    reseal(older);
    expect_refused(*sim, older, "format version " + std::to_string(snapshot_format - 1));
    auto other = make_stormy_yard(1);
    expect_refused(*other, bytes, "different scene");
    YardOptions seeded;
    seeded.ground_cells = 16;
    seeded.max_flakes = 300;
    seeded.emitter_rate = 600.0f;
    seeded.seed = 99;
    expect_refused(*make_yard(seeded), bytes, "different scene");
}

} // namespace
} // namespace snow
