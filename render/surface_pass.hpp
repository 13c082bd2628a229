/// @file surface_pass.hpp
/// @brief Settled snow: draws each SnowSurface's heightfield mesh
/// (surface_mesh.hpp), rebuilt and re-uploaded only when its snow changed.
#pragma once

#include "render/gl_objects.hpp"
#include "render/render_pass.hpp"
#include "render/surface_mesh.hpp"

#include <cstdint>
#include <map>
#include <vector>

namespace snow {

class SurfacePass final : public RenderPass {
  public:
    [[nodiscard]] std::string_view name() const override { return "snow_surfaces"; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;

  private:
    struct GpuSurface {
        GlVertexArray vao;
        GlBuffer vertices;
        GlBuffer indices;
        GLsizei index_count = 0;
        std::uint32_t nx = 0, nz = 0;
        std::uint64_t fingerprint = 0;
        bool uploaded = false;
        std::uint64_t last_frame = 0;
    };

    std::map<std::uint32_t, GpuSurface> surfaces_; // by Entity::bits
    std::vector<float> vertex_staging_;            // reused across surfaces and frames
    std::vector<std::uint32_t> index_staging_;
    std::uint64_t frame_ = 0;
};

} // namespace snow
