#include "render/passes/shadow_pass.hpp"

#include "render/gl/frame_block.hpp"
#include "render/passes/sun_cascades.hpp"
#include <snow/error.hpp>

#include <cstddef>

namespace snow {

static_assert(sun_cascade_count == frame_sun_cascades);

ShadowPass::ShadowPass(const std::vector<std::unique_ptr<RenderPass>>& passes,
                       const RenderSettings& settings)
    : passes_(passes), settings_(settings) {}

bool ShadowPass::wanted(const World&, const SceneVisuals& visuals) const {
    return visuals.sun.has_value() && settings_.sun_shadows;
}

void ShadowPass::allocate(int resolution) {
    resolution_ = resolution;
    glBindTexture(GL_TEXTURE_2D, atlas_.id());
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, resolution * sun_cascade_count, resolution,
                 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
    // Linear compare filtering: each tap is itself a 2×2 PCF on llvmpipe too.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, atlas_.id(), 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw RenderError("sun shadows: the depth atlas framebuffer is incomplete");
    }
}

void ShadowPass::run(const World& world, FrameContext& frame) {
    // Nothing may sample the atlas while it is drawn into.
    glActiveTexture(GL_TEXTURE0 + texture_unit::sun_shadow);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (resolution_ != settings_.shadow_map_size) {
        allocate(settings_.shadow_map_size);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_.id());
    glClear(GL_DEPTH_BUFFER_BIT);
    // A constant and a slope-scaled depth bias keep lit faces from shadowing
    // themselves (shadow acne) [WIL]; the receivers add a normal offset.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 4.0f);
    FrameContext casters = frame;
    casters.depth_only = true;
    casters.cascades = nullptr;
    for (int i = 0; i < sun_cascade_count; ++i) {
        glViewport(i * resolution_, 0, resolution_, resolution_);
        casters.view_proj = frame.cascades->light_clip[static_cast<std::size_t>(i)];
        // The casters' vertex shaders read view_proj, the block's first member.
        glBindBuffer(GL_UNIFORM_BUFFER, frame.frame_ubo);
        glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(glm::mat4), &casters.view_proj);
        for (const auto& pass : passes_) {
            if (pass->casts_shadows() && pass->wanted(world, frame.visuals)) {
                pass->run(world, casters);
            }
        }
    }
    glBindBuffer(GL_UNIFORM_BUFFER, frame.frame_ubo);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(glm::mat4), &frame.view_proj);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glBindFramebuffer(GL_FRAMEBUFFER, frame.target_fbo);
    glViewport(0, 0, frame.viewport.x, frame.viewport.y);
    glActiveTexture(GL_TEXTURE0 + texture_unit::sun_shadow);
    glBindTexture(GL_TEXTURE_2D, atlas_.id());
    glActiveTexture(GL_TEXTURE0);
}

} // namespace snow
