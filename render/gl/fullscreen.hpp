/// @file fullscreen.hpp
/// @brief The full-screen triangle of sky.vert (three vertices, no
/// attributes) drawn over the frame with alpha blending: how the spectral
/// snow and fog-puff passes composite their layer. Internal to snow_render.
#pragma once

#include "render/gl/gl_objects.hpp"

namespace snow {

/// Draws the triangle with colour = mix(frame, layer, layer alpha), depth
/// writes off; the depth test is left as the caller set it.
inline void draw_fullscreen_blended(const GlVertexArray& vao) {
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindVertexArray(vao.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
}

} // namespace snow
