#include "ecs/schedule.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace snow {
namespace {

struct Needed {};
struct Config {
    int value = 0;
};
/// What the systems below did: a system is a plain function and keeps its
/// state in the World.
struct Log {
    std::vector<std::string> order;
    int comp_runs = 0;
    int res_runs = 0;
};

TEST(EcsSchedule, RunsInOrderOfAdd) {
    World w;
    w.set_resource<Log>();
    Schedule s;
    s.add("a", [](World& world) { world.resource<Log>().order.emplace_back("a"); });
    s.add("b", [](World& world) { world.resource<Log>().order.emplace_back("b"); });
    s.add("c", [](World& world) { world.resource<Log>().order.emplace_back("c"); });
    s.run(w);
    s.run(w);
    EXPECT_EQ(w.resource<Log>().order, (std::vector<std::string>{"a", "b", "c", "a", "b", "c"}));
    std::vector<std::string> names;
    for (const auto& st : s.stats()) {
        names.emplace_back(st.name);
        EXPECT_EQ(st.calls, 2u);
        EXPECT_EQ(st.skipped, 0u);
        EXPECT_GE(st.total_ms, 0.0);
    }
    EXPECT_EQ(names, (std::vector<std::string>{"a", "b", "c"}));
}

TEST(EcsSchedule, SkipsSystemWhoseNeedsAreMissing) {
    World w;
    const Log& log = w.set_resource<Log>();
    Schedule s;
    s.add("needs_component", [](World& world) { ++world.resource<Log>().comp_runs; },
          {needs<Needed>()});
    s.add("needs_resource", [](World& world) { ++world.resource<Log>().res_runs; },
          {needs<Config>()});
    s.run(w);
    EXPECT_EQ(log.comp_runs, 0);
    EXPECT_EQ(log.res_runs, 0);
    EXPECT_FALSE(s.would_run("needs_component", w));
    EXPECT_EQ(s.stats()[0].calls, 0u);
    EXPECT_EQ(s.stats()[0].skipped, 1u);
    EXPECT_EQ(s.stats()[0].total_ms, 0.0); // a skipped system costs nothing

    const Entity e = w.create();
    w.add<Needed>(e);
    w.set_resource<Config>();
    s.run(w);
    EXPECT_EQ(log.comp_runs, 1);
    EXPECT_EQ(log.res_runs, 1);
    EXPECT_TRUE(s.would_run("needs_component", w));
    w.destroy(e);
    s.run(w);
    EXPECT_EQ(log.comp_runs, 1);
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
