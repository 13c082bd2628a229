// Moving bodies drawn at their pose: a snowball where its Body is (and gone
// from where it was), a capsule's core pulled out between its hemispheres, an
// eye inside a body seeing out, and the pass only for worlds with bodies.
#include "render/renderer_internals.hpp"
#include "systems/bodies/body.hpp"
#include "tests/render/render_fixture.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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
