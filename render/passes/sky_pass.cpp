#include "render/passes/sky_pass.hpp"

#include "systems/api/fog.hpp"

namespace snow {

bool SkyPass::wanted(const World& world, const SceneVisuals&) const {
    return world.has_resource<Fog>();
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
