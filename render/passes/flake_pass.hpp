/// @file flake_pass.hpp
/// @brief Falling flakes as GL_POINTS sprites [ZCL], uploaded from the
/// FlakePool with one buffer upload per frame: alive, visible flakes are
/// compacted on the CPU into a preallocated staging array.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/flake_selection.hpp"
#include "render/passes/render_pass.hpp"

#include <vector>

namespace snow {

class FlakePass final : public RenderPass {
  public:
    [[nodiscard]] std::string_view name() const override { return "flakes"; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;

  private:
    GlVertexArray vao_;
    GlBuffer buffer_;
    bool attributes_set_ = false;
    std::vector<float> staging_; // 4 floats per pool slot, grown only with the pool
};

} // namespace snow
