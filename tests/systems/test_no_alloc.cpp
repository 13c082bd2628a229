// No allocation inside a tick after warm-up (issue #8): the global operator
// new is replaced by one that counts calls while `counting` is set; ticks of
// a warmed-up scene in which every system runs and does real work (flakes
// spawn, land, roll, smooth, spill, hit the sphere, and the sky map refreshes
// as the wind turns) must make none, on 1 and on 2 threads.
#include "systems/sample_scenes.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <vector>

namespace {

std::atomic<bool> counting{false};
std::atomic<std::uint64_t> allocations{0};

void* counted_alloc(std::size_t size, std::size_t align) noexcept {
    if (counting.load(std::memory_order_relaxed)) {
        allocations.fetch_add(1, std::memory_order_relaxed);
    }
    size = size == 0 ? 1 : size;
    if (align <= alignof(std::max_align_t)) {
        return std::malloc(size);
    }
    return std::aligned_alloc(align, (size + align - 1) / align * align);
}

void* counted_alloc_or_throw(std::size_t size, std::size_t align) {
    void* p = counted_alloc(size, align);
    if (p == nullptr) {
        throw std::bad_alloc();
    }
    return p;
}

} // namespace

// Every replaceable allocation form routes through counted_alloc; every
// deallocation form frees with std::free (malloc and aligned_alloc agree).
void* operator new(std::size_t n) {
    return counted_alloc_or_throw(n, 0);
}
void* operator new[](std::size_t n) {
    return counted_alloc_or_throw(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a) {
    return counted_alloc_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return counted_alloc_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    return counted_alloc(n, 0);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    return counted_alloc(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return counted_alloc(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return counted_alloc(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}

namespace snow {
namespace {

/// Puts snow over the edge limit along one border of every spilling surface
/// (as an embedder might), so the next tick spills.
void overload_edges(Simulation& sim) {
    World& w = sim.world();
    w.each<SnowSurface>([&](Entity, SnowSurface& s) {
        if (!s.spills) {
            return;
        }
        const std::uint32_t units = 2 * s.edge_limit_units + 5000;
        for (std::uint32_t ix = 0; ix < s.nx; ++ix) {
            s.snow[s.index(ix, 0)] += units;
            w.resource<MassLedger>().spawned += units;
            s.mark_dirty(ix, 0);
        }
    });
}

/// The yard with everything switched on: emitter, walking and gusting wind
/// with a wind field,
/// a mesh roof over the snowman seen through a tilted sky camera, and a
/// garage roof whose edge is over its limit (so it spills at once).
std::unique_ptr<Simulation> busy_scene(unsigned threads) {
    YardOptions o;
    o.threads = threads;
    o.max_flakes = 60000;
    o.prefill = 40000; // more than two chunks of flake_grain: both threads work
    o.emitter_rate = 6000.0f;
    auto sim = make_yard(o);
    Wind wind;
    wind.base = wind.current = {2.0f, 0.0f, 0.5f};
    wind.walk = 1.0f;
    wind.max_deviation = 1.5f;
    wind.gust_strength = 2.0f;
    wind.gust_rate = 0.5f;
    sim->set_wind(wind);
    sim->set_wind_field(WindFieldDef{});
    const glm::vec3 a{-6.0f, 2.0f, 1.0f}, b{-2.0f, 2.0f, 1.0f}, c{-2.0f, 2.5f, 5.0f},
        d{-6.0f, 2.5f, 5.0f};
    sim->add_mesh_collider({a, b, c, a, c, d});
    OcclusionCamera cam;
    cam.resolution = 128;
    cam.tilt = 0.4f; // the map leans with the wind: refreshes as it turns
    sim->set_occlusion(cam);
    overload_edges(*sim);
    return sim;
}

TEST(NoAllocation, WarmTicksWithEverySystemAllocateNothing) {
    for (const unsigned threads : {1u, 2u}) {
        auto sim = busy_scene(threads);
        sim->run(240); // warm-up: scratch buffers reach their working sizes
        overload_edges(*sim);
        const SimCounters before = sim->counters();
        std::vector<std::uint64_t> calls;
        for (const SystemStats& s : sim->schedule().stats()) {
            calls.push_back(s.calls);
        }
        allocations = 0;
        counting = true;
        sim->run(120);
        counting = false;
        EXPECT_EQ(allocations.load(), 0u) << threads << " thread(s)";

        // Every system ran in the counted ticks, and did work.
        const auto& stats = sim->schedule().stats();
        for (std::size_t i = 0; i < stats.size(); ++i) {
            EXPECT_EQ(stats[i].calls, calls[i] + 120) << stats[i].name;
        }
        const SimCounters& after = sim->counters();
        EXPECT_GT(after.landed, before.landed);
        EXPECT_GT(after.rolled, before.rolled);
        EXPECT_GT(after.smoothing_iterations, before.smoothing_iterations);
        EXPECT_GT(after.spilled_units, before.spilled_units);
        EXPECT_GT(after.occlusion_refreshes, before.occlusion_refreshes);
        EXPECT_GT(sim->mass().removed, 0u);
        EXPECT_TRUE(sim->mass().balanced());
    }
}

TEST(NoAllocation, CounterSeesAllocations) {
    // The instrument works: a vector growing under counting is seen.
    allocations = 0;
    counting = true;
    std::vector<int> v;
    v.resize(1000);
    counting = false;
    EXPECT_GE(allocations.load(), 1u);
}

} // namespace
} // namespace snow
