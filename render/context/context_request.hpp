/// @file context_request.hpp
/// @brief What make_context() should create: the backend and the surface's
/// size, plus the window's title and swap interval (GlfwContext reads those).
#pragma once

#include <cstdint>
#include <string>

namespace snow {

enum class ContextBackend : std::uint8_t {
    automatic, ///< a window if a display is usable, else headless (prints why)
    headless,  ///< OSMesa, no display needed
    window,    ///< GLFW; throws RenderError if no window can be made
    egl,       ///< EGL surfaceless (Mesa), no display needed; throws if unavailable
};

/// What make_context() should create.
struct ContextRequest {
    ContextBackend backend = ContextBackend::automatic;
    int width = 640;
    int height = 480;
    std::string title = "snow";
    bool visible = true; ///< window backend: false for an offscreen window
    bool vsync = true;   ///< window backend: swap interval 1
    bool quiet = false;  ///< automatic: do not print the fallback reason to stderr
};

} // namespace snow
