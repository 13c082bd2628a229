// Moving bodies drawn at their pose: a snowball where its Body is (and gone
// from where it was), a capsule's core pulled out between its hemispheres, an
// eye inside a body seeing out, the pass only for worlds with bodies, and
// snow on a body's top where the sky map shows it open (and only there).
#include "render/renderer_internals.hpp"
#include "systems/bodies/body.hpp"
#include "systems/sky/occlusion_map.hpp"
#include "tests/render/render_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace snow::test {
namespace {

/// Largest channel difference of two mean colours.
float difference(const glm::vec3& a, const glm::vec3& b) {
    const glm::vec3 d = glm::abs(a - b);
    return std::max({d.x, d.y, d.z});
}

ViewCamera front_camera() {
    ViewCamera c;
    c.position = {0.0f, 1.0f, 6.0f};
    c.look_at({0.0f, 1.0f, 0.0f});
    return c;
}

Entity add(World& w, const BodyDef& d) {
    const Entity e = w.create();
    w.add<Body>(e, make_body(d));
    return e;
}

BodyDef snowball_at(const glm::vec3& p) {
    BodyDef d;
    d.position = p;
    d.radius = 0.5f;
    d.snowball = true;
    return d;
}

TEST(RenderBodies, SnowballIsDrawnWhereItsBodyIsNow) {
    World world;
    SceneVisuals visuals;
    visuals.environment.sky = {0.1f, 0.1f, 0.12f}; // a dark background behind the white ball
    const ViewCamera camera = front_camera();
    const Image empty = render_image(world, visuals, camera);
    const Entity ball = add(world, snowball_at({-1.5f, 1.0f, 0.0f}));
    const Image before = render_image(world, visuals, camera);
    const glm::ivec2 left = to_pixel(camera, {-1.5f, 1.0f, 0.0f});
    const glm::ivec2 right = to_pixel(camera, {1.5f, 1.0f, 0.0f});
    EXPECT_GT(difference(mean_color(before, left, 2), mean_color(empty, left, 2)), 20.0f);

    world.get<Body>(ball).position = {1.5f, 1.0f, 0.0f};
    const Image after = render_image(world, visuals, camera);
    EXPECT_EQ(mean_color(after, left, 2), mean_color(empty, left, 2)) << "no ghost left behind";
    EXPECT_GT(difference(mean_color(after, right, 2), mean_color(empty, right, 2)), 20.0f);
}

TEST(RenderBodies, CapsuleCoreSpansBetweenItsHemispheres) {
    World world;
    const SceneVisuals visuals;
    const ViewCamera camera = front_camera();
    const Image empty = render_image(world, visuals, camera);
    BodyDef d;
    d.shape = BodyShape::capsule;
    d.position = {0.0f, 1.0f, 0.0f};
    d.radius = 0.25f;
    d.half_height = 0.6f;
    add(world, d);
    const Image image = render_image(world, visuals, camera);
    // Covered along its whole height (0.15 .. 1.85 m), and only that.
    for (const float y : {0.2f, 0.6f, 1.0f, 1.4f, 1.8f}) {
        const glm::ivec2 px = to_pixel(camera, {0.0f, y, 0.25f});
        EXPECT_GT(difference(mean_color(image, px, 1), mean_color(empty, px, 1)), 20.0f)
            << "y " << y;
    }
    const glm::vec3 coat = mean_color(image, to_pixel(camera, {0.0f, 1.0f, 0.25f}), 1);
    EXPECT_GT(coat.x, coat.z + 10.0f) << "the walker's coat is reddish";
    for (const float y : {0.05f, 1.95f}) {
        const glm::ivec2 px = to_pixel(camera, {0.0f, y, 0.25f});
        EXPECT_EQ(mean_color(image, px, 0), mean_color(empty, px, 0)) << "y " << y;
    }
}

TEST(RenderBodies, EyeInsideABodySeesOut) {
    World world;
    const SceneVisuals visuals;
    ViewCamera camera = front_camera();
    add(world, snowball_at({3.0f, 1.0f, 0.0f})); // in view
    const Image outside = render_image(world, visuals, camera);
    add(world, snowball_at(camera.position));
    const Image inside = render_image(world, visuals, camera);
    const ImageComparison c = compare_images(outside, inside);
    EXPECT_EQ(c.pixels_over, 0u) << "the body around the eye hides nothing (back faces culled)";
}

/// How near to white a colour is: its least channel over its largest (1 for
/// grey and white, 0.24 for the walker's coat).
float whiteness(const glm::vec3& c) {
    return std::min({c.x, c.y, c.z}) / std::max({c.x, c.y, c.z, 1.0f});
}

/// A sky map over the ground at y = 0 with a roof 3 m up over x in [0.5, 2.5],
/// z in [-1, 1]: only the map has it (as the simulation would), nothing draws it.
void set_sky_map(World& w) {
    OcclusionMap& map = w.set_resource<OcclusionMap>();
    map.x0 = map.z0 = -6.0f;
    map.texel = 0.1f;
    map.width = map.height = 120;
    map.top_y.resize(static_cast<std::size_t>(map.width) * map.height);
    for (std::uint32_t j = 0; j < map.height; ++j) {
        for (std::uint32_t i = 0; i < map.width; ++i) {
            const float x = map.x0 + (static_cast<float>(i) + 0.5f) * map.texel;
            const float z = map.z0 + (static_cast<float>(j) + 0.5f) * map.texel;
            const bool roof = x > 0.5f && x < 2.5f && z > -1.0f && z < 1.0f;
            map.top_y[j * map.width + i] = roof ? 3.0f : 0.0f;
        }
    }
    map.version = 1;
}

TEST(RenderBodies, SnowLiesOnABodysTopOnlyWhereTheSkyMapShowsItOpen) {
    World world;
    set_sky_map(world);
    constexpr float radius = 0.35f, half = 0.45f;
    const auto walker_at = [&](float x) {
        BodyDef d;
        d.shape = BodyShape::capsule;
        d.position = {x, 1.0f, 0.0f};
        d.radius = radius;
        d.half_height = half;
        add(world, d);
    };
    walker_at(-1.5f); // in the open
    walker_at(1.5f);  // under the roof
    SceneVisuals visuals;
    visuals.environment.sky = {0.1f, 0.1f, 0.12f};
    ViewCamera camera;
    camera.position = {0.0f, 3.0f, 5.0f};
    camera.look_at({0.0f, 1.2f, 0.0f});
    // The crown of the head (normal 17 degrees off up, towards the camera) and
    // the coat's side at the core (normal level).
    const glm::vec3 crown_normal = glm::normalize(glm::vec3(0.0f, 1.0f, 0.3f));
    const auto crown = [&](float x) {
        return to_pixel(camera, glm::vec3(x, 1.0f + half, 0.0f) + radius * crown_normal);
    };
    const auto side = [&](float x) { return to_pixel(camera, {x, 1.0f, radius}); };

    RenderSettings off;
    off.body_snow = 0.0f;
    const Image with = render_image(world, visuals, camera);
    const Image without = render_image(world, visuals, camera, off);
    const auto measure = [](const Image& image, glm::ivec2 px) {
        return whiteness(mean_color(image, px, 1));
    };
    const float open_top = measure(with, crown(-1.5f)), open_side = measure(with, side(-1.5f));
    const float bare_top = measure(without, crown(-1.5f)),
                bare_side = measure(without, side(-1.5f));
    const float roofed_top = measure(with, crown(1.5f)), roofed_side = measure(with, side(1.5f));
    const auto brightness = [&](const Image& image) {
        const glm::vec3 c = mean_color(image, crown(-1.5f), 1);
        return c.x + c.y + c.z;
    };
    std::printf("[ measure ] whiteness top/side: open %.3f / %.3f, body_snow off %.3f / %.3f, "
                "under the roof %.3f / %.3f; open crown R+G+B %.1f on, %.1f off\n",
                open_top, open_side, bare_top, bare_side, roofed_top, roofed_side, brightness(with),
                brightness(without));
    EXPECT_GT(open_top, open_side + 0.5f) << "the open walker's head wears snow";
    EXPECT_GT(brightness(with), brightness(without) + 100.0f) << "and is brighter for it";
    EXPECT_LT(std::abs(bare_top - bare_side), 0.1f) << "ablation: no snow, top and side alike";
    EXPECT_LT(std::abs(roofed_top - roofed_side), 0.1f) << "the roofed walker's head stays bare";
    EXPECT_EQ(mean_color(with, side(-1.5f), 1), mean_color(without, side(-1.5f), 1))
        << "the level coat is the same with and without snow";
}

TEST(RenderBodies, PassOnlyForWorldsWithBodies) {
    World world;
    const SceneVisuals visuals;
    auto context = headless_context();
    Renderer renderer(*context);
    render_world(renderer, world, visuals, front_camera());
    std::vector<std::string> names = renderer.pass_names();
    EXPECT_EQ(std::count(names.begin(), names.end(), "bodies"), 0);
    add(world, snowball_at({0.0f, 1.0f, 0.0f}));
    render_world(renderer, world, visuals, front_camera());
    const std::vector<std::string> with = {"sky", "meshes", "bodies", "snow_surfaces", "flakes"};
    EXPECT_EQ(renderer.pass_names(), with);
}

} // namespace
} // namespace snow::test
