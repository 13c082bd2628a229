/// @file render_fixture.hpp
/// @brief Shared setup of the render tests: a fixed scene built directly in a
/// World and its SceneVisuals (no simulation systems), headless contexts and
/// golden-image checks.
#pragma once

#include "ecs/world.hpp"
#include "render/context/osmesa_context.hpp"
#include "systems/geometry/geometry.hpp"
#include "systems/snowpack/snow_surface.hpp"
#include <snow/render.hpp>

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace snow::test {

inline constexpr int golden_width = 320;
inline constexpr int golden_height = 240;

/// Metres of snow per mass unit in the fixture's surfaces.
inline constexpr float fixture_unit_height = 0.002f;

/// An OSMesa context (current, GL loaded) with Mesa's shader cache disabled.
[[nodiscard]] std::unique_ptr<OsMesaContext> headless_context(int width = golden_width,
                                                              int height = golden_height);

/// A flat snow surface with no snow; `base_y` is the bare top.
[[nodiscard]] SnowSurface flat_surface(float x0, float z0, float size_x, float size_z, float cell,
                                       float base_y);

/// A closed box mesh with flat per-face normals.
[[nodiscard]] MeshRenderable box_mesh(const Aabb& box, const glm::vec3& color);

/// The fixed scene (see render_fixture.cpp): ground with snow, a house with a
/// snow-covered roof, an open shelter whose roof hides a crate, three coloured
/// lights [WF §5], an occlusion map and flakes at fixed positions.
struct FixtureScene {
    World world;
    SceneVisuals visuals;
    ViewCamera camera;
    Entity ground_surface, house_roof;
    Aabb shelter_roof_box, crate_box, house_box;
};
void build_fixture(FixtureScene& scene);

/// Renders one frame of `world` and `visuals` in a fresh golden-size headless context.
[[nodiscard]] Image render_image(const World& world, const SceneVisuals& visuals,
                                 const ViewCamera& camera, const RenderSettings& settings = {});

/// Projects a world point to pixel (x, y), y = 0 at the top, for a golden-size image.
[[nodiscard]] glm::ivec2 to_pixel(const ViewCamera& camera, const glm::vec3& p);

/// Mean RGB (0..255) of the pixels in a square of half-size `r` around `px`.
[[nodiscard]] glm::vec3 mean_color(const Image& image, glm::ivec2 px, int r);

/// Result of comparing two images of the same size.
struct ImageComparison {
    std::size_t pixels_over = 0; ///< pixels whose largest channel difference exceeds the tolerance
    int worst = 0;               ///< largest channel difference anywhere
    Image diff;                  ///< |a − b| × 8 per channel
};
inline constexpr int golden_tolerance = 4;
[[nodiscard]] ImageComparison compare_images(const Image& a, const Image& b);
/// True when at most 0.2 % of the pixels exceed the tolerance.
[[nodiscard]] bool close_enough(const ImageComparison& c, const Image& a);

/// Compares `actual` with assets/golden/<name>.png: passes when at most 0.2 % of
/// pixels differ by more than 4 levels in some channel. On failure writes
/// <build>/golden_out/<name>.actual.png and .diff.png and names them. With
/// SNOW_UPDATE_GOLDEN=1 in the environment the golden is rewritten instead.
[[nodiscard]] ::testing::AssertionResult matches_golden(const Image& actual,
                                                        const std::string& name);

} // namespace snow::test
