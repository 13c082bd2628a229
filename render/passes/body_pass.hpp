/// @file body_pass.hpp
/// @brief Moving bodies (systems/bodies/body.hpp) drawn where the simulation has
/// them this tick: lit spheres, upright capsules and boxes, read from the
/// World's Body components. A snowball is snow-white and grows with what it
/// carries; a capsule (a walker) wears a dark coat.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"

namespace snow {

class BodyPass final : public RenderPass {
  public:
    static constexpr std::string_view pass_name = "bodies";
    BodyPass();
    [[nodiscard]] std::string_view name() const override { return pass_name; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;
    [[nodiscard]] bool casts_shadows() const override { return true; }
    [[nodiscard]] bool in_masks() const override { return true; }

  private:
    /// A unit shape on the GPU: position, normal and hemisphere side per vertex.
    struct Shape {
        GlVertexArray vao;
        GlBuffer vertices;
        GlBuffer indices;
        GLsizei index_count = 0;
    };
    Shape round_; ///< unit sphere whose hemispheres a capsule pulls apart
    Shape cube_;  ///< unit cube (half size 1)
};

} // namespace snow
