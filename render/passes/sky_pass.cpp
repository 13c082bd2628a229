#include "render/passes/sky_pass.hpp"

namespace snow {

bool SkyPass::wanted(const World& /*world*/, const SceneVisuals& visuals) const {
    return visuals.fog.has_value();
}

void SkyPass::run(const World& /*world*/, FrameContext& frame) {
    frame.programs.get("sky.vert", "sky.frag", frame.fog_defines).use();
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthMask(GL_TRUE);
    glEnable(GL_DEPTH_TEST);
}

} // namespace snow
