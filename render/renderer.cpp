#include "render/renderer_internals.hpp"

#include "render/gl/frame_block.hpp"
#include "render/passes/body_pass.hpp"
#include "render/passes/flake_pass.hpp"
#include "render/passes/fog_puff_pass.hpp"
#include "render/passes/fog_table.hpp"
#include "render/passes/mesh_pass.hpp"
#include "render/passes/scene_textures.hpp"
#include "render/passes/shadow_pass.hpp"
#include "render/passes/sky_pass.hpp"
#include "render/passes/spectral_pass.hpp"
#include "render/passes/sun_cascades.hpp"
#include "render/passes/surface_pass.hpp"
#include "render/passes/wind_field_pass.hpp"
#include "render/visual_rules.hpp"
#include "systems/api/simulation_internals.hpp"
#include "systems/bodies/body.hpp"
#include "systems/sky/occlusion.hpp"
#include <snow/error.hpp>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace snow {

// The public header cannot name the simulation's constant; the two must agree.
static_assert(RenderSettings{}.exposure_tolerance == occlusion_tolerance);

namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

std::string gl_string(GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return s != nullptr ? std::string(s) : std::string();
}

/// A finite value ≥ 0, else 0: bad fog numbers give no fog instead of NaN pixels.
float clamp_non_negative(float v) {
    return std::isfinite(v) && v > 0.0f ? v : 0.0f;
}

std::vector<std::string> fog_defines(const Fog* fog) {
    if (fog == nullptr) {
        return {};
    }
    switch (fog->mode) {
    case FogMode::exponential:
        return {"FOG", "FOG_EXPONENTIAL"};
    case FogMode::half_life:
        return {"FOG", "FOG_HALF_LIFE"};
    case FogMode::layered:
        return {"FOG", "FOG_LAYERED"};
    }
    return {};
}

/// The exposure a sun sets, like a photographer's "sunny 16" rule [S16]: from
/// the sun alone, not the lamps, so that flat snow in full sun comes out at
/// the same radiance (1.1 before the filmic curve: about 220 of 255) whatever
/// the sun's strength; `setting` (RenderSettings::exposure) scales it. A sun
/// lower than 12° is metered as if at 12°.
float sun_exposure(const Sun& sun, float setting) {
    constexpr float sunlit_snow = 1.1f;
    constexpr float snow_albedo = 0.9f; // as in common.glsl [WAR]
    const float height = std::max(glm::normalize(sun.direction).y, 0.2f);
    const float flat = snow_albedo * clamp_non_negative(sun.intensity) * height;
    return flat > 0.0f ? clamp_non_negative(setting) * sunlit_snow / flat : 0.0f;
}

GlContext& made_current(GlContext& c) {
    c.make_current();
    return c;
}

} // namespace

struct Renderer::Impl {
    // `context` is declared first: it is made current before any GL object is created.
    Impl(GlContext& c, const RenderSettings& s) : context(made_current(c)), settings(s) {}

    GlContext& context;
    RenderSettings settings;
    ProgramCache programs;
    GlBuffer frame_ubo;
    OcclusionTexture occlusion;
    FogTableTexture fog_table;
    std::vector<std::unique_ptr<RenderPass>> passes;
    FrameTimings timings;
    bool software = false;
    std::string description;

    void fill_block(FrameBlock& b, const World& world, const SceneVisuals& visuals,
                    const ViewCamera& camera, const glm::mat4& view_proj, glm::ivec2 viewport,
                    bool has_occlusion, const SunCascades* cascades) const;
    void add_effect_passes(const World& world, const SceneVisuals& visuals);
    [[nodiscard]] bool has_pass(std::string_view name) const;
};

Renderer::Renderer(GlContext& context, RenderSettings settings)
    : impl_(std::make_unique<Impl>(context, settings)) {
    const std::string renderer = gl_string(GL_RENDERER);
    impl_->description = renderer + " / " + gl_string(GL_VERSION);
    impl_->software = renderer.find("llvmpipe") != std::string::npos ||
                      renderer.find("softpipe") != std::string::npos ||
                      renderer.find("swrast") != std::string::npos;
    impl_->passes.push_back(std::make_unique<SkyPass>());
    // Snow after the meshes it lies on: it is blended over them by incline.
    impl_->passes.push_back(std::make_unique<MeshPass>());
    impl_->passes.push_back(std::make_unique<SurfacePass>());
    impl_->passes.push_back(std::make_unique<FlakePass>());
    glBindBuffer(GL_UNIFORM_BUFFER, impl_->frame_ubo.id());
    glBufferData(GL_UNIFORM_BUFFER, sizeof(FrameBlock), nullptr, GL_DYNAMIC_DRAW);
    glBindBufferBase(GL_UNIFORM_BUFFER, frame_block_binding, impl_->frame_ubo.id());
}

Renderer::~Renderer() {
    // GL names belong to this context: delete them there, not in whichever is current.
    try {
        impl_->context.make_current();
    } catch (const RenderError&) {
        // The context is unusable; its objects die with it.
    }
}

void Renderer::Impl::fill_block(FrameBlock& b, const World& world, const SceneVisuals& visuals,
                                const ViewCamera& camera, const glm::mat4& view_proj,
                                glm::ivec2 viewport, bool has_occlusion,
                                const SunCascades* cascades) const {
    b.view_proj = view_proj;
    b.inv_view_proj = glm::inverse(view_proj);
    b.camera_pos = glm::vec4(camera.position, 1.0f);
    const float tan_half = std::tan(glm::radians(camera.fov_y_deg) * 0.5f);
    b.lens = {static_cast<float>(viewport.y) / (2.0f * tan_half), camera.near_plane,
              camera.far_plane, 0.0f};
    const Environment& env = visuals.environment;
    b.ambient = glm::vec4(env.ambient, 0.0f);
    b.sky = glm::vec4(env.sky, 0.0f);
    b.snow_color = glm::vec4(settings.snow_color, std::clamp(settings.mesh_snow, 0.0f, 1.0f));
    b.flake = {settings.flake_min_px, std::max(settings.flake_min_px, settings.flake_max_px),
               settings.flake_alpha,
               settings.flake_fade_distance > 0.0f ? 1.0f / settings.flake_fade_distance : 0.0f};
    b.light_params = {clamp_non_negative(settings.light_falloff), 0.0f, 0.0f, 0.0f};
    int lights = 0;
    for (const PointLight& l : visuals.lights) {
        if (lights < max_point_lights) {
            b.light_pos[lights] = glm::vec4(l.position, l.intensity);
            b.light_color[lights] = glm::vec4(l.color, 0.0f);
            ++lights;
        }
    }
    if (const Sun* sun = visuals.sun ? &*visuals.sun : nullptr) {
        // A declared sun is shaded apart from the ambient (shade() in common.glsl).
        b.sun = glm::vec4(glm::normalize(sun->direction), 0.0f);
        b.sun_color = glm::vec4(sun->color * clamp_non_negative(sun->intensity),
                                sun_exposure(*sun, settings.exposure));
    } else {
        // A scene without lights still shows its shapes: a soft sun from above.
        b.sun = lights == 0 ? glm::vec4(glm::normalize(glm::vec3(0.3f, 1.0f, 0.4f)), 0.8f)
                            : glm::vec4(0.0f);
    }
    if (cascades != nullptr) {
        b.view_forward = glm::vec4(camera.forward(), 0.0f);
        for (int i = 0; i < sun_cascade_count; ++i) {
            const auto c = static_cast<std::size_t>(i);
            b.sun_atlas[i] = cascades->to_atlas[c];
            b.cascade_far[i] = cascades->far[c];
            b.cascade_texel[i] = cascades->texel[c];
        }
        b.cascade_texel.w = 1.0f / static_cast<float>(settings.shadow_map_size);
    }
    b.snow_detail = {settings.detail_normals ? 1.0f : 0.0f, settings.sparkle ? 1.0f : 0.0f, 0.0f,
                     0.0f};
    b.counts = {lights, 0, 0, static_cast<int>(settings.output)};
    if (const Fog* fog = visuals.fog ? &*visuals.fog : nullptr) {
        const float fog_param = fog->mode == FogMode::half_life
                                    ? (fog->half_distance > 0.0f ? 1.0f / fog->half_distance : 0.0f)
                                    : clamp_non_negative(fog->density);
        b.fog_color = glm::vec4(fog->color, clamp_non_negative(fog_param));
        // An empty or non-finite layer keeps a valid span for the shader; its table is all zero.
        const bool valid_layer = std::isfinite(fog->layer_bottom) &&
                                 std::isfinite(fog->layer_top) &&
                                 fog->layer_top > fog->layer_bottom;
        b.fog_layer = {valid_layer ? fog->layer_bottom : 0.0f, valid_layer ? fog->layer_top : 1.0f,
                       static_cast<float>(fog_table_size), 0.0f};
    }
    if (has_occlusion) {
        const auto& map = world.resource<OcclusionMap>();
        b.occlusion = {map.x0, map.z0, 1.0f / map.texel, settings.exposure_tolerance};
        b.occlusion_shear = {map.shear_x, map.shear_z, 0.0f, 0.0f};
        b.counts.y = static_cast<int>(map.width);
        b.counts.z = static_cast<int>(map.height);
    }
}

bool Renderer::Impl::has_pass(std::string_view name) const {
    return std::any_of(passes.begin(), passes.end(),
                       [&](const auto& p) { return p->name() == name; });
}

void Renderer::Impl::add_effect_passes(const World& world, const SceneVisuals& visuals) {
    // Draw only what the scene calls for: an effect's pass (and its FFT volume or
    // shader) exists from the first frame whose world declares the effect.
    if (visuals.spectral && !has_pass(SpectralPass::pass_name)) {
        // Behind the particle flakes ([LZ] composites over the background).
        const auto flakes = std::find_if(passes.begin(), passes.end(),
                                         [](const auto& p) { return p->name() == "flakes"; });
        passes.insert(flakes, std::make_unique<SpectralPass>());
    }
    if (visuals.sun && !has_pass(ShadowPass::pass_name)) {
        // First: the lit passes sample the cascades it draws.
        passes.insert(passes.begin(), std::make_unique<ShadowPass>(passes, settings));
    }
    if (world.count<Body>() > 0 && !has_pass(BodyPass::pass_name)) {
        // Opaque, beside the meshes: the snow surfaces blend over both.
        const auto surfaces = std::find_if(passes.begin(), passes.end(), [](const auto& p) {
            return p->name() == "snow_surfaces";
        });
        passes.insert(surfaces, std::make_unique<BodyPass>());
    }
    const auto wind_arrows = std::find_if(passes.begin(), passes.end(), [](const auto& p) {
        return p->name() == WindFieldPass::pass_name;
    });
    if (visuals.fog && !visuals.fog->puffs.empty() && !has_pass(FogPuffPass::pass_name)) {
        // Over everything, flakes included; only the wind's arrows go after it.
        passes.insert(wind_arrows, std::make_unique<FogPuffPass>());
    }
    if (settings.show_wind_field && world.has_resource<WindField>() &&
        !has_pass(WindFieldPass::pass_name)) {
        passes.push_back(std::make_unique<WindFieldPass>(settings)); // last: a view of the air
    }
}

struct RendererAccess {
    static Renderer::Impl& impl(Renderer& r) { return *r.impl_; }
};

void Renderer::render(const Simulation& sim, const SceneVisuals& visuals,
                      const ViewCamera& camera) {
    render_world(*this, world_of(sim), visuals, camera);
}

void render_world(Renderer& renderer, const World& world, const SceneVisuals& visuals,
                  const ViewCamera& camera) {
    Renderer::Impl& m = RendererAccess::impl(renderer);
    const Clock::time_point frame_start = Clock::now();
    m.context.make_current();
    m.add_effect_passes(world, visuals);
    FrameTimings& t = m.timings;
    t.synchronous = m.settings.timing_mode;
    t.flakes_alive = t.flakes_drawn = t.surfaces_uploaded = t.meshes_uploaded = 0;
    t.surface_tiles_uploaded = t.surface_tiles_drawn = t.surface_samples = 0;
    t.passes.resize(m.passes.size() + 1);
    t.passes[0].name = "setup";

    const glm::ivec2 viewport = m.context.framebuffer_size();
    const float aspect =
        static_cast<float>(viewport.x) / static_cast<float>(std::max(viewport.y, 1));
    const glm::mat4 view_proj = camera.projection(aspect) * camera.view();
    const OcclusionMap* map = world.try_resource<OcclusionMap>();
    const bool has_occlusion =
        map != nullptr && map->width > 0 && map->height > 0 && map->texel > 0.0f;
    const Fog* fog = visuals.fog ? &*visuals.fog : nullptr;
    if (visuals.sun) {
        // Its direction is normalised below: a host's bad sun is refused, not drawn as NaN.
        if (const Invalid error = validate(*visuals.sun); !error.empty()) {
            throw RenderError("SceneVisuals::" + error.text());
        }
    }
    const bool sun_shadows = visuals.sun && m.settings.sun_shadows;
    std::optional<SunCascades> cascades;
    if (sun_shadows) {
        if (!(m.settings.shadow_map_size >= 16 && m.settings.shadow_map_size <= 2048)) {
            throw RenderError("RenderSettings::shadow_map_size must be in [16, 2048] (got " +
                              std::to_string(m.settings.shadow_map_size) + ")");
        }
        cascades = fit_sun_cascades(camera, aspect, visuals.sun->direction,
                                    clamp_non_negative(m.settings.shadow_distance),
                                    m.settings.shadow_map_size);
    }
    const bool mask = m.settings.output != RenderOutput::color;

    FrameBlock block;
    m.fill_block(block, world, visuals, camera, view_proj, viewport, has_occlusion,
                 cascades ? &*cascades : nullptr);
    glBindBuffer(GL_UNIFORM_BUFFER, m.frame_ubo.id());
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof(FrameBlock), &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, frame_block_binding, m.frame_ubo.id());
    if (has_occlusion) {
        m.occlusion.update(*map);
        m.occlusion.bind(texture_unit::occlusion);
    }
    if (fog != nullptr && fog->mode == FogMode::layered) {
        m.fog_table.update(*fog);
        m.fog_table.bind(texture_unit::fog_table);
    }
    // Reset state another GL user (e.g. an overlay UI) may have left behind.
    glBindFramebuffer(GL_FRAMEBUFFER, m.context.framebuffer());
    glViewport(0, 0, viewport.x, viewport.y);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    if (mask) {
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f); // the sky is neither snow nor shadow
    } else {
        glClearColor(block.sky.r, block.sky.g, block.sky.b, 1.0f);
    }
    glClearDepth(1.0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (m.settings.timing_mode) {
        glFinish();
    }
    t.passes[0].ran = true;
    t.passes[0].cpu_ms = ms_since(frame_start);

    std::vector<std::string> sun_defines;
    if (visuals.sun) {
        sun_defines.emplace_back("SUN");
        if (sun_shadows) {
            sun_defines.emplace_back("SUN_SHADOWS");
        }
    }
    FrameContext frame{camera,
                       visuals,
                       view_proj,
                       viewport,
                       m.settings,
                       m.programs,
                       fog_defines(fog),
                       has_occlusion,
                       m.software,
                       t,
                       std::move(sun_defines),
                       cascades ? &*cascades : nullptr,
                       false,
                       m.frame_ubo.id(),
                       m.context.framebuffer()};
    for (std::size_t i = 0; i < m.passes.size(); ++i) {
        RenderPass& pass = *m.passes[i];
        PassTiming& pt = t.passes[i + 1];
        pt.name = pass.name();
        pt.ran = pass.wanted(world, visuals) && (!mask || pass.in_masks());
        pt.cpu_ms = 0.0;
        if (!pt.ran) {
            continue;
        }
        const Clock::time_point t0 = Clock::now();
        pass.run(world, frame);
        if (m.settings.timing_mode) {
            glFinish();
        }
        pt.cpu_ms = ms_since(t0);
    }
    t.frame_ms = ms_since(frame_start);
}

const FrameTimings& Renderer::timings() const {
    return impl_->timings;
}

Image Renderer::read_pixels() const {
    impl_->context.make_current();
    const glm::ivec2 size = impl_->context.framebuffer_size();
    Image image;
    image.width = size.x;
    image.height = size.y;
    const std::size_t row = static_cast<std::size_t>(size.x) * 4u;
    std::vector<std::uint8_t> bottom_up(row * static_cast<std::size_t>(size.y));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, impl_->context.framebuffer());
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, bottom_up.data());
    // GL rows start at the bottom (OSMesa's buffer too); PNG rows start at the top.
    image.rgba.resize(bottom_up.size());
    for (int y = 0; y < size.y; ++y) {
        std::memcpy(image.rgba.data() + static_cast<std::size_t>(y) * row,
                    bottom_up.data() + static_cast<std::size_t>(size.y - 1 - y) * row, row);
    }
    return image;
}

RenderSettings& Renderer::settings() {
    return impl_->settings;
}
const RenderSettings& Renderer::settings() const {
    return impl_->settings;
}

void insert_pass(Renderer& renderer, std::string_view before, std::unique_ptr<RenderPass> pass) {
    if (!pass) {
        throw RenderError("insert_pass: null pass");
    }
    auto& passes = RendererAccess::impl(renderer).passes;
    if (before.empty()) {
        passes.push_back(std::move(pass));
        return;
    }
    const auto it = std::find_if(passes.begin(), passes.end(),
                                 [&](const auto& p) { return p->name() == before; });
    if (it == passes.end()) {
        throw RenderError("insert_pass: no pass named '" + std::string(before) + "'");
    }
    passes.insert(it, std::move(pass));
}

std::vector<std::string> Renderer::pass_names() const {
    std::vector<std::string> names;
    for (const auto& p : impl_->passes) {
        names.emplace_back(p->name());
    }
    return names;
}

std::vector<std::string> Renderer::compiled_variants() const {
    return impl_->programs.variants();
}

bool Renderer::software_gl() const {
    return impl_->software;
}

std::string Renderer::gl_description() const {
    return impl_->description;
}

} // namespace snow
