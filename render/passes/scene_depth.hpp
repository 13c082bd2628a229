/// @file scene_depth.hpp
/// @brief The frame's depth buffer so far, copied into a texture, so that
/// full-screen effect passes (far-field snow, fog puffs) know how far the
/// surface behind each pixel is. Internal to snow_render.
#pragma once

#include "render/gl/gl_objects.hpp"

#include <glm/vec2.hpp>

namespace snow {

/// Texture unit of the copied depth (sampler2D scene_depth); units 0 and 1 are
/// the occlusion map and the fog table (shader.hpp texture_unit).
inline constexpr int scene_depth_unit = 3;

/// A DEPTH_COMPONENT24 texture refreshed from the read framebuffer on demand.
class SceneDepthTexture {
  public:
    /// Copies the bound read framebuffer's depth (viewport size) into the
    /// texture on scene_depth_unit; the texture is reallocated only on resize.
    void capture(glm::ivec2 viewport);

  private:
    GlTexture texture_;
    glm::ivec2 size_{0, 0};
};

} // namespace snow
