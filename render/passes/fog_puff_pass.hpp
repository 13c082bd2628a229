/// @file fog_puff_pass.hpp
/// @brief The fog-puff pass [PE]: after the flakes, every pixel is
/// fogged by the puffs between the eye and the opaque surface behind it,
/// colour = mix(fog colour, colour, 0.5^(optical depth)), the optical depth
/// in closed form (fog_puffs.hpp). Runs only for a Fog with puffs.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/fog_puffs.hpp"
#include "render/passes/render_pass.hpp"
#include "render/passes/scene_depth.hpp"

namespace snow {

class FogPuffPass final : public RenderPass {
  public:
    static constexpr std::string_view pass_name = "fog_puffs";
    [[nodiscard]] std::string_view name() const override { return pass_name; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;

  private:
    GlVertexArray vao_;
    SceneDepthTexture depth_;
    bool cap_reported_ = false;
};

} // namespace snow
