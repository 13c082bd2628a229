/// @file osmesa_context.hpp
/// @brief Headless GL 3.3 core context on Mesa's OSMesa (llvmpipe): renders
/// into a CPU buffer, needs no display. The default in tests.
#pragma once

#include <snow/render.hpp>

#include <cstdint>
#include <vector>

namespace snow {

class OsMesaContext final : public GlContext {
  public:
    /// Creates a core-profile context with a width×height RGBA + depth buffer;
    /// throws RenderError on failure or a non-positive size.
    OsMesaContext(int width, int height);
    ~OsMesaContext() override;

    void swap_buffers() override {}
    [[nodiscard]] glm::ivec2 framebuffer_size() const override { return {width_, height_}; }
    [[nodiscard]] GlProc proc_address(const char* name) const override;
    void poll_events() override {}
    [[nodiscard]] bool should_close() const override { return false; }
    [[nodiscard]] std::string_view name() const override { return "osmesa"; }

  protected:
    void bind() override;

  private:
    void* context_ = nullptr; ///< OSMesaContext, opaque here to keep GL/gl.h out of headers
    int width_;
    int height_;
    std::vector<std::uint8_t> buffer_; ///< colour buffer, bottom row first
};

} // namespace snow
