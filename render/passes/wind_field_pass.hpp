/// @file wind_field_pass.hpp
/// @brief The wind field drawn as arrows (wind_arrows.hpp), after every
/// other pass and hidden only by solid geometry, when
/// RenderSettings::show_wind_field is on and the world has a WindField. A debugging view of the air
/// the buildings shape; it reads the field and changes nothing.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"
#include "render/passes/wind_arrows.hpp"

namespace snow {

class WindFieldPass final : public RenderPass {
  public:
    static constexpr std::string_view pass_name = "wind_field";
    /// `settings` (the renderer's) says whether the arrows are wanted.
    explicit WindFieldPass(const RenderSettings& settings) : settings_(settings) {}
    [[nodiscard]] std::string_view name() const override { return pass_name; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;

  private:
    const RenderSettings& settings_;
    GlVertexArray vao_;
    GlBuffer buffer_;
    bool attributes_set_ = false;
    WindArrows arrows_;
};

} // namespace snow
