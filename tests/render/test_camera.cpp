// The view camera: built from a CameraDef, it looks at the target.
#include <snow/render.hpp>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace snow::test {
namespace {

TEST(RenderCamera, FromDefLooksAtTheTarget) {
    CameraDef def;
    def.position = {3.0f, 5.0f, 10.0f};
    def.target = {-1.0f, 1.0f, 0.0f};
    const ViewCamera c = ViewCamera::from_def(def);
    const glm::vec3 want = glm::normalize(def.target - def.position);
    EXPECT_GT(glm::dot(c.forward(), want), 0.99999f);
    const glm::vec4 clip = c.projection(1.5f) * c.view() * glm::vec4(def.target, 1.0f);
    EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-5f); // the target is at the screen centre
    EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(c.right(), c.forward()), 0.0f, 1e-6f);
}

TEST(RenderCamera, PitchStaysAwayFromStraightUp) {
    ViewCamera c;
    c.turn(0.0f, 10.0f);
    EXPECT_LT(c.pitch, 1.5708f);
    c.look_at(c.position + glm::vec3(0.0f, 1.0f, 0.0f));
    EXPECT_LT(c.pitch, 1.5708f);
    const float yaw = c.yaw;
    c.look_at(c.position); // degenerate: unchanged
    EXPECT_EQ(c.yaw, yaw);
}

} // namespace
} // namespace snow::test
