// The work budget (docs/scenes.md#work-budget): a scene that declares more
// work than its host's WorkBudget allows is refused with one error naming
// the declaration and the budget, before anything is allocated; a host that
// raises the budget gets the scene.
#include "tests/game/scene/scene_test_files.hpp"

#include "game/run/run_options.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace snow {
namespace {

using test::asset_path;
using test::expect_error;
using test::read_text;

/// minimal.gltf with `edit` applied to its JSON.
template <typename Edit>
std::string minimal_with(Edit&& edit) {
    nlohmann::json doc = nlohmann::json::parse(read_text(asset_path("minimal.gltf")));
    edit(doc);
    return doc.dump();
}

nlohmann::json& snow_settings(nlohmann::json& doc) {
    return doc["scenes"][0]["extras"]["snow"];
}

SceneLoadResult load(const std::string& text, const WorkBudget& budget = {}) {
    SceneOverrides o;
    o.budget = budget;
    return load_scene_memory(text, "budget.gltf", o);
}

TEST(WorkBudget, DefaultRefusesAPoolPastItAndARaisedOneAdmitsIt) {
    const std::string text = minimal_with(
        [](nlohmann::json& d) { snow_settings(d)["simulation"]["max_flakes"] = 2000000; });
    expect_error(load(text), {"budget.gltf", "simulation.max_flakes", "2000000 flakes",
                              "allows 1048576", "SceneOverrides::budget.flakes"});
    WorkBudget raised;
    raised.flakes = 2000000;
    EXPECT_NE(load(text, raised).sim, nullptr) << load(text, raised).error;
}

TEST(WorkBudget, EachKindIsCountedAndNamed) {
    struct Case {
        const char* what;
        std::uint64_t WorkBudget::*limit;
        std::string text;
        std::string field;
    };
    const std::string minimal = read_text(asset_path("minimal.gltf"));
    const Case cases[] = {
        {"snow_cells", &WorkBudget::snow_cells, minimal, "nodes[0].extras.snow.surface.cell"},
        {"surfaces", &WorkBudget::surfaces, minimal, "nodes[0].extras.snow.surface"},
        {"flakes", &WorkBudget::flakes, minimal, "simulation.max_flakes"},
        {"collider_triangles", &WorkBudget::collider_triangles, minimal_with([](nlohmann::json& d) {
             d["nodes"][0]["extras"]["snow"]["collider"] = "mesh";
         }),
         "nodes[0].extras.snow.collider"},
        {"bodies", &WorkBudget::bodies, minimal_with([](nlohmann::json& d) {
             d["nodes"][0]["extras"]["snow"] = {{"collider", "sphere"}, {"snowball", true}};
         }),
         "nodes[0].extras.snow"},
        {"field_cells", &WorkBudget::field_cells, minimal_with([](nlohmann::json& d) {
             snow_settings(d)["wind"] = {{"base", {1, 0, 0}}, {"field", {{"cells", {8, 4, 8}}}}};
         }),
         "wind.field.cells"},
        {"field_cell_sweeps", &WorkBudget::field_cell_sweeps, minimal_with([](nlohmann::json& d) {
             snow_settings(d)["wind"] = {
                 {"base", {1, 0, 0}},
                 {"field", {{"cells", {8, 4, 8}}, {"pressure_iterations", 9}}}};
         }),
         "wind.field.pressure_iterations"},
        {"occlusion_texels", &WorkBudget::occlusion_texels, minimal_with([](nlohmann::json& d) {
             snow_settings(d)["occlusion"] = {{"resolution", 64}};
         }),
         "occlusion.resolution"},
        {"snow_cells (cover)", &WorkBudget::snow_cells, minimal_with([](nlohmann::json& d) {
             d["nodes"][0]["extras"].erase("snow");
             snow_settings(d)["cover"] = {{"min", {-5, -5}}, {"max", {5, 5}}, {"cell", 0.1}};
         }),
         "cover.cell"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        const SceneLoadResult fits = load(c.text);
        ASSERT_NE(fits.sim, nullptr) << fits.error;
        // A budget one short of what the scene declares refuses it.
        WorkBudget tight;
        tight.*c.limit = 0;
        const SceneLoadResult refused = load(c.text, tight);
        expect_error(refused, {c.field, "allows 0", "SceneOverrides::budget."});
    }
}

TEST(WorkBudget, TheScenesAtTheDefaultBudgetLoad) {
    // fuzz/make_budget_scenes.py: everything the defaults allow, at once.
    const SceneLoadResult r = load_scene_file(test::test_data_path("at_default_budget.gltf"));
    ASSERT_NE(r.sim, nullptr) << r.error;
    EXPECT_EQ(r.sim->mass().spawned, 0u);
}

TEST(WorkBudget, CommandLinePoolRaisesTheFlakeBudget) {
    std::string words[] = {"snow_run", "--max-flakes", "3000000"};
    char* argv[] = {words[0].data(), words[1].data(), words[2].data(), nullptr};
    const RunOptions o = parse_run_options(3, argv);
    EXPECT_EQ(o.overrides.budget.flakes, 3000000u);
    EXPECT_EQ(o.overrides.budget.snow_cells, WorkBudget{}.snow_cells);
}

} // namespace
} // namespace snow
