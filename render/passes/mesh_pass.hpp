/// @file mesh_pass.hpp
/// @brief Scene meshes (SceneVisuals::meshes), lit by the point lights and ambient,
/// whitened by snow where they face the sky unoccluded [SKY]; a mesh with a
/// base colour texture is drawn in its colour times the texture.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"

#include <cstdint>
#include <map>
#include <memory>

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
        GlBuffer vertices; // position, normal (and texcoord when textured) interleaved
        GlBuffer indices;
        GLsizei index_count = 0;
        bool drawable = false; // false when the mesh data was invalid
        // Meshes are treated as immutable; replacing one changes these.
        const void* source = nullptr;
        const Image* texture = nullptr;
        std::size_t vertex_count = 0, source_index_count = 0;
        std::uint64_t last_frame = 0;
    };
    /// Uploads `mesh`; leaves `gpu.drawable` false (and says why) for bad data.
    static void upload(const MeshRenderable& mesh, GpuMesh& gpu);

    /// A base colour texture on the GPU; holding the image keeps its address
    /// (the key) from being reused by another while it is here.
    struct GpuTexture {
        GlTexture texture;
        std::shared_ptr<const Image> image;
        std::uint64_t last_frame = 0;
    };
    /// The texture of `image`, uploaded with mipmaps on first use.
    GLuint texture_of(const std::shared_ptr<const Image>& image);

    std::map<std::size_t, GpuMesh> meshes_; // by index in SceneVisuals::meshes
    std::map<const Image*, GpuTexture> textures_;
    std::uint64_t frame_ = 0;
};

} // namespace snow
