/// @file spectral_pass.hpp
/// @brief Far-field snow [LZ]: the periodic opacity volume α(x, y, t)
/// uploaded once as a 3-D texture and composited over the scene behind the
/// particle flakes, I = I_snow·α + (1 − α)·I_background, tiled over view
/// directions and looped in time. Runs only with a SpectralSnow resource.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"
#include "render/passes/scene_depth.hpp"
#include <snow/render.hpp>

#include <cstdint>
#include <optional>

namespace snow {

/// Texture unit of the volume (sampler3D spectral_volume).
inline constexpr int spectral_volume_unit = 2;

class SpectralPass final : public RenderPass {
  public:
    static constexpr std::string_view pass_name = "spectral_snow";
    [[nodiscard]] std::string_view name() const override { return pass_name; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;

  private:
    void build(const SpectralSnow& s, std::uint64_t seed);

    GlVertexArray vao_; // the full-screen triangle needs no attributes
    GlTexture volume_;
    SceneDepthTexture depth_;
    std::optional<SpectralSnow> built_for_;
    std::uint64_t built_seed_ = 0;
    bool invalid_reported_ = false;
};

} // namespace snow
