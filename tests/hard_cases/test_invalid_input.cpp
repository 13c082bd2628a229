// Hard case 11: NaN, ±inf, negative and zero values through every door: the
// Simulation API (SimulationError naming the field, state exactly unchanged: Box2D's
// test_invalid_input pattern), a scene file (an error naming the file and the
// field, no Simulation), and snow_run's flags (exit status 2, the flag named).
#include "hard_case_util.hpp"
#include "systems/api/simulation_internals.hpp"

#include "render/visual_rules.hpp"
#include "systems/core/units.hpp"
#include "systems/geometry/colliders.hpp"
#include "tests/scenes/sample_scenes.hpp"
#include <snow/scene.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace snow {
namespace {

constexpr float nan_v = std::numeric_limits<float>::quiet_NaN();
constexpr float inf_v = std::numeric_limits<float>::infinity();

/// What a field accepts; each rule implies the bad values tried against it.
enum class Rule { finite, non_negative, positive };

/// The values a field with rule `r` must reject.
std::vector<float> bad_values(Rule r) {
    switch (r) {
    case Rule::finite:
        return {nan_v, inf_v, -inf_v};
    case Rule::non_negative:
        return {nan_v, inf_v, -inf_v, -1.0f, -1e-30f};
    case Rule::positive:
        return {nan_v, inf_v, -inf_v, -1.0f, 0.0f, -0.0f};
    }
    return {};
}

/// One settable number of the API: the name its error must contain and a call
/// that passes `v` in that field (everything else valid).
struct Field {
    std::string name;
    Rule rule;
    std::function<void(Simulation&, float)> call;
};

/// A call that builds a default `Def`, applies `set` and hands it to the API.
template <typename Def, typename Setter>
std::function<void(Simulation&, float)> with(Setter set) {
    return [set](Simulation& sim, float v) {
        Def d;
        set(d, v);
        if constexpr (std::is_same_v<Def, Emitter>) {
            sim.add_emitter(d);
        } else if constexpr (std::is_same_v<Def, Wind>) {
            sim.set_wind(d);
        } else if constexpr (std::is_same_v<Def, SurfaceDef>) {
            sim.add_surface(d);
        } else if constexpr (std::is_same_v<Def, Fog> || std::is_same_v<Def, SpectralSnow>) {
            throw_if(validate(d)); // render-only: the scene loader and renderer check them so
        } else {
            sim.set_occlusion(d);
        }
    };
}

/// The id of the first entity that has a T (the running yard has one of each used here).
template <typename T, typename IdType>
IdType first_with(const Simulation& sim) {
    Entity found = null_entity;
    world_of(sim).each<T>([&](Entity e, const T&) { found = found.is_null() ? e : found; });
    return id_of<IdType>(found);
}

/// A flake placed with `set` applied to an otherwise valid FlakeSpec.
template <typename Setter>
std::function<void(Simulation&, float)> flake_with(Setter set) {
    return [set](Simulation& sim, float v) {
        FlakeSpec f;
        f.position = {0.0f, 5.0f, 0.0f};
        set(f, v);
        (void)sim.place_flake(f);
    };
}

/// A box collider without a snow surface, to move around.
ColliderId free_box(const Simulation& sim) {
    Entity found = null_entity;
    world_of(sim).each<BoxCollider>([&](Entity e, const BoxCollider&) {
        if (found.is_null() && !world_of(sim).has<SnowHolder>(e)) {
            found = e;
        }
    });
    return id_of<ColliderId>(found);
}

/// Every number the API takes that has a validity rule.
std::vector<Field> api_fields() {
    using R = Rule;
    return {
        {"emitter.rate", R::non_negative,
         [](Simulation& s, float v) { s.set_emitter_rate(first_with<Emitter, EmitterId>(s), v); }},
        {"box.max.z", R::finite,
         [](Simulation& s, float v) {
             s.move_box(free_box(s), {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, v}});
         }},
        {"flake.position.x", R::finite,
         flake_with([](FlakeSpec& f, float v) { f.position.x = v; })},
        {"flake.velocity.y", R::finite,
         flake_with([](FlakeSpec& f, float v) { f.velocity.y = v; })},
        {"flake.k_over_m", R::positive, flake_with([](FlakeSpec& f, float v) { f.k_over_m = v; })},
        {"flake.size", R::non_negative, flake_with([](FlakeSpec& f, float v) { f.size = v; })},
        {"emitter.rate", R::non_negative, with<Emitter>([](Emitter& e, float v) { e.rate = v; })},
        {"emitter.snowfall_kg_m2_h", R::non_negative,
         with<Emitter>([](Emitter& e, float v) { e.snowfall_kg_m2_h = v; })},
        {"emitter.size_mean", R::positive,
         with<Emitter>([](Emitter& e, float v) { e.size_mean = v; })},
        {"emitter.size_min", R::positive,
         with<Emitter>([](Emitter& e, float v) { e.size_min = v; })},
        {"emitter.size_max", R::positive,
         with<Emitter>([](Emitter& e, float v) { e.size_max = v; })},
        {"wind.base.x", R::finite, with<Wind>([](Wind& w, float v) { w.base.x = v; })},
        {"wind.base.y", R::finite, with<Wind>([](Wind& w, float v) { w.base.y = v; })},
        {"wind.current.z", R::finite, with<Wind>([](Wind& w, float v) { w.current.z = v; })},
        {"wind.deviation.x", R::finite, with<Wind>([](Wind& w, float v) { w.deviation.x = v; })},
        {"wind.walk", R::non_negative, with<Wind>([](Wind& w, float v) { w.walk = v; })},
        {"wind.max_deviation", R::non_negative,
         with<Wind>([](Wind& w, float v) { w.max_deviation = v; })},
        {"wind.gust_strength", R::non_negative,
         with<Wind>([](Wind& w, float v) { w.gust_strength = v; })},
        {"wind.gust_rate", R::non_negative, with<Wind>([](Wind& w, float v) { w.gust_rate = v; })},
        {"wind.gust_duration", R::positive,
         with<Wind>([](Wind& w, float v) { w.gust_duration = v; })},
        {"wind.gust_left", R::non_negative, with<Wind>([](Wind& w, float v) { w.gust_left = v; })},
        {"surface.x0", R::finite, with<SurfaceDef>([](SurfaceDef& d, float v) { d.x0 = v; })},
        {"surface.z0", R::finite, with<SurfaceDef>([](SurfaceDef& d, float v) { d.z0 = v; })},
        {"surface.size_x", R::positive,
         with<SurfaceDef>([](SurfaceDef& d, float v) { d.size_x = v; })},
        {"surface.size_z", R::positive,
         with<SurfaceDef>([](SurfaceDef& d, float v) { d.size_z = v; })},
        {"surface.cell", R::positive, with<SurfaceDef>([](SurfaceDef& d, float v) { d.cell = v; })},
        {"surface.base_y", R::finite,
         with<SurfaceDef>([](SurfaceDef& d, float v) { d.base_y = v; })},
        {"surface.slope_x", R::finite,
         with<SurfaceDef>([](SurfaceDef& d, float v) { d.slope_x = v; })},
        {"surface.slope_z", R::finite,
         with<SurfaceDef>([](SurfaceDef& d, float v) { d.slope_z = v; })},
        {"surface.edge_limit", R::non_negative,
         with<SurfaceDef>([](SurfaceDef& d, float v) { d.edge_limit = v; })},
        {"surface.laplacian_limit", R::positive,
         with<SurfaceDef>([](SurfaceDef& d, float v) { d.laplacian_limit = v; })},
        {"box.min.x", R::finite,
         [](Simulation& s, float v) {
             s.add_box({{v, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}});
         }},
        {"box.max.y", R::finite,
         [](Simulation& s, float v) {
             s.add_box({{0.0f, 0.0f, 0.0f}, {1.0f, v, 1.0f}});
         }},
        {"sphere.center.z", R::finite,
         [](Simulation& s, float v) {
             s.add_sphere({0.0f, 1.0f, v}, 0.5f);
         }},
        {"sphere.radius", R::positive,
         [](Simulation& s, float v) {
             s.add_sphere({0.0f, 1.0f, 0.0f}, v);
         }},
        {"mesh.triangles[1]", R::finite,
         [](Simulation& s, float v) {
             s.add_mesh_collider({{0.0f, 1.0f, 0.0f}, {1.0f, v, 0.0f}, {0.0f, 1.0f, 1.0f}});
         }},
        {"occlusion.tilt", R::finite,
         with<OcclusionCamera>([](OcclusionCamera& c, float v) { c.tilt = v; })},
        {"fog.color.y", R::finite, with<Fog>([](Fog& f, float v) { f.color.y = v; })},
        {"fog.density", R::non_negative, with<Fog>([](Fog& f, float v) { f.density = v; })},
        {"fog.half_distance", R::positive, with<Fog>([](Fog& f, float v) { f.half_distance = v; })},
        {"fog.layer_density", R::non_negative,
         with<Fog>([](Fog& f, float v) { f.layer_density = v; })},
        {"fog.puffs[0].sigma", R::positive, with<Fog>([](Fog& f, float v) {
             f.puffs.push_back(FogPuff{});
             f.puffs[0].sigma = v;
         })},
        {"spectral.speed", R::positive,
         with<SpectralSnow>([](SpectralSnow& s, float v) { s.speed = v; })},
        {"spectral.opacity", R::non_negative,
         with<SpectralSnow>([](SpectralSnow& s, float v) { s.opacity = v; })},
        {"spectral.start_distance", R::non_negative,
         with<SpectralSnow>([](SpectralSnow& s, float v) { s.start_distance = v; })},
    };
}

/// Everything a rejected call could have touched, hashed or not.
struct Observed {
    std::uint64_t hash;
    std::size_t entities;
    SourceVersions sources;
    bool occlusion;
    friend bool operator==(const Observed&, const Observed&) = default;
};

/// The observable state of `sim`.
Observed observe(const Simulation& sim) {
    const World& w = world_of(sim);
    return {sim.state_hash(), w.entity_count(), w.resource<SourceVersions>(),
            w.has_resource<OcclusionCamera>()};
}

/// A small sample yard with a free-standing shed after 30 ticks.
std::unique_ptr<Simulation> running_yard() {
    YardOptions o;
    o.seed = 11;
    o.ground_cells = 32;
    o.max_flakes = 4000;
    auto sim = make_yard(o);
    sim->add_box({{-7.0f, 0.0f, -7.0f}, {-6.0f, 1.0f, -6.0f}});
    sim->run(30);
    return sim;
}

TEST(HardCaseInvalidInput, ApiRejectsEveryBadNumberAndLeavesTheStateAlone) {
    auto sim = running_yard();
    auto twin = running_yard(); // never sees bad input
    const Observed before = observe(*sim);
    int rejected = 0;
    for (const Field& field : api_fields()) {
        for (const float v : bad_values(field.rule)) {
            SCOPED_TRACE(::testing::Message() << field.name << " = " << v);
            try {
                field.call(*sim, v);
                ADD_FAILURE() << "accepted";
            } catch (const SimulationError& e) {
                EXPECT_NE(std::string(e.what()).find(field.name), std::string::npos)
                    << "message does not name the field: " << e.what();
                EXPECT_EQ(e.field().rfind(field.name, 0), 0u) << "field() is " << e.field();
                ++rejected;
            }
            ASSERT_EQ(observe(*sim), before) << "a rejected call changed the simulation";
        }
    }
    // Ids: null, never created, or forged from another kind's bits.
    EXPECT_THROW(sim->remove(BodyId{}), SimulationError);
    EXPECT_THROW(sim->remove(ColliderId{}), SimulationError);
    EXPECT_THROW(sim->add_surface(SurfaceDef{}, id_of<ColliderId>(Entity::make(4000, 3))),
                 SimulationError);
    EXPECT_THROW(sim->set_emitter_rate(EmitterId{}, 10.0f), SimulationError);
    EXPECT_THROW(sim->set_emitter_rate(id_of<EmitterId>(entity_of(free_box(*sim))), 10.0f),
                 SimulationError);
    EXPECT_THROW(
        (void)sim->surface(id_of<SurfaceId>(entity_of(first_with<Emitter, EmitterId>(*sim)))),
        SimulationError);
    // A box carrying snow cannot move; hand-added snow must fit its surface and cell.
    const auto garage = first_with<SnowHolder, ColliderId>(*sim);
    EXPECT_THROW(sim->move_box(garage, {{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}), SimulationError);
    const auto ground = first_with<SurfaceOf, SurfaceId>(*sim);
    const SnowSurface& g = snow_surface(*sim, ground);
    EXPECT_THROW(sim->add_settled_snow(ground, g.nx, 0, 1), SimulationError);
    EXPECT_THROW(sim->add_settled_snow(ground, 0, g.nz, 1), SimulationError);
    EXPECT_THROW(sim->add_settled_snow(ground, 0, 0, 0), SimulationError);
    for (const std::uint32_t units : {0u, max_flake_units + 1}) {
        FlakeSpec f;
        f.mass_units = units;
        try {
            (void)sim->place_flake(f);
            ADD_FAILURE() << "mass_units " << units << " accepted";
        } catch (const SimulationError& e) {
            EXPECT_EQ(e.field(), "flake.mass_units") << e.what();
        }
    }
    // An integrator value outside the enum would match no rule and freeze every flake.
    try {
        sim->set_integrator(static_cast<Integrator>(200));
        ADD_FAILURE() << "integrator 200 accepted";
    } catch (const SimulationError& e) {
        EXPECT_EQ(e.field(), "simulation.integrator") << e.what();
    }
    EXPECT_EQ(observe(*sim), before);
    EXPECT_GT(rejected, 150);
    RecordProperty("rejected", rejected);
    // Nothing hidden changed either: the two run on identically.
    for (int t = 0; t < 60; ++t) {
        sim->tick();
        twin->tick();
        ASSERT_EQ(sim->state_hash(), twin->state_hash()) << "tick " << t;
    }
    ASSERT_TRUE(hard::healthy(*sim));
}

TEST(HardCaseInvalidInput, HandAddedSnowStopsAtTheCellLimit) {
    Simulation sim;
    SurfaceDef d;
    d.spills = false;
    const SurfaceId e = sim.add_surface(d);
    sim.add_settled_snow(e, 3, 4, max_cell_units - 5);
    try {
        sim.add_settled_snow(e, 3, 4, 6);
        ADD_FAILURE() << "a cell past max_cell_units accepted";
    } catch (const SimulationError& err) {
        EXPECT_EQ(err.field(), "add_settled_snow(units)") << err.what();
    }
    sim.add_settled_snow(e, 3, 4, 5);
    EXPECT_EQ(snow_surface(sim, e).snow[snow_surface(sim, e).index(3, 4)], max_cell_units);
    EXPECT_THROW(sim.add_settled_snow(e, 3, 4, 1), SimulationError);
    EXPECT_TRUE(sim.mass().balanced());
    EXPECT_EQ(sim.mass().settled, max_cell_units);
}

TEST(HardCaseInvalidInput, BadSimConfigNeverMakesASimulation) {
    struct Bad {
        std::string name;
        Rule rule;
        std::function<void(SimConfig&, float)> set;
    };
    const std::vector<Bad> bad = {
        {"simulation.dt", Rule::positive, [](SimConfig& c, float v) { c.dt = v; }},
        {"simulation.gravity.y", Rule::finite, [](SimConfig& c, float v) { c.gravity.y = v; }},
        {"simulation.bounds.min.x", Rule::finite,
         [](SimConfig& c, float v) { c.bounds.min.x = v; }},
        {"simulation.bounds.max.z", Rule::finite,
         [](SimConfig& c, float v) { c.bounds.max.z = v; }},
    };
    for (const Bad& b : bad) {
        for (const float v : bad_values(b.rule)) {
            SCOPED_TRACE(::testing::Message() << b.name << " = " << v);
            SimConfig c;
            b.set(c, v);
            try {
                Simulation sim(c);
                ADD_FAILURE() << "accepted";
            } catch (const SimulationError& e) {
                EXPECT_NE(std::string(e.what()).find(b.name), std::string::npos) << e.what();
            }
        }
    }
    SimConfig no_pool;
    no_pool.max_flakes = 0; // a pool that can never hold a flake
    try {
        Simulation sim(no_pool);
        ADD_FAILURE() << "max_flakes 0 accepted";
    } catch (const SimulationError& e) {
        EXPECT_NE(std::string(e.what()).find("simulation.max_flakes"), std::string::npos)
            << e.what();
    }
}

/// A whole file as text.
std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream os;
    os << in.rdbuf();
    return os.str();
}

/// The minimal scene with one value replaced (the original text must be present).
std::string minimal_with(const std::string& from, const std::string& to) {
    std::string text = read_text(std::string(SNOW_SOURCE_DIR) + "/assets/scenes/minimal.gltf");
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "test setup: '" << from << "' not in minimal.gltf";
    if (at != std::string::npos) {
        text.replace(at, from.size(), to);
    }
    return text;
}

/// A bad value in a scene file and what its error must contain.
struct SceneEdit {
    std::string from, to, expect;
};

const std::vector<SceneEdit>& scene_edits() {
    // JSON has no NaN or infinity: such text fails as JSON (no field to name);
    // values past float range and negative ones are named by their field path.
    static const std::vector<SceneEdit> edits = {
        {"\"dt\": 0.016666666666666666", "\"dt\": -0.5", "simulation.dt"},
        {"\"dt\": 0.016666666666666666", "\"dt\": 0", "simulation.dt"},
        {"\"dt\": 0.016666666666666666", "\"dt\": NaN", "not valid JSON"},
        {"\"dt\": 0.016666666666666666", "\"dt\": 1e999", "not valid JSON"},
        {"\"dt\": 0.016666666666666666", "\"dt\": 1e39", "simulation.dt"},
        {"\"dt\": 0.016666666666666666", "\"dt\": 0.02, \"air_temperature\": -81",
         "simulation.air_temperature"},
        {"\"dt\": 0.016666666666666666", "\"dt\": 0.02, \"air_temperature\": 41",
         "simulation.air_temperature"},
        {"\"max_flakes\": 5000", "\"max_flakes\": -5", "simulation.max_flakes"},
        {"\"rate\": 1000.0", "\"rate\": -1000.0", "emitter.rate"},
        {"\"snowfall_kg_m2_h\": 5.0", "\"snowfall_kg_m2_h\": -5.0", "emitter.snowfall_kg_m2_h"},
        {"\"size_mean\": 0.004", "\"size_mean\": -1e39", "emitter.size_mean"},
        {"\"cell\": 0.1", "\"cell\": -0.1", "surface.cell"},
        {"\"cell\": 0.1", "\"cell\": 0", "surface.cell"},
        {"\"edge_limit\": 0.1", "\"edge_limit\": -0.1", "surface.edge_limit"},
        {"\"edge_limit\": 0.1", "\"edge_limit\": -1e999", "not valid JSON"},
        // Past float range after the node transform: named by the node.
        {"\"translation\": [0.0, -0.1, 0.0]", "\"translation\": [0.0, -1e39, 0.0]", "nodes[0]"},
    };
    return edits;
}

TEST(HardCaseInvalidInput, SceneWithBadNumberNamesTheFieldAndBuildsNothing) {
    for (const SceneEdit& e : scene_edits()) {
        SCOPED_TRACE(e.to);
        const SceneLoadResult r = load_scene_memory(minimal_with(e.from, e.to), "bad.gltf");
        EXPECT_EQ(r.sim, nullptr);
        EXPECT_NE(r.error.find("bad.gltf"), std::string::npos) << r.error;
        EXPECT_NE(r.error.find(e.expect), std::string::npos) << r.error;
    }
}

struct CliRun {
    int status = -1;
    std::string output; ///< stdout and stderr
};

/// Runs snow_run with `args`; stdout and stderr together.
CliRun run_snow_run(const std::string& args) {
    const std::string exe = std::string(SNOW_BINARY_DIR) + "/game/snow_run";
    CliRun r;
    FILE* p = popen((exe + " " + args + " 2>&1").c_str(), "r");
    if (p == nullptr) {
        return r;
    }
    std::array<char, 4096> buf{};
    while (std::fgets(buf.data(), buf.size(), p) != nullptr) {
        r.output += buf.data();
    }
    const int raw = pclose(p);
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    return r;
}

/// snow_run was built (SNOW_BUILD_GAME).
bool have_snow_run() {
    return std::filesystem::exists(std::string(SNOW_BINARY_DIR) + "/game/snow_run");
}

TEST(HardCaseInvalidInput, SnowRunFlagsWithBadNumbersExitWithStatus2) {
    if (!have_snow_run()) {
        GTEST_SKIP() << "snow_run not built (SNOW_BUILD_GAME=OFF)";
    }
    struct Flag {
        std::string args, names;
    };
    const std::vector<Flag> flags = {
        {"--dt nan", "--dt"},
        {"--dt -nan", "--dt"},
        {"--dt inf", "--dt"},
        {"--dt -inf", "--dt"},
        {"--dt -0.5", "--dt"},
        {"--dt 0", "--dt"},
        {"--dt -0", "--dt"},
        {"--dt 1e400", "--dt"},
        {"--dt 2", "--dt"},
        {"--dt 1e-50", "simulation.dt"}, // positive as a double, 0 as a float
        {"--ticks -1", "--ticks"},
        {"--ticks nan", "--ticks"},
        {"--ticks 1e3", "--ticks"},
        {"--seed -1", "--seed"},
        {"--seed inf", "--seed"},
        {"--threads -1", "--threads"},
        {"--threads 0", "--threads"},
        {"--threads nan", "--threads"},
        {"--max-flakes -1", "--max-flakes"},
        {"--max-flakes nan", "--max-flakes"},
        {"--max-flakes 99999999999", "--max-flakes"},
    };
    for (const Flag& f : flags) {
        const CliRun r = run_snow_run(f.args + " --ticks 5");
        EXPECT_EQ(r.status, 2) << f.args << "\n" << r.output;
        EXPECT_NE(r.output.find(f.names), std::string::npos) << f.args << "\n" << r.output;
    }
}

TEST(HardCaseInvalidInput, SnowRunSceneWithBadNumberExitsWithStatus2) {
    if (!have_snow_run()) {
        GTEST_SKIP() << "snow_run not built (SNOW_BUILD_GAME=OFF)";
    }
    const std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                      ("snow_hard_case_scene_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    for (const SceneEdit& e : scene_edits()) {
        const std::filesystem::path file = dir / "bad.gltf";
        std::ofstream(file, std::ios::binary) << minimal_with(e.from, e.to);
        const CliRun r = run_snow_run("--scene " + file.string() + " --ticks 5");
        EXPECT_EQ(r.status, 2) << e.to << "\n" << r.output;
        EXPECT_NE(r.output.find(e.expect), std::string::npos) << e.to << "\n" << r.output;
    }
    std::filesystem::remove_all(dir);
}

TEST(HardCaseInvalidInput, SnowRunRejectsAZeroFlakePool) {
    // docs/scenes.md: max_flakes is valid in [1, 16 777 216], for the scene
    // loader, the --max-flakes override and validate(SimConfig) alike: a pool
    // that can never hold a flake is an error, not an empty run.
    if (!have_snow_run()) {
        GTEST_SKIP() << "snow_run not built (SNOW_BUILD_GAME=OFF)";
    }
    const CliRun r = run_snow_run("--max-flakes 0 --ticks 5");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("max"), std::string::npos) << r.output;
}

} // namespace
} // namespace snow
