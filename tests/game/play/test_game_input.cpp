// snow_game's input part (game/play/input_reader.hpp) without a window: window key
// presses and the key script become one frame's actions, in order; held keys
// become the move vector; the wheel is read once.
#include "game/play/input_reader.hpp"

#include <gtest/gtest.h>

#include <GLFW/glfw3.h>

#include <vector>

namespace snow {
namespace {

TEST(GameInput, ScriptPressesComeAtTheirFrameInOrder) {
    InputReader input(nullptr, parse_key_script("0:T,2:P,2:N,2:ESC"));
    EXPECT_EQ(input.read(0, false).presses, std::vector<Action>{Action::time_scale});
    EXPECT_TRUE(input.read(1, false).presses.empty());
    EXPECT_EQ(input.read(2, false).presses,
              (std::vector<Action>{Action::pause, Action::step, Action::quit}));
    EXPECT_TRUE(input.read(3, false).presses.empty());
}

TEST(GameInput, WindowKeysComeBeforeTheScriptsAndAreReadOnce) {
    InputReader input(nullptr, parse_key_script("0:O"));
    input.key_pressed(GLFW_KEY_EQUAL);
    input.key_pressed(GLFW_KEY_X); // bound to nothing
    input.key_pressed(GLFW_KEY_F12);
    EXPECT_EQ(input.read(0, false).presses,
              (std::vector<Action>{Action::rate_up, Action::screenshot, Action::next_camera}));
    EXPECT_TRUE(input.read(1, false).presses.empty());
}

TEST(GameInput, HeldKeysMoveForTheirFrames) {
    InputReader input(nullptr, parse_key_script("1:W:2,2:A,3:A,3:D"));
    EXPECT_EQ(input.read(0, false).move, glm::vec3(0.0f));
    EXPECT_EQ(input.read(1, false).move, glm::vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(input.read(2, false).move, glm::vec3(-1.0f, 0.0f, 1.0f));
    EXPECT_EQ(input.read(3, false).move, glm::vec3(0.0f)); // A and D together: no sideways
}

TEST(GameInput, WheelStepsAddUpAndAreReadOnce) {
    InputReader input(nullptr, KeyScript{});
    input.scrolled(1.0);
    input.scrolled(2.0);
    EXPECT_EQ(input.read(0, false).scroll, 3.0f);
    EXPECT_EQ(input.read(1, false).scroll, 0.0f);
}

TEST(GameInput, WithoutAWindowTheMouseIsStill) {
    InputReader input(nullptr, KeyScript{});
    const PlayerActions a = input.read(0, false);
    EXPECT_EQ(a.mouse, glm::vec2(0.0f));
    EXPECT_FALSE(a.look_button);
    EXPECT_FALSE(a.drag_button);
}

} // namespace
} // namespace snow
