// The host's allocator (<snow/allocator.hpp>): every allocation of the
// simulation library goes through it, and a tick makes none. The allocator is
// process-wide, so these tests have their own executable (snow_alloc_tests);
// it also replaces the global operator new, to count what does not go
// through the hook.
#include "systems/api/simulation_internals.hpp"
#include "tests/support/counted_new.hpp"
#include "tests/support/share_work.hpp"

#include <snow/allocator.hpp>
#include <snow/scene.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace {

using snow::test::malloc_aligned;

// -- the host's allocator: counts every call, takes its memory from malloc --

struct HostCounts {
    std::atomic<std::uint64_t> allocations{0};
    std::atomic<std::uint64_t> frees{0};
    std::atomic<std::int64_t> bytes{0};
};

void* counting_allocate(std::size_t size, std::size_t alignment, void* user) {
    auto* counts = static_cast<HostCounts*>(user);
    counts->allocations.fetch_add(1, std::memory_order_relaxed);
    counts->bytes.fetch_add(static_cast<std::int64_t>(size), std::memory_order_relaxed);
    return malloc_aligned(size, alignment);
}

void counting_free(void* p, std::size_t size, std::size_t, void* user) {
    auto* counts = static_cast<HostCounts*>(user);
    counts->frees.fetch_add(1, std::memory_order_relaxed);
    counts->bytes.fetch_sub(static_cast<std::int64_t>(size), std::memory_order_relaxed);
    std::free(p);
}

} // namespace

namespace snow {
namespace {

using test::counting_new;
using test::new_calls;

/// Installs a counting allocator for one test and takes it out again (once
/// the test destroyed every Simulation it made).
class HostAllocatorTest : public ::testing::Test {
  protected:
    void SetUp() override {
        ASSERT_EQ(live_allocations(), 0u) << "a test before left memory in the library";
        set_allocator(Allocator{counting_allocate, counting_free, &counts_});
    }
    void TearDown() override { reset_allocator(); }

    HostCounts counts_;
};

std::unique_ptr<Simulation> load_village(unsigned threads) {
    SceneOverrides o;
    o.threads = threads;
    SceneLoadResult r =
        load_scene_file(std::string(SNOW_SOURCE_DIR) + "/assets/scenes/village.gltf", o);
    EXPECT_TRUE(r.sim) << r.error;
    return std::move(r.sim);
}

TEST_F(HostAllocatorTest, VillageTicksAllocateNothingFromTheFirst) {
    std::uint64_t hashes[2] = {0, 0};
    for (const unsigned threads : {1u, 2u}) {
        const std::uint64_t before = counts_.allocations.load();
        auto sim = load_village(threads);
        ASSERT_TRUE(sim);
        // Loading went through the hook; what the library holds is what the host gave.
        EXPECT_GT(counts_.allocations.load(), before);
        EXPECT_GT(live_allocations(), 0u);
        EXPECT_EQ(static_cast<std::int64_t>(allocated_bytes()), counts_.bytes.load());
        if (threads == 2) {
            test::share_work_at_any_size(*sim); // the second thread takes chunks too
        }

        const std::uint64_t loaded = counts_.allocations.load();
        new_calls = 0;
        counting_new = true;
        sim->run(1000);
        counting_new = false;
        EXPECT_EQ(counts_.allocations.load(), loaded) << threads << " thread(s)";
        EXPECT_EQ(new_calls.load(), 0u) << threads << " thread(s)";

        // The ticks did the village's work: every system it declares ran.
        for (const SystemStats& s : schedule_of(*sim).stats()) {
            if (s.name != "wind_field" && s.name != "wind_transport") {
                EXPECT_GT(s.calls, 0u) << s.name;
            }
        }
        EXPECT_GT(sim->counters().landed, 0u);
        EXPECT_GT(sim->counters().occlusion_refreshes, 0u);
        EXPECT_GT(sim->counters().carved_units, 0u);
        EXPECT_TRUE(sim->mass().balanced());
        hashes[threads - 1] = sim->state_hash();

        sim.reset();
        EXPECT_EQ(live_allocations(), 0u) << "the library kept memory of a destroyed Simulation";
        EXPECT_EQ(allocated_bytes(), 0u);
        EXPECT_EQ(counts_.allocations.load(), counts_.frees.load());
        EXPECT_EQ(counts_.bytes.load(), 0);
    }
    EXPECT_EQ(hashes[0], hashes[1]);
}

TEST_F(HostAllocatorTest, TheLibraryAllocatesOnlyThroughTheHook) {
    // A scene with every kind of thing (a wind field with transport, a
    // cover, a body, meshes), built, run, changed, saved, loaded and
    // destroyed through the facade on one thread (the built-in pool of more
    // starts std::threads, whose start-up state the C++ library allocates).
    // Only the bytes save_bytes returns are the host's. No tick allocates,
    // the first after each change included.
    std::vector<glm::vec3> shelter{{-6.0f, 2.0f, 1.0f}, {-2.0f, 2.0f, 1.0f}, {-2.0f, 2.5f, 5.0f}};
    SimConfig config;
    config.max_flakes = 20000;
    std::optional<Simulation> sim; // in place: the Simulation object itself is the host's
    new_calls = 0;
    counting_new = true;
    sim.emplace(config);
    SurfaceDef ground;
    ground.x0 = -8.0f;
    ground.z0 = -8.0f;
    ground.size_x = 16.0f;
    ground.size_z = 16.0f;
    ground.cell = 0.25f;
    const SurfaceId ground_id = sim->add_surface(ground);
    const ColliderId box = sim->add_box(Aabb{{1.0f, 0.0f, 1.0f}, {2.0f, 1.0f, 2.0f}});
    sim->add_sphere({-3.0f, 0.5f, -3.0f}, 0.5f);
    sim->add_mesh_collider(std::move(shelter));
    CoverDef cover;
    cover.min_x = 2.5f;
    cover.min_z = 2.5f;
    cover.max_x = 5.0f;
    cover.max_z = 5.0f;
    sim->add_cover(cover);
    BodyDef walker;
    walker.position = {-5.4f, 0.3f, -5.4f}; // on the pile added below
    walker.on_ground = true;
    const BodyId body = sim->add_body(walker);
    sim->set_body_velocity(body, {0.5f, 0.0f, 0.0f});
    Wind wind;
    wind.base = wind.current = {2.0f, 0.0f, 0.5f};
    sim->set_wind(wind);
    WindFieldDef field;
    field.cells_x = 16;
    field.cells_y = 8;
    field.cells_z = 16;
    sim->set_wind_field(field);
    sim->set_wind_transport(WindTransportDef{});
    OcclusionCamera camera;
    camera.resolution = 64;
    camera.tilt = 0.3f;
    sim->set_occlusion(camera);
    Emitter emitter;
    emitter.rate = 4000.0f;
    sim->add_emitter(emitter);
    sim->add_settled_snow(ground_id, 10, 10, 5000); // the cell under the walker
    // Hook calls in the ticks after building and after each change; checked
    // once counting stopped (a failed check allocates).
    std::uint64_t in_ticks[4] = {};
    const auto ticks_allocate = [&](std::uint64_t ticks) {
        const std::uint64_t before = counts_.allocations.load();
        sim->run(ticks);
        return counts_.allocations.load() - before;
    };
    in_ticks[0] = ticks_allocate(200);
    sim->move_box(box, Aabb{{1.5f, 0.0f, 1.5f}, {2.5f, 1.0f, 2.5f}});
    in_ticks[1] = ticks_allocate(20);
    counting_new = false;
    const std::vector<std::byte> bytes = sim->save_bytes();
    counting_new = true;
    sim->run(20);
    sim->load_bytes(bytes);
    in_ticks[2] = ticks_allocate(20);
    sim->remove(box);
    sim->add_sphere({3.0f, 0.5f, -3.0f}, 0.75f);
    in_ticks[3] = ticks_allocate(20);
    const SimCounters counters = sim->counters();
    sim.reset();
    counting_new = false;
    EXPECT_EQ(new_calls.load(), 0u) << "snow called the global operator new";
    EXPECT_EQ(in_ticks[0], 0u) << "after building";
    EXPECT_EQ(in_ticks[1], 0u) << "after move_box";
    EXPECT_EQ(in_ticks[2], 0u) << "after load_bytes";
    EXPECT_EQ(in_ticks[3], 0u) << "after remove and add_sphere";
    EXPECT_GT(counters.landed, 0u);
    EXPECT_GT(counters.carved_units, 0u);
    EXPECT_GT(counts_.allocations.load(), 0u);
    EXPECT_EQ(live_allocations(), 0u);
}

TEST_F(HostAllocatorTest, RefusesToChangeWhileTheLibraryHoldsMemory) {
    auto sim = std::make_unique<Simulation>();
    ASSERT_GT(live_allocations(), 0u);
    HostCounts other;
    try {
        set_allocator(Allocator{counting_allocate, counting_free, &other});
        FAIL() << "set_allocator accepted a new allocator while memory was live";
    } catch (const SimulationError& e) {
        EXPECT_NE(std::string(e.what()).find("destroy every Simulation first"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(reset_allocator(), SimulationError);
    sim->run(10); // still on the first allocator, which it frees to
    sim.reset();
    EXPECT_EQ(other.allocations.load(), 0u);
    EXPECT_EQ(live_allocations(), 0u);
    EXPECT_EQ(counts_.allocations.load(), counts_.frees.load());
    reset_allocator(); // accepted now (TearDown resets again: nothing is live)
}

TEST_F(HostAllocatorTest, RefusesNullFunctions) {
    const auto refused = [](const Allocator& a) -> std::string {
        try {
            set_allocator(a);
        } catch (const SimulationError& e) {
            return e.what();
        }
        return "accepted";
    };
    EXPECT_EQ(refused(Allocator{nullptr, counting_free, nullptr}),
              "set_allocator(allocator) has no allocate function");
    EXPECT_EQ(refused(Allocator{counting_allocate, nullptr, nullptr}),
              "set_allocator(allocator) has no free function");
    EXPECT_EQ(refused(Allocator{}), "set_allocator(allocator) has no allocate function");
    // The allocator in place stays.
    auto sim = std::make_unique<Simulation>();
    EXPECT_GT(counts_.allocations.load(), 0u);
}

TEST(HostAllocatorDefault, CountsWhatTheDefaultGives) {
    ASSERT_EQ(live_allocations(), 0u);
    auto sim = std::make_unique<Simulation>();
    EXPECT_GT(live_allocations(), 0u);
    EXPECT_GT(allocated_bytes(), 0u);
    sim.reset();
    EXPECT_EQ(live_allocations(), 0u);
    EXPECT_EQ(allocated_bytes(), 0u);
}

} // namespace
} // namespace snow
