/// @file surface_pass.hpp
/// @brief Settled snow: every SnowSurface drawn as a displaced heightfield
/// over its bare top, cut into tiles with distance-based level of detail
/// (surface_tiles.hpp). Heights live in a texture per surface; only tiles
/// whose cells changed are re-uploaded.
#pragma once

#include "render/gl/gl_objects.hpp"
#include "render/passes/render_pass.hpp"
#include "render/passes/surface_tiles.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <unordered_map>
#include <vector>

namespace snow {

/// Texture unit of a surface's cells (sampler2D surface_cells).
inline constexpr int surface_cells_unit = 4;

class SurfacePass final : public RenderPass {
  public:
    [[nodiscard]] std::string_view name() const override { return "snow_surfaces"; }
    [[nodiscard]] bool wanted(const World& world, const SceneVisuals& visuals) const override;
    void run(const World& world, FrameContext& frame) override;
    [[nodiscard]] bool in_masks() const override { return true; }

  private:
    /// The index list of a tile with edges, for the level and skirts it was
    /// last drawn with.
    struct EdgePatch {
        GlBuffer indices;
        GLsizei count = 0;
        std::uint32_t level = 0, skirts = 0, version = 0;
        bool built = false;
    };
    struct GpuSurface {
        GlTexture cells; // RG32F: snow top, bare top per cell
        SurfaceTiles tiles;
        std::unordered_map<std::uint32_t, EdgePatch> edge_patches; // by tile index
        bool drawable = false;
        std::uint64_t last_frame = 0;
    };
    struct Patch {
        GlBuffer indices;
        GLsizei count = 0; ///< 0 until first used
    };

    void upload(GpuSurface& gpu, const SnowSurface& surface, FrameContext& frame);
    void draw(GpuSurface& gpu, const SnowSurface& surface, FrameContext& frame);
    const Patch& patch(std::uint32_t level, std::uint32_t skirts);
    const EdgePatch& edge_patch(GpuSurface& gpu, const SnowSurface& surface, const TileDraw& d);

    std::map<std::uint32_t, GpuSurface> surfaces_; // by Entity::bits
    /// Index lists by level and skirt bits, made on first use and shared by
    /// every tile of every surface.
    std::array<std::array<Patch, skirt_all + 1>, surface_tile_levels> patches_;
    GlVertexArray vao_;
    GlBuffer instances_; // first cell of each drawn tile, in draw order
    std::vector<TileDraw> draws_;
    std::vector<glm::ivec2> instance_staging_;
    std::vector<float> texel_staging_;
    std::vector<std::uint32_t> index_staging_;
    std::uint64_t frame_ = 0;
    bool too_large_reported_ = false;
};

} // namespace snow
