// The narrow-phase tests of one flake path against one shape [WF §4]:
// where a segment enters an open box or sphere, and what it is when it
// starts inside.
#include "systems/geometry/narrow_phase.hpp"

#include <gtest/gtest.h>

namespace snow {
namespace {

const Aabb unit_box{{0.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 1.0f}};

TEST(NarrowPhase, StrictlyInsideLeavesTheFacesOutside) {
    EXPECT_TRUE(strictly_inside(unit_box, {0.5f, 0.5f, 0.5f}));
    EXPECT_FALSE(strictly_inside(unit_box, {0.5f, 1.0f, 0.5f}));
    EXPECT_FALSE(strictly_inside(unit_box, {0.0f, 0.5f, 0.5f}));
    EXPECT_FALSE(strictly_inside(unit_box, {0.5f, 0.5f, 1.5f}));
}

TEST(NarrowPhase, SphereEntryAlongTheSegment) {
    const glm::vec3 c{0.0f, 0.0f, 0.0f};
    float t = -1.0f;
    // From 2 m above to 2 m below: enters at y = 1, a quarter of the way.
    ASSERT_TRUE(sphere_entry({0, 2, 0}, {0, -2, 0}, c, 1.0f, t));
    EXPECT_FLOAT_EQ(t, 0.25f);
    // Starting inside: t = 0, whatever the direction.
    ASSERT_TRUE(sphere_entry({0, 0.5f, 0}, {0, 3, 0}, c, 1.0f, t));
    EXPECT_EQ(t, 0.0f);
    // Ending short of the sphere, passing beside it, moving away, standing still.
    EXPECT_FALSE(sphere_entry({0, 3, 0}, {0, 1.5f, 0}, c, 1.0f, t));
    EXPECT_FALSE(sphere_entry({2, 2, 0}, {2, -2, 0}, c, 1.0f, t));
    EXPECT_FALSE(sphere_entry({0, 1.5f, 0}, {0, 3, 0}, c, 1.0f, t));
    EXPECT_FALSE(sphere_entry({0, 1.5f, 0}, {0, 1.5f, 0}, c, 1.0f, t));
    // Grazing (touching the surface at one point) does not enter the open sphere.
    EXPECT_FALSE(sphere_entry({1, 2, 0}, {1, -2, 0}, c, 1.0f, t));
    // Fast enough to cross the whole sphere in one segment: still caught.
    ASSERT_TRUE(sphere_entry({0, 50, 0}, {0, -50, 0}, c, 1.0f, t));
    EXPECT_FLOAT_EQ(t, 0.49f);
}

TEST(NarrowPhase, BoxContactFromAboveLandsOnTheTop) {
    BoxContact k;
    ASSERT_TRUE(box_contact(unit_box, {0.5f, 1.5f, 0.25f}, {0.5f, 0.5f, 0.25f}, k));
    EXPECT_EQ(k.axis, 1);
    EXPECT_TRUE(k.max_side);
    EXPECT_FLOAT_EQ(k.t, 0.5f);
    EXPECT_EQ(k.at, (glm::vec3{0.5f, 1.0f, 0.25f}));
}

TEST(NarrowPhase, BoxContactFromTheSideAndThroughACorner) {
    BoxContact k;
    ASSERT_TRUE(box_contact(unit_box, {-1.0f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, k));
    EXPECT_EQ(k.axis, 0);
    EXPECT_FALSE(k.max_side);
    EXPECT_EQ(k.at.x, 0.0f);
    EXPECT_FLOAT_EQ(k.t, 2.0f / 3.0f);
    // Entering through the top edge diagonally: the corner counts as the top.
    ASSERT_TRUE(box_contact(unit_box, {-0.5f, 1.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, k));
    EXPECT_EQ(k.axis, 1);
    EXPECT_TRUE(k.max_side);
    EXPECT_EQ(k.at.y, 1.0f);
}

TEST(NarrowPhase, BoxContactStartingInside) {
    BoxContact k;
    // Inside at both ends: the face nearest the end point (here +z).
    ASSERT_TRUE(box_contact(unit_box, {0.5f, 0.5f, 0.5f}, {0.5f, 0.5f, 0.9f}, k));
    EXPECT_EQ(k.axis, 2);
    EXPECT_TRUE(k.max_side);
    EXPECT_EQ(k.t, 0.0f);
    EXPECT_EQ(k.at, (glm::vec3{0.5f, 0.5f, 1.0f}));
    // A tie between the top and a side goes to the top.
    ASSERT_TRUE(box_contact(unit_box, {0.5f, 0.5f, 0.5f}, {0.75f, 0.75f, 0.5f}, k));
    EXPECT_EQ(k.axis, 1);
    EXPECT_TRUE(k.max_side);
    // Leaving the box: no contact.
    EXPECT_FALSE(box_contact(unit_box, {0.5f, 0.5f, 0.5f}, {0.5f, 2.0f, 0.5f}, k));
}

TEST(NarrowPhase, BoxContactMisses) {
    BoxContact k;
    // Ends short of the top; beside the box; along a face (the open box
    // excludes its faces); parallel to an axis outside the slab.
    EXPECT_FALSE(box_contact(unit_box, {0.5f, 2.0f, 0.5f}, {0.5f, 1.1f, 0.5f}, k));
    EXPECT_FALSE(box_contact(unit_box, {1.5f, 2.0f, 0.5f}, {1.5f, -1.0f, 0.5f}, k));
    EXPECT_FALSE(box_contact(unit_box, {1.0f, 2.0f, 0.5f}, {1.0f, -1.0f, 0.5f}, k));
    EXPECT_FALSE(box_contact(unit_box, {-1.0f, 0.5f, 2.0f}, {2.0f, 0.5f, 2.0f}, k));
    // Ending exactly on the top face does not enter.
    EXPECT_FALSE(box_contact(unit_box, {0.5f, 2.0f, 0.5f}, {0.5f, 1.0f, 0.5f}, k));
}

} // namespace
} // namespace snow
