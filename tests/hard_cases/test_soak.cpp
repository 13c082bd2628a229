// Hard case 10: soak. A small yard runs SNOW_SOAK_TICKS ticks (default 20 000,
// 5.6 simulated minutes; 5 000 in sanitizer/Debug builds). The full 10^6-tick
// soak (4.6 simulated hours) is run by hand:
//   SNOW_SOAK_TICKS=1000000 build/tests/snow_tests --gtest_filter='HardCase*Soak*'
// Every 1000 ticks: all flakes inside the bounds with bounded speed, no NaN,
// exact mass, the wind within its bounds, and memory flat (no storage grows
// and, on Linux, resident memory grows < 1 MiB from 10% to 100% of the run).
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"

#include "tests/scenes/sample_scenes.hpp"

#include <glm/geometric.hpp>

#include <fstream>
#include <string>
#include <vector>

namespace snow {
namespace {

/// Resident set size of this process in KiB from /proc/self/status; 0 if unknown.
std::uint64_t resident_kib() {
    std::ifstream in("/proc/self/status");
    std::string key;
    while (in >> key) {
        if (key == "VmRSS:") {
            std::uint64_t kib = 0;
            in >> kib;
            return kib;
        }
        in.ignore(1 << 16, '\n');
    }
    return 0;
}

/// Allocated sizes of every per-slot and per-cell buffer: equal means no growth.
std::vector<std::size_t> storage_sizes(const Simulation& sim) {
    const FlakePool& f = flake_pool(sim);
    std::vector<std::size_t> sizes = {f.capacity(),
                                      f.px.capacity(),
                                      f.vy.capacity(),
                                      f.k_over_m.capacity(),
                                      f.size.capacity(),
                                      f.mass_units.capacity(),
                                      f.free_stack.capacity(),
                                      world_of(sim).entity_count()};
    world_of(sim).each<SnowSurface>([&](Entity, const SnowSurface& s) {
        sizes.push_back(s.snow.size());
        sizes.push_back(s.snow.capacity());
        sizes.push_back(s.base_level.capacity());
    });
    return sizes;
}

TEST(HardCaseSoak, SmallYardStaysBoundedExactAndFlat) {
    const std::uint64_t ticks = hard::env_count("SNOW_SOAK_TICKS", hard::scaled(20000, 5000));
    const std::uint64_t check_every = 1000;
    YardOptions o;
    o.seed = 10;
    o.ground_cells = 32;
    o.max_flakes = 2000;
    o.emitter_rate = 150.0f;
    auto sim = make_yard(o);
    const SimConfig& cfg = sim->config();
    const Wind base_wind = world_of(*sim).resource<Wind>();
    const float max_speed = 50.0f; // wind 2 m/s ± 1, fall speeds up to 1.3 m/s, spills from rest
    // Warm-up: every buffer reaches its steady size in the first ticks.
    sim->run(100);
    const std::vector<std::size_t> sizes = storage_sizes(*sim);
    std::uint64_t rss_at_10 = 0, rss_at_100 = 0;
    const FlakePool& f = flake_pool(*sim);
    for (std::uint64_t t = 100; t < ticks; ++t) {
        sim->tick();
        if ((t + 1) % check_every != 0 && t + 1 != ticks) {
            continue;
        }
        ASSERT_TRUE(hard::healthy(*sim));
        for (std::uint32_t i = 0; i < f.slot_end; ++i) {
            if (!f.is_alive(i)) {
                continue;
            }
            const glm::vec3 p{f.px[i], f.py[i], f.pz[i]};
            ASSERT_TRUE(cfg.bounds.contains(p)) << "slot " << i << " tick " << t + 1;
            ASSERT_LE(glm::length(glm::vec3{f.vx[i], f.vy[i], f.vz[i]}), max_speed)
                << "slot " << i << " tick " << t + 1;
        }
        const Wind& w = world_of(*sim).resource<Wind>();
        ASSERT_LE(glm::length(w.current - base_wind.base), base_wind.max_deviation * 1.0001f);
        ASSERT_EQ(storage_sizes(*sim), sizes) << "storage grew by tick " << t + 1;
        if (rss_at_10 == 0 && t + 1 >= ticks / 10) {
            rss_at_10 = resident_kib();
        }
    }
    rss_at_100 = resident_kib();
    EXPECT_GT(sim->counters().landed, 0u);
    if (rss_at_10 != 0 && rss_at_100 != 0) {
        EXPECT_LT(rss_at_100, rss_at_10 + 1024) << "resident memory grew (KiB)";
    }
    RecordProperty("ticks", std::to_string(ticks));
    RecordProperty("rss_growth_kib", std::to_string(static_cast<long long>(rss_at_100) -
                                                    static_cast<long long>(rss_at_10)));
    RecordProperty("max_alive", std::to_string(f.max_alive));
}

} // namespace
} // namespace snow
