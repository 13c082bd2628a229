/// @file gl_context.hpp
/// @brief One interface over the GL context backends (OSMesa or EGL headless,
/// GLFW window). It knows none of them: make_context.hpp picks one.
#pragma once

#include <glm/vec2.hpp>

#include <cstdint>
#include <string_view>

namespace snow {

/// A GL entry point as returned by a platform's proc-address function.
using GlProc = void (*)();

/// A GL 3.3+ core context and the surface it draws to. All GL work happens on
/// the thread that called make_current().
class GlContext {
  public:
    GlContext();
    virtual ~GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    /// Makes the context current and (re)loads the GL entry points from it when
    /// another context was loaded last; throws RenderError if GL < 3.3.
    void make_current();
    /// Presents the frame (no-op for headless surfaces).
    virtual void swap_buffers() = 0;
    /// Drawable size in pixels.
    [[nodiscard]] virtual glm::ivec2 framebuffer_size() const = 0;
    /// The platform's GL proc-address lookup for `name`.
    [[nodiscard]] virtual GlProc proc_address(const char* name) const = 0;
    /// Processes window events (no-op for headless surfaces).
    virtual void poll_events() = 0;
    /// True once the user asked to close the window (never for headless).
    [[nodiscard]] virtual bool should_close() const = 0;
    /// Backend name: "osmesa", "egl" or "glfw".
    [[nodiscard]] virtual std::string_view name() const = 0;
    /// The GL framebuffer object frames are drawn into; 0 is the default one.
    [[nodiscard]] virtual std::uint32_t framebuffer() const { return 0; }

  protected:
    /// Platform make-current; the base class then loads GL through proc_address().
    virtual void bind() = 0;

  private:
    std::uint64_t serial_; ///< unique per context, so a reused address never skips a reload
};

} // namespace snow
