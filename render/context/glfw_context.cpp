#include "render/context/glfw_context.hpp"

#include <snow/error.hpp>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

namespace snow {

namespace {

// glfwInit/glfwTerminate are process-wide; windows share one initialisation.
int glfw_users = 0;

std::string glfw_error_text() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description != nullptr ? std::string(description) : std::string("no details");
}

bool has_display() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

void release_glfw() {
    if (--glfw_users == 0) {
        glfwTerminate();
    }
}

} // namespace

GlfwContext::GlfwContext(const ContextRequest& request) {
    if (!has_display()) {
        throw RenderError("glfw: no DISPLAY (or WAYLAND_DISPLAY) is set");
    }
    if (request.width <= 0 || request.height <= 0) {
        throw RenderError("glfw: window size " + std::to_string(request.width) + "x" +
                          std::to_string(request.height) + " must be positive");
    }
    if (glfw_users == 0 && glfwInit() != GLFW_TRUE) {
        throw RenderError("glfw: glfwInit failed: " + glfw_error_text());
    }
    ++glfw_users;
    glfwDefaultWindowHints();
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    glfwWindowHint(GLFW_DEPTH_BITS, 24);
    glfwWindowHint(GLFW_VISIBLE, request.visible ? GLFW_TRUE : GLFW_FALSE);
    window_ =
        glfwCreateWindow(request.width, request.height, request.title.c_str(), nullptr, nullptr);
    if (window_ == nullptr) {
        const std::string why = glfw_error_text();
        release_glfw();
        throw RenderError("glfw: window creation failed (no GL 3.3 core via GLX?): " + why);
    }
    try {
        make_current();
    } catch (...) {
        glfwDestroyWindow(window_);
        release_glfw();
        throw;
    }
    glfwSwapInterval(request.vsync ? 1 : 0);
}

GlfwContext::~GlfwContext() {
    glfwDestroyWindow(window_);
    release_glfw();
}

void GlfwContext::swap_buffers() {
    glfwSwapBuffers(window_);
}

glm::ivec2 GlfwContext::framebuffer_size() const {
    glm::ivec2 size{0, 0};
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
}

GlProc GlfwContext::proc_address(const char* name) const {
    return glfwGetProcAddress(name);
}

void GlfwContext::poll_events() {
    glfwPollEvents();
}

bool GlfwContext::should_close() const {
    return glfwWindowShouldClose(window_) == GLFW_TRUE;
}

void GlfwContext::bind() {
    glfwMakeContextCurrent(window_);
}

} // namespace snow
