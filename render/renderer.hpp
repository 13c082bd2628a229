/// @file renderer.hpp
/// @brief The renderer: draws a simulation's World and a scene's visuals
/// (both read only) from a ViewCamera into the current GlContext, as an
/// ordered list of passes.
#pragma once

#include "ecs/world.hpp"
#include "render/camera.hpp"
#include "render/context/gl_context.hpp"
#include "render/frame_timings.hpp"
#include "render/image.hpp"
#include "render/passes/render_pass.hpp"
#include "render/render_settings.hpp"
#include "render/scene_visuals.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

/// Create, use and destroy it with `context` current. Passes, in order:
///   "sky"           fogged sky (only with a Fog resource; else the clear colour)
///   "meshes"        SceneVisuals::meshes, lit, snow-white where exposed [SKY]
///   (moving bodies at this tick's pose: "bodies", inserted before
///    "snow_surfaces" from the first frame whose world has a Body)
///   "snow_surfaces" SnowSurface tiled heightfields + skirts [WF §6]
///   (far-field spectral snow [LZ]: insert_pass("flakes", ...))
///   "flakes"        FlakePool point sprites ([ZCL], [SKY])
///   (fog puffs [PE]: insert_pass("", ...) appends after "flakes")
///   (the wind field's arrows: "wind_field", last, from the first frame with
///    RenderSettings::show_wind_field on and a WindField in the world)
class Renderer {
  public:
    /// Throws RenderError if the context lacks what the renderer needs.
    explicit Renderer(GlContext& context, RenderSettings settings = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Draws one frame of `world` (Simulation::world()) and `visuals` (the
    /// scene loader's meshes, lights and sky) into the context's framebuffer (no swap).
    void render(const World& world, const SceneVisuals& visuals, const ViewCamera& camera);
    /// Per-pass times and counters of the last render().
    [[nodiscard]] const FrameTimings& timings() const;
    /// The framebuffer as an image, top row first (any backend).
    [[nodiscard]] Image read_pixels() const;

    [[nodiscard]] RenderSettings& settings();
    [[nodiscard]] const RenderSettings& settings() const;
    /// Inserts `pass` before the pass named `before`; an empty name appends.
    /// Throws RenderError for an unknown name.
    void insert_pass(std::string_view before, std::unique_ptr<RenderPass> pass);
    [[nodiscard]] std::vector<std::string> pass_names() const;
    /// Shader variants compiled so far (a world without Fog compiles no "FOG" one).
    [[nodiscard]] std::vector<std::string> compiled_variants() const;
    /// True on llvmpipe/softpipe, where distant flakes are thinned by default.
    [[nodiscard]] bool software_gl() const;
    /// GL_RENDERER and GL_VERSION of the context.
    [[nodiscard]] std::string gl_description() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace snow
