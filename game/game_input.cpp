#include "game/game_input.hpp"

#include <GLFW/glfw3.h>

#include <array>
#include <charconv>
#include <stdexcept>

namespace snow {

namespace {

struct Binding {
    const char* name;
    int key;
    Action action;
};

constexpr std::array<Binding, 16> bindings{{
    {"P", GLFW_KEY_P, Action::pause},
    {"N", GLFW_KEY_N, Action::step},
    {"R", GLFW_KEY_R, Action::reset},
    {"+", GLFW_KEY_EQUAL, Action::rate_up},
    {"+", GLFW_KEY_KP_ADD, Action::rate_up},
    {"-", GLFW_KEY_MINUS, Action::rate_down},
    {"LEFT", GLFW_KEY_LEFT, Action::wind_left},
    {"RIGHT", GLFW_KEY_RIGHT, Action::wind_right},
    {"UP", GLFW_KEY_UP, Action::wind_up},
    {"DOWN", GLFW_KEY_DOWN, Action::wind_down},
    {"F", GLFW_KEY_F, Action::toggle_fog},
    {"Q", GLFW_KEY_Q, Action::quality_next},
    {"C", GLFW_KEY_C, Action::screenshot},
    {"O", GLFW_KEY_O, Action::toggle_orbit},
    {"H", GLFW_KEY_H, Action::toggle_help},
    {"ESC", GLFW_KEY_ESCAPE, Action::quit},
}};

} // namespace

const std::vector<KeyHelp>& key_help() {
    static const std::vector<KeyHelp> help{
        {"W A S D", "fly (mouse: look while the right button is held)"},
        {"Space / Shift", "fly up / down; scroll: flying speed (orbit: zoom)"},
        {"O", "switch fly / orbit camera"},
        {"P", "pause / resume"},
        {"N", "one tick while paused"},
        {"R", "reset the scene"},
        {"+ / -", "more / less snowfall"},
        {"Left / Right", "rotate the wind"},
        {"Up / Down", "stronger / weaker wind"},
        {"F", "fog on / off"},
        {"Q", "next quality preset"},
        {"C or F12", "screenshot (PNG)"},
        {"H", "this help"},
        {"Esc", "quit"},
    };
    return help;
}

std::optional<Action> action_for_key(int glfw_key) {
    if (glfw_key == GLFW_KEY_F12) {
        return Action::screenshot;
    }
    for (const Binding& b : bindings) {
        if (b.key == glfw_key) {
            return b.action;
        }
    }
    return std::nullopt;
}

std::vector<InjectedKey> parse_injected_keys(std::string_view text) {
    std::vector<InjectedKey> out;
    while (!text.empty()) {
        const std::size_t comma = text.find(',');
        const std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        const std::size_t colon = item.find(':');
        InjectedKey k;
        const std::string_view frame = item.substr(0, colon);
        const auto [ptr, ec] = std::from_chars(frame.data(), frame.data() + frame.size(), k.frame);
        bool found = false;
        if (colon != std::string_view::npos && ec == std::errc{} &&
            ptr == frame.data() + frame.size()) {
            const std::string_view key = item.substr(colon + 1);
            for (const Binding& b : bindings) {
                if (key == b.name) {
                    k.action = b.action;
                    found = true;
                    break;
                }
            }
        }
        if (!found) {
            throw std::invalid_argument("--inject: bad item '" + std::string(item) +
                                        "' (expected FRAME:KEY, e.g. 10:P)");
        }
        out.push_back(k);
    }
    return out;
}

} // namespace snow
