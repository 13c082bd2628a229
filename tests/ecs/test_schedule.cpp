#include "ecs/schedule.hpp"

#include <gtest/gtest.h>

namespace snow {
namespace {

struct Needed {};
struct Config {
    int value = 0;
};

TEST(EcsSchedule, RunsInOrderOfAdd) {
    World w;
    Schedule s;
    std::vector<std::string> order;
    for (const char* n : {"a", "b", "c"}) {
        s.add(n, [&order, n](World&) { order.emplace_back(n); });
    }
    s.run(w);
    s.run(w);
    EXPECT_EQ(order, (std::vector<std::string>{"a", "b", "c", "a", "b", "c"}));
    EXPECT_EQ(s.names(), (std::vector<std::string>{"a", "b", "c"}));
    for (const auto& st : s.stats()) {
        EXPECT_EQ(st.calls, 2u);
        EXPECT_EQ(st.skipped, 0u);
        EXPECT_GE(st.total_ms, 0.0);
    }
}

TEST(EcsSchedule, SkipsSystemWhoseNeedsAreMissing) {
    World w;
    Schedule s;
    int comp_runs = 0, res_runs = 0;
    s.add("needs_component", [&](World&) { ++comp_runs; }, {needs<Needed>()});
    s.add("needs_resource", [&](World&) { ++res_runs; }, {needs<Config>()});
    s.run(w);
    EXPECT_EQ(comp_runs, 0);
    EXPECT_EQ(res_runs, 0);
    EXPECT_FALSE(s.would_run("needs_component", w));
    EXPECT_EQ(s.stats()[0].calls, 0u);
    EXPECT_EQ(s.stats()[0].skipped, 1u);
    EXPECT_EQ(s.stats()[0].total_ms, 0.0); // a skipped system costs nothing

    const Entity e = w.create();
    w.add<Needed>(e);
    w.set_resource<Config>();
    s.run(w);
    EXPECT_EQ(comp_runs, 1);
    EXPECT_EQ(res_runs, 1);
    EXPECT_TRUE(s.would_run("needs_component", w));
    w.destroy(e);
    s.run(w);
    EXPECT_EQ(comp_runs, 1);
    EXPECT_EQ(s.stats()[0].calls, 1u);
}

TEST(EcsSchedule, ResetStats) {
    World w;
    Schedule s;
    s.add("x", [](World&) {});
    s.run(w);
    s.reset_stats();
    EXPECT_EQ(s.stats()[0].calls, 0u);
}

} // namespace
} // namespace snow
