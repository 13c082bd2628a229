#include "render/passes/scene_depth.hpp"

namespace snow {

void SceneDepthTexture::capture(glm::ivec2 viewport) {
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(scene_depth_unit));
    glBindTexture(GL_TEXTURE_2D, texture_.id());
    if (viewport != size_) {
        size_ = viewport;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, size_.x, size_.y, 0, GL_DEPTH_STENCIL,
                     GL_UNSIGNED_INT_24_8, nullptr);
    }
    // A depth format makes the copy read the depth buffer, not colour; depth +
    // stencil like the contexts' buffers (OSMesa, EGL) keeps it a plain copy on
    // llvmpipe (docs/performance.md "Measurements the code relies on").
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, size_.x, size_.y);
}

} // namespace snow
