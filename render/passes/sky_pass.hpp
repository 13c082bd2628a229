/// @file sky_pass.hpp
/// @brief The sky seen through fog. Runs only when the world has a Fog; without
/// one the frame's clear colour is the sky and no fog code runs.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"

namespace snow {

class SkyPass final : public RenderPass {
  public:
    [[nodiscard]] std::string_view name() const override { return "sky"; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;

  private:
    GlVertexArray vao_; // core profile needs a bound VAO even with no attributes
};

} // namespace snow
