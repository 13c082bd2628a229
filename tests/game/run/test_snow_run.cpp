// snow_run as a user runs it: the JSON report's fields, and the exit status
// for bad arguments.
#include "tests/support/run_app.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace {

snow::test::AppRun run(const std::string& args) {
    return snow::test::run_app("game/snow_run", args, "", false);
}

TEST(SnowRunCli, JsonReportHasEveryField) {
    const snow::test::AppRun r = run("--ticks 200 --report json --threads 2");
    ASSERT_EQ(r.status, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["ticks"], 200);
    EXPECT_EQ(j["threads"], 2);
    EXPECT_TRUE(j["scene"].is_string());
    EXPECT_TRUE(j["seed"].is_number_integer());
    EXPECT_TRUE(j["dt"].is_number_float());
    EXPECT_EQ(j["state_hash"].get<std::string>().size(), 16u);
    const auto& m = j["mass"];
    EXPECT_GT(m["unit_kg"].get<double>(), 0.0);
    EXPECT_EQ(m["spawned"].get<std::uint64_t>(),
              m["airborne"].get<std::uint64_t>() + m["settled"].get<std::uint64_t>() +
                  m["carried"].get<std::uint64_t>() + m["removed"].get<std::uint64_t>());
    EXPECT_GT(m["settled"].get<std::uint64_t>(), 0u);
    EXPECT_GT(j["flakes"]["alive"].get<int>(), 0);
    EXPECT_GE(j["flakes"]["max_alive"].get<int>(), j["flakes"]["alive"].get<int>());
    EXPECT_EQ(j["nonfinite"], 0);
    ASSERT_TRUE(j["systems"].is_array());
    std::vector<std::string> names;
    for (const auto& s : j["systems"]) {
        names.push_back(s["name"]);
        EXPECT_TRUE(s["calls"].is_number_integer());
        EXPECT_TRUE(s["total_ms"].is_number());
    }
    EXPECT_EQ(names, (std::vector<std::string>{"cover", "bodies", "order", "spawn", "wind",
                                               "wind_field", "flakes", "carve", "wind_transport",
                                               "settle", "redistribute", "spill", "occlusion"}));
}

TEST(SnowRunCli, SameHashForOneAndTwoThreads) {
    const auto one = nlohmann::json::parse(run("--ticks 300 --report json --threads 1").out);
    const auto two = nlohmann::json::parse(run("--ticks 300 --report json --threads 2").out);
    EXPECT_EQ(one["state_hash"], two["state_hash"]);
    const auto other = nlohmann::json::parse(run("--ticks 300 --report json --seed 99").out);
    EXPECT_NE(one["state_hash"], other["state_hash"]);
}

TEST(SnowRunCli, WindOverrideChangesTheRunAndStaysDeterministic) {
    const auto west = nlohmann::json::parse(run("--ticks 300 --report json").out);
    const auto south = nlohmann::json::parse(run("--ticks 300 --report json --wind 0,0,-2.5").out);
    const auto south2 =
        nlohmann::json::parse(run("--ticks 300 --report json --wind 0,0,-2.5 --threads 2").out);
    EXPECT_NE(west["state_hash"], south["state_hash"]);
    EXPECT_EQ(south["state_hash"], south2["state_hash"]);
    EXPECT_TRUE(south["mass"]["balanced"].get<bool>());
}

TEST(SnowRunCli, BadArgumentsExitWithStatus2) {
    for (const char* bad :
         {"--bogus", "--ticks -5", "--ticks abc", "--dt 0", "--dt -1", "--dt nan", "--threads 0",
          "--integrator magic", "--report xml", "--ticks", "--scene /nonexistent/scene.gltf",
          "--wind 1,2", "--wind 1,2,x", "--wind 1,2,3,4", "--wind 1000,0,0", "--wind nan,0,0"}) {
        EXPECT_EQ(run(bad).status, 2) << bad;
    }
}

} // namespace
