/// @file mesh_pass.hpp
/// @brief Scene meshes (SceneVisuals::meshes), lit by the point lights and ambient,
/// whitened by snow where they face the sky unoccluded [SKY].
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"

#include <cstdint>
#include <map>

namespace snow {

class MeshPass final : public RenderPass {
  public:
    [[nodiscard]] std::string_view name() const override { return "meshes"; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;
    [[nodiscard]] bool casts_shadows() const override { return true; }
    [[nodiscard]] bool in_masks() const override { return true; }

  private:
    struct GpuMesh {
        GlVertexArray vao;
        GlBuffer vertices; // position, normal interleaved
        GlBuffer indices;
        GLsizei index_count = 0;
        bool drawable = false; // false when the mesh data was invalid
        // Meshes are treated as immutable; replacing one changes these.
        const void* source = nullptr;
        std::size_t vertex_count = 0, source_index_count = 0;
        std::uint64_t last_frame = 0;
    };
    /// Uploads `mesh`; leaves `gpu.drawable` false (and says why) for bad data.
    static void upload(const MeshRenderable& mesh, GpuMesh& gpu);

    std::map<std::size_t, GpuMesh> meshes_; // by index in SceneVisuals::meshes
    std::uint64_t frame_ = 0;
};

} // namespace snow
