// Quality presets (game/play/quality.hpp, picked in docs/accuracy.md) and the
// scene overrides they use: ordered from cheap to accurate, applied only where
// the user gave no value, loadable with every project scene, and bad override
// values rejected naming the field.
#include "game/play/quality.hpp"
#include "systems/api/simulation_internals.hpp"
#include <snow/scene.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace snow {
namespace {

std::string scene_path(const char* name) {
    return std::string(SNOW_SOURCE_DIR) + "/assets/scenes/" + name;
}

TEST(Quality, PresetsGoFromCheapToAccurate) {
    ASSERT_EQ(quality_presets.size(), 3u);
    EXPECT_EQ(quality_presets[0].name, "low");
    EXPECT_EQ(quality_presets[1].name, "medium");
    EXPECT_EQ(quality_presets[2].name, "high");
    for (std::size_t i = 1; i < quality_presets.size(); ++i) {
        const QualityPreset& a = quality_presets[i - 1];
        const QualityPreset& b = quality_presets[i];
        EXPECT_GE(a.dt, b.dt) << b.name << " ticks no faster than " << a.name;
        EXPECT_GE(a.cell_scale, b.cell_scale) << b.name << " has no coarser cells";
        EXPECT_LE(a.lod_distance, b.lod_distance);
    }
    for (const QualityPreset& q : quality_presets) {
        // The renderer does not interpolate between ticks: none slower than 30 Hz.
        EXPECT_LE(q.dt, 1.0f / 30.0f + 1e-7f) << q.name;
        EXPECT_GT(q.cell_scale, 0.0f) << q.name;
        EXPECT_GE(q.occlusion_resolution, 1u) << q.name;
        EXPECT_LE(q.occlusion_resolution, 4096u) << q.name;
    }
}

TEST(Quality, ApplyFillsOnlyWhatTheUserLeftUnset) {
    const QualityPreset& q = quality_presets[2];
    SceneOverrides o;
    apply_quality(q, o);
    EXPECT_EQ(o.dt, q.dt);
    EXPECT_EQ(o.integrator, q.integrator);
    EXPECT_EQ(o.cell_scale, q.cell_scale);
    EXPECT_EQ(o.occlusion_resolution, q.occlusion_resolution);
    EXPECT_FALSE(o.seed.has_value());
    EXPECT_FALSE(o.smoothing_iterations.has_value());

    SceneOverrides user;
    user.dt = 0.005f;
    user.integrator = Integrator::rk4;
    user.cell_scale = 3.0f;
    user.occlusion_resolution = 77;
    apply_quality(q, user);
    EXPECT_EQ(user.dt, 0.005f);
    EXPECT_EQ(user.integrator, Integrator::rk4);
    EXPECT_EQ(user.cell_scale, 3.0f);
    EXPECT_EQ(user.occlusion_resolution, 77u);
}

TEST(Quality, EveryPresetLoadsEveryProjectSceneAndApplies) {
    for (const char* scene : {"village.gltf", "village_effects.gltf", "minimal.gltf"}) {
        const SceneLoadResult plain = load_scene_file(scene_path(scene));
        ASSERT_NE(plain.sim, nullptr) << plain.error;
        for (const QualityPreset& q : quality_presets) {
            SceneOverrides o;
            apply_quality(q, o);
            const SceneLoadResult r = load_scene_file(scene_path(scene), o);
            ASSERT_NE(r.sim, nullptr) << scene << " " << q.name << ": " << r.error;
            EXPECT_EQ(r.sim->config().dt, q.dt);
            EXPECT_EQ(r.sim->config().integrator, q.integrator);
            // Same surfaces, cells scaled.
            std::vector<float> cells, plain_cells;
            world_of(*r.sim).each<SnowSurface>(
                [&](Entity, const SnowSurface& s) { cells.push_back(s.cell); });
            world_of(*plain.sim).each<SnowSurface>([&](Entity, const SnowSurface& s) {
                plain_cells.push_back(s.cell);
            });
            ASSERT_EQ(cells.size(), plain_cells.size());
            for (std::size_t i = 0; i < cells.size(); ++i) {
                EXPECT_FLOAT_EQ(cells[i], plain_cells[i] * q.cell_scale) << scene << " " << q.name;
            }
            // The sky map follows the preset where the scene has one.
            const auto* cam = world_of(*r.sim).try_resource<OcclusionCamera>();
            EXPECT_EQ(cam != nullptr, world_of(*plain.sim).has_resource<OcclusionCamera>());
            if (cam != nullptr) {
                EXPECT_EQ(cam->resolution, q.occlusion_resolution);
            }
            r.sim->run(30);
            EXPECT_TRUE(r.sim->mass().balanced()) << scene << " " << q.name;
            EXPECT_EQ(r.sim->nonfinite_count(), 0u);
        }
    }
}

TEST(Quality, SmoothingOverrideReachesTheConfig) {
    SceneOverrides o;
    o.smoothing_iterations = 3;
    const SceneLoadResult r = load_scene_file(scene_path("village.gltf"), o);
    ASSERT_NE(r.sim, nullptr) << r.error;
    EXPECT_EQ(r.sim->config().smoothing_iterations, 3u);
}

TEST(Quality, BadKnobOverridesNameTheirField) {
    const auto error_of = [](const SceneOverrides& o) {
        const SceneLoadResult r = load_scene_file(scene_path("village.gltf"), o);
        EXPECT_EQ(r.sim, nullptr);
        return r.error;
    };
    for (const float scale : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity()}) {
        SceneOverrides o;
        o.cell_scale = scale;
        EXPECT_NE(error_of(o).find("cell_scale"), std::string::npos) << error_of(o);
    }
    {
        SceneOverrides o;
        o.cell_scale = 1.0e-3f; // 20 m ground at 0.1 mm cells: far too many
        const std::string e = error_of(o);
        EXPECT_NE(e.find("surface.cell"), std::string::npos) << e;
        EXPECT_NE(e.find("cell_scale"), std::string::npos) << e;
    }
    for (const std::uint32_t res : {0u, 5000u}) {
        SceneOverrides o;
        o.occlusion_resolution = res;
        EXPECT_NE(error_of(o).find("occlusion.resolution"), std::string::npos) << error_of(o);
    }
    {
        SceneOverrides o;
        o.smoothing_iterations = 0;
        EXPECT_NE(error_of(o).find("simulation.smoothing_iterations"), std::string::npos)
            << error_of(o);
    }
}

} // namespace
} // namespace snow
