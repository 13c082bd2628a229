#include "game/play/game_input.hpp"

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

constexpr std::array<Binding, 19> bindings{{
    {"P", GLFW_KEY_P, Action::pause},           {"N", GLFW_KEY_N, Action::step},
    {"R", GLFW_KEY_R, Action::reset},           {"+", GLFW_KEY_EQUAL, Action::rate_up},
    {"+", GLFW_KEY_KP_ADD, Action::rate_up},    {"-", GLFW_KEY_MINUS, Action::rate_down},
    {"LEFT", GLFW_KEY_LEFT, Action::wind_left}, {"RIGHT", GLFW_KEY_RIGHT, Action::wind_right},
    {"UP", GLFW_KEY_UP, Action::wind_up},       {"DOWN", GLFW_KEY_DOWN, Action::wind_down},
    {"F", GLFW_KEY_F, Action::toggle_fog},      {"V", GLFW_KEY_V, Action::toggle_wind},
    {"Q", GLFW_KEY_Q, Action::quality_next},    {"C", GLFW_KEY_C, Action::screenshot},
    {"O", GLFW_KEY_O, Action::next_camera},     {"T", GLFW_KEY_T, Action::time_scale},
    {"B", GLFW_KEY_B, Action::push_snowball},   {"H", GLFW_KEY_H, Action::toggle_help},
    {"ESC", GLFW_KEY_ESCAPE, Action::quit},
}};

struct MoveBinding {
    const char* name;
    int key;
};

/// Indexed by MoveKey.
constexpr std::array<MoveBinding, move_key_count> move_bindings{{
    {"W", GLFW_KEY_W},
    {"S", GLFW_KEY_S},
    {"A", GLFW_KEY_A},
    {"D", GLFW_KEY_D},
}};

constexpr const char* key_list = "P N R + - LEFT RIGHT UP DOWN F V Q C O T B H ESC, held: W A S D";

/// Whole-string unsigned number, or nothing.
std::optional<std::uint64_t> whole_number(std::string_view text) {
    std::uint64_t v = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc{} || ptr != text.data() + text.size()) {
        return std::nullopt;
    }
    return v;
}

[[noreturn]] void bad_item(std::string_view item, const std::string& problem) {
    throw std::invalid_argument("--inject: '" + std::string(item) + "' " + problem +
                                " (expected FRAME:KEY or FRAME:MOVE:FRAMES, e.g. 10:P or 0:W:30)");
}

/// Adds one FRAME:KEY[:FRAMES] item to `script`.
void parse_item(std::string_view item, KeyScript& script) {
    const std::size_t colon = item.find(':');
    const std::string_view rest = colon == std::string_view::npos ? "" : item.substr(colon + 1);
    const std::size_t second = rest.find(':');
    const std::string_view key = rest.substr(0, second);
    if (key.empty()) {
        bad_item(item, "names no key");
    }
    const auto frame = whole_number(item.substr(0, colon));
    if (!frame) {
        bad_item(item, "does not start with a frame number");
    }
    for (std::size_t m = 0; m < move_bindings.size(); ++m) {
        if (key == move_bindings[m].name) {
            InjectedHold hold{*frame, 1, static_cast<MoveKey>(m)};
            if (second != std::string_view::npos) {
                const auto frames = whole_number(rest.substr(second + 1));
                if (!frames || *frames == 0) {
                    bad_item(item, "holds for no whole number of frames >= 1");
                }
                hold.frames = *frames;
            }
            script.holds.push_back(hold);
            return;
        }
    }
    for (const Binding& b : bindings) {
        if (key == b.name) {
            if (second != std::string_view::npos) {
                bad_item(item, "gives a hold length, but only W A S D are held");
            }
            script.presses.push_back({*frame, b.action});
            return;
        }
    }
    bad_item(item, "names unknown key '" + std::string(key) + "' (keys: " + key_list + ")");
}

} // namespace

const std::vector<KeyHelp>& key_help() {
    static const std::vector<KeyHelp> help{
        {"W A S D", "walk / fly (mouse: look while the right button is held)"},
        {"Space / Shift", "fly up / down; scroll: flying speed (orbit: zoom)"},
        {"O", "camera: walk / fly / orbit"},
        {"B", "walk: push the snowball ahead (makes one if none)"},
        {"T", "simulated time per frame x1 / x4 / x16 / x64"},
        {"P", "pause / resume"},
        {"N", "one tick while paused"},
        {"R", "reset the scene"},
        {"+ / -", "more / less snowfall"},
        {"Left / Right", "rotate the wind"},
        {"Up / Down", "stronger / weaker wind"},
        {"F", "fog on / off"},
        {"V", "wind field arrows on / off (blue still, red fastest)"},
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

int glfw_key_of(MoveKey k) {
    return move_bindings[static_cast<std::size_t>(k)].key;
}

bool KeyScript::held(MoveKey key, std::uint64_t frame) const {
    for (const InjectedHold& h : holds) {
        if (h.key == key && frame >= h.frame && frame - h.frame < h.frames) {
            return true;
        }
    }
    return false;
}

KeyScript parse_key_script(std::string_view text) {
    KeyScript script;
    while (!text.empty()) {
        const std::size_t comma = text.find(',');
        parse_item(text.substr(0, comma), script);
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
    }
    if (script.presses.empty() && script.holds.empty()) {
        throw std::invalid_argument("--inject: names no key (expected FRAME:KEY or "
                                    "FRAME:MOVE:FRAMES, e.g. 10:P or 0:W:30)");
    }
    return script;
}

} // namespace snow
