#include "game/play/input_reader.hpp"

#include <GLFW/glfw3.h>

#include <utility>

namespace snow {

InputReader::InputReader(GLFWwindow* window, KeyScript script)
    : window_(window), script_(std::move(script)) {
    if (!window_) {
        return;
    }
    glfwSetWindowUserPointer(window_, this);
    glfwSetKeyCallback(window_, [](GLFWwindow* win, int key, int, int action, int) {
        if (action == GLFW_PRESS) {
            static_cast<InputReader*>(glfwGetWindowUserPointer(win))->key_pressed(key);
        }
    });
    glfwSetScrollCallback(window_, [](GLFWwindow* win, double, double dy) {
        static_cast<InputReader*>(glfwGetWindowUserPointer(win))->scrolled(dy);
    });
}

void InputReader::key_pressed(int glfw_key) {
    if (const auto a = action_for_key(glfw_key)) {
        pressed_.push_back(*a);
    }
}

void InputReader::scrolled(double steps) {
    scroll_ += static_cast<float>(steps);
}

bool InputReader::window_key(int glfw_key) const {
    return window_ && glfwGetKey(window_, glfw_key) == GLFW_PRESS;
}

PlayerActions InputReader::read(std::uint64_t frame, bool hud_has_mouse) {
    PlayerActions a;
    a.presses = std::exchange(pressed_, {});
    for (const InjectedKey& k : script_.presses) {
        if (k.frame == frame) {
            a.presses.push_back(k.action);
        }
    }
    const auto down = [&](MoveKey k) {
        return window_key(glfw_key_of(k)) || script_.held(k, frame) ? 1.0f : 0.0f;
    };
    const auto key = [&](int k) { return window_key(k) ? 1.0f : 0.0f; };
    a.move = {down(MoveKey::right) - down(MoveKey::left),
              key(GLFW_KEY_SPACE) - key(GLFW_KEY_LEFT_SHIFT),
              down(MoveKey::forward) - down(MoveKey::back)};
    a.scroll = std::exchange(scroll_, 0.0f);
    if (window_) {
        double x = 0.0, y = 0.0;
        glfwGetCursorPos(window_, &x, &y);
        a.mouse = {static_cast<float>(x - last_x_), static_cast<float>(y - last_y_)};
        last_x_ = x;
        last_y_ = y;
        if (!hud_has_mouse) {
            a.look_button = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
            a.drag_button = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        }
    }
    return a;
}

} // namespace snow
