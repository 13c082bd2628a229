/// @file shadow_pass.hpp
/// @brief The sun's shadow maps [WIL]: the passes that cast shadows (meshes,
/// bodies) drawn depth only from the sun into one atlas of cascades [CSM],
/// which the lit surfaces then sample with 3×3 PCF [PCF]. Only with a
/// SceneVisuals::sun and RenderSettings::sun_shadows.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"

#include <memory>
#include <vector>

namespace snow {

class ShadowPass final : public RenderPass {
  public:
    static constexpr std::string_view pass_name = "sun_shadows";
    /// `passes` is the renderer's list; the casters among them are drawn.
    ShadowPass(const std::vector<std::unique_ptr<RenderPass>>& passes,
               const RenderSettings& settings);
    [[nodiscard]] std::string_view name() const override { return pass_name; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;
    [[nodiscard]] bool in_masks() const override { return true; }

  private:
    /// (Re)allocates the atlas for `resolution` texels per cascade.
    void allocate(int resolution);

    const std::vector<std::unique_ptr<RenderPass>>& passes_;
    const RenderSettings& settings_;
    GlTexture atlas_; ///< DEPTH_COMPONENT24, compare mode on: a sampler2DShadow
    GlFramebuffer fbo_;
    int resolution_ = 0;
};

} // namespace snow
