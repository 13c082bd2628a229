/// @file egl_context.hpp
/// @brief Headless GL 3.3 core context on EGL's Mesa surfaceless platform,
/// drawing into an offscreen framebuffer object. The replacement for OSMesa
/// once Mesa drops it (removed upstream in 25.1).
#pragma once

#include <snow/render.hpp>

namespace snow {

class EglContext final : public GlContext {
  public:
    /// Throws RenderError saying which EGL step failed (no surfaceless
    /// platform, no GL 3.3 core context, ...) or for a bad size.
    EglContext(int width, int height);
    ~EglContext() override;

    void swap_buffers() override {}
    [[nodiscard]] glm::ivec2 framebuffer_size() const override { return {width_, height_}; }
    [[nodiscard]] GlProc proc_address(const char* name) const override;
    void poll_events() override {}
    [[nodiscard]] bool should_close() const override { return false; }
    [[nodiscard]] std::string_view name() const override { return "egl"; }
    [[nodiscard]] std::uint32_t framebuffer() const override { return fbo_; }

  protected:
    void bind() override;

  private:
    void release();

    void* display_ = nullptr; ///< EGLDisplay
    void* context_ = nullptr; ///< EGLContext
    int width_;
    int height_;
    std::uint32_t fbo_ = 0, color_ = 0, depth_ = 0;
};

} // namespace snow
