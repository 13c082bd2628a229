/// @file glfw_context.hpp
/// @brief GL 3.3 core context in a GLFW window (X11 via GLX, or Xvfb).
#pragma once

#include <snow/render.hpp>

struct GLFWwindow;

namespace snow {

class GlfwContext final : public GlContext {
  public:
    /// Opens a window; throws RenderError saying why when there is no DISPLAY,
    /// glfwInit fails or no GL 3.3 core window can be created.
    explicit GlfwContext(const ContextRequest& request);
    ~GlfwContext() override;

    void swap_buffers() override;
    [[nodiscard]] glm::ivec2 framebuffer_size() const override;
    [[nodiscard]] GlProc proc_address(const char* name) const override;
    void poll_events() override;
    [[nodiscard]] bool should_close() const override;
    [[nodiscard]] std::string_view name() const override { return "glfw"; }

    /// The GLFW window, for input callbacks (keyboard, mouse) in the app.
    [[nodiscard]] GLFWwindow* window() const { return window_; }

  protected:
    void bind() override;

  private:
    GLFWwindow* window_ = nullptr;
};

} // namespace snow
