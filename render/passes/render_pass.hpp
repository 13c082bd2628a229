/// @file render_pass.hpp
/// @brief One step of a frame. The Renderer runs its passes in a fixed list;
/// a pass whose content the world lacks is skipped and costs nothing.
#pragma once

#include "ecs/world.hpp"
#include "render/gl/shader.hpp"
#include <snow/render.hpp>

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

struct SunCascades;

/// What every pass of one frame shares. The "Frame" uniform block is bound,
/// the shared textures are bound to their units (texture_unit) and the depth
/// buffer holds the opaque passes that ran before.
struct FrameContext {
    const ViewCamera& camera;
    const SceneVisuals& visuals;
    glm::mat4 view_proj;
    glm::ivec2 viewport;
    const RenderSettings& settings;
    ProgramCache& programs;
    /// Shader defines of the world's fog ("FOG", "FOG_LAYERED", ...); empty
    /// without a Fog resource, so no fog variant is compiled or run.
    std::vector<std::string> fog_defines;
    bool occlusion = false;   ///< an OcclusionMap is bound to texture_unit::occlusion
    bool software_gl = false; ///< llvmpipe/softpipe: passes may trade detail for speed
    FrameTimings& stats;      ///< passes add their counters
    /// "SUN" with a SceneVisuals::sun, and "SUN_SHADOWS" when its cascades
    /// are drawn: the lit surfaces' variants. Empty without a sun.
    std::vector<std::string> sun_defines;
    const SunCascades* cascades = nullptr; ///< this frame's, when sun shadows are drawn
    /// Drawing shadow casters into the sun's cascades: depth only (depth.frag).
    bool depth_only = false;
    std::uint32_t frame_ubo = 0;  ///< the buffer behind the "Frame" block
    std::uint32_t target_fbo = 0; ///< the framebuffer the frame is drawn into
};

/// The defines of a lit surface's program: the fog's and the sun's.
[[nodiscard]] inline std::vector<std::string> lit_defines(const FrameContext& frame) {
    std::vector<std::string> d = frame.fog_defines;
    d.insert(d.end(), frame.sun_defines.begin(), frame.sun_defines.end());
    return d;
}

/// Interface of a pass. Built-in order (Renderer::pass_names()):
/// "sky" → "meshes" → "snow_surfaces" → "flakes"; the sun's shadows first,
/// moving bodies before "snow_surfaces", far-field snow [LZ] before "flakes" and fog puffs [PE]
/// after it, as the world declares them (or via Renderer::insert_pass).
class RenderPass {
  public:
    virtual ~RenderPass() = default;
    /// Stable name, used in timings and by insert_pass.
    [[nodiscard]] virtual std::string_view name() const = 0;
    /// True if the world or the visuals have something for this pass to draw.
    [[nodiscard]] virtual bool wanted(const World& world, const SceneVisuals& visuals) const = 0;
    /// Reads the world and frame.visuals (never writes them), uploads what changed, draws.
    virtual void run(const World& world, FrameContext& frame) = 0;
    /// Drawn into the sun's shadow cascades too (with frame.depth_only set).
    [[nodiscard]] virtual bool casts_shadows() const { return false; }
    /// Drawn in mask frames (RenderOutput other than color): the passes that
    /// draw opaque surfaces and snow, and what they need.
    [[nodiscard]] virtual bool in_masks() const { return false; }
};

} // namespace snow
