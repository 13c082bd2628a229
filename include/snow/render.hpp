/// @file render.hpp
/// @brief The OpenGL 3.3 renderer (target snow::render): GL contexts (OSMesa
/// or EGL headless, a GLFW window) from make_context, or the host's own
/// GlContext, and a Renderer that draws a Simulation and a scene's
/// SceneVisuals from a ViewCamera. GL itself stays private: no GL header is
/// included. Self-contained: the standard library and GLM. See
/// docs/rendering.md.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <snow/error.hpp>
#include <snow/snow.hpp>

namespace snow {

// -- what a scene shows besides the simulation --

enum class FogMode : std::uint8_t {
    exponential, ///< e^(−density·z), [SKY]
    half_life,   ///< 0.5^(d/D), [PE]
    layered,     ///< ∫ density(y) via table E(y), [PE]
};

/// A Gaussian (or Gabor, when frequency > 0) fog puff, [PE].
struct FogPuff {
    glm::vec3 center{0.0f};
    float sigma = 1.0f;
    float density = 0.5f;
    glm::vec3 frequency{0.0f}; ///< Gabor wave vector (rad/m); zero = plain Gaussian
    float phase = 0.0f;
};

/// Fog settings ([PE], [SKY]); absent means no fog code is compiled or run.
struct Fog {
    FogMode mode = FogMode::exponential;
    glm::vec3 color{0.75f, 0.78f, 0.82f};
    float density = 0.04f;       ///< exponential: 1/m
    float half_distance = 30.0f; ///< half_life: D (m)
    float layer_bottom = 0.0f;   ///< layered: density is zero below ..
    float layer_top = 3.0f;      ///< .. and above
    float layer_density = 0.15f; ///< layered: peak density (1/m)
    std::vector<FogPuff> puffs;
};

/// The far-field spectral snow layer [LZ]; absent means no FFT volume is
/// built and no pass runs.
struct SpectralSnow {
    std::uint32_t size_xy = 128;  ///< volume size in x and y (power of two)
    std::uint32_t size_t = 64;    ///< frames in the loop (power of two)
    float speed = 1.0f;           ///< c in ω_t = c·ω_y/|ω|
    float band_low = 4.0f;        ///< lowest spatial frequency (cycles per tile)
    float band_high = 32.0f;      ///< highest
    float opacity = 0.6f;         ///< scales α
    float start_distance = 25.0f; ///< where the particle LOD ends
};

struct Image;

/// A triangle mesh in world space.
struct MeshRenderable {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals; ///< per vertex, same count as positions
    std::vector<std::uint32_t> indices;
    glm::vec3 color{0.6f, 0.6f, 0.6f};
    /// A base colour texture, multiplied by `color` (glTF's baseColorTexture);
    /// meshes sharing an image share one. Null: `color` alone.
    std::shared_ptr<const Image> texture;
    /// Per vertex with a texture, same count as positions: (0, 0) is the
    /// image's top left corner (glTF's convention), repeating beyond [0, 1].
    std::vector<glm::vec2> texcoords;
};

/// A coloured point light ([WF §5] uses three).
struct PointLight {
    glm::vec3 position{0.0f, 5.0f, 0.0f};
    glm::vec3 color{1.0f, 1.0f, 1.0f};
    float intensity = 1.0f;
};

/// A directional light far away (the sun): parallel rays, one colour. With a
/// Sun the renderer draws cascaded shadow maps from it and shades snow as a
/// rough, bright material under a filmic tone curve (docs/rendering.md#the-sun).
struct Sun {
    glm::vec3 direction{0.5f, 0.6f, 0.35f}; ///< towards the sun (any length > 0)
    glm::vec3 color{1.0f, 0.95f, 0.86f};    ///< a low winter sun is a little warm
    float intensity = 2.0f;                 ///< irradiance on a face turned to it
};

/// The view the scene starts with.
struct CameraDef {
    glm::vec3 position{0.0f, 4.0f, 14.0f};
    glm::vec3 target{0.0f, 1.5f, 0.0f};
    float fov_y_deg = 50.0f;
    float near_plane = 0.05f, far_plane = 200.0f;
};

/// Ambient light and sky colour.
struct Environment {
    glm::vec3 ambient{0.18f, 0.2f, 0.24f};
    glm::vec3 sky{0.55f, 0.62f, 0.7f};
};

/// Everything the renderer draws besides the simulation's own state, in draw order.
struct SceneVisuals {
    std::vector<MeshRenderable> meshes;
    std::vector<PointLight> lights; ///< the renderer uses the first 8
    CameraDef camera;
    Environment environment;
    std::optional<Fog> fog;               ///< render-only: the simulation never sees it
    std::optional<SpectralSnow> spectral; ///< render-only
    std::optional<Sun> sun;               ///< render-only: no sun, no shadow pass
};

// -- the view --

/// A free-look camera. yaw = 0 looks along −z, positive yaw turns toward +x;
/// pitch > 0 looks up. Angles in radians, pitch kept inside ±89°.
struct ViewCamera {
    glm::vec3 position{0.0f, 4.0f, 14.0f};
    float yaw = 0.0f;
    float pitch = 0.0f;
    float fov_y_deg = 50.0f;
    float near_plane = 0.05f;
    float far_plane = 200.0f;

    /// The camera a scene starts with (position, look-at target, lens).
    [[nodiscard]] static ViewCamera from_def(const CameraDef& def);
    /// Turns the camera to look at `target` (no change if target == position).
    void look_at(const glm::vec3& target);
    /// Adds to yaw/pitch, clamping pitch.
    void turn(float d_yaw, float d_pitch);
    [[nodiscard]] glm::vec3 forward() const;
    [[nodiscard]] glm::vec3 right() const;
    [[nodiscard]] glm::mat4 view() const;
    [[nodiscard]] glm::mat4 projection(float aspect) const;
};

// -- GL contexts --

/// A GL entry point as returned by a platform's proc-address function.
using GlProc = void (*)();

/// A GL 3.3+ core context and the surface it draws to. All GL work happens on
/// the thread that called make_current().
class GlContext {
  public:
    GlContext();
    virtual ~GlContext() = default;
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    /// Makes the context current and (re)loads the GL entry points from it when
    /// another context was loaded last; throws RenderError if GL < 3.3.
    void make_current();
    /// Presents the frame (no-op for headless surfaces).
    virtual void swap_buffers() = 0;
    /// Drawable size in pixels.
    [[nodiscard]] virtual glm::ivec2 framebuffer_size() const = 0;
    /// The platform's GL proc-address lookup for `name`.
    [[nodiscard]] virtual GlProc proc_address(const char* name) const = 0;
    /// Processes window events (no-op for headless surfaces).
    virtual void poll_events() = 0;
    /// True once the user asked to close the window (never for headless).
    [[nodiscard]] virtual bool should_close() const = 0;
    /// Backend name: "osmesa", "egl" or "glfw".
    [[nodiscard]] virtual std::string_view name() const = 0;
    /// The GL framebuffer object frames are drawn into; 0 is the default one.
    [[nodiscard]] virtual std::uint32_t framebuffer() const { return 0; }

  protected:
    /// Platform make-current; the base class then loads GL through proc_address().
    virtual void bind() = 0;

  private:
    std::uint64_t serial_; ///< unique per context, so a reused address never skips a reload
};

enum class ContextBackend : std::uint8_t {
    automatic, ///< a window if a display is usable, else headless (prints why)
    headless,  ///< OSMesa, no display needed
    window,    ///< GLFW; throws RenderError if no window can be made
    egl,       ///< EGL surfaceless (Mesa), no display needed; throws if unavailable
};

/// What make_context() should create.
struct ContextRequest {
    ContextBackend backend = ContextBackend::automatic;
    int width = 640;
    int height = 480;
    std::string title = "snow";
    bool visible = true; ///< window backend: false for an offscreen window
    bool vsync = true;   ///< window backend: swap interval 1
    bool quiet = false;  ///< automatic: do not print the fallback reason to stderr
};

/// Creates a context (already current, GL loaded). With `automatic`, a window
/// that cannot be made falls back to headless; the reason goes to stderr and to
/// `fallback_reason` (left empty when no fallback happened).
[[nodiscard]] std::unique_ptr<GlContext> make_context(const ContextRequest& request,
                                                      std::string* fallback_reason = nullptr);

// -- images --

/// RGBA, 8 bits per channel, rows top to bottom (as a PNG stores them).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;

    /// Pointer to the 4 channels of pixel (x, y), y = 0 at the top.
    [[nodiscard]] const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x)) *
                                 4u;
    }
};

/// `image` as the bytes of a PNG file, for a host that stores them itself;
/// throws RenderError when its size does not match its data.
[[nodiscard]] std::vector<std::uint8_t> encode_png(const Image& image);

/// Writes `image` as a PNG, all or nothing (a temporary file beside `path`,
/// flushed and renamed into place); throws RenderError naming the path and
/// the step that failed.
void write_png(const std::filesystem::path& path, const Image& image);

/// Reads a PNG as RGBA8; throws RenderError naming the path. For trusted files
/// only (golden images): stb_image is not hardened against hostile input.
[[nodiscard]] Image read_png(const std::filesystem::path& path);

// -- the renderer --

/// When distant flakes are thinned (level of detail).
enum class FlakeLod : std::uint8_t {
    automatic, ///< only on a software rasteriser (llvmpipe, softpipe)
    always,
    never,
};

/// What a frame writes: the image, or one of its masks (AOVs) of the same
/// size, white where the pixel shows snow / lies in the sun's shadow. A mask
/// frame draws only the opaque surfaces (meshes, bodies, snow) on black.
enum class RenderOutput : std::uint8_t {
    color,
    snow_mask,   ///< how much of the pixel is snow cover (0..1)
    shadow_mask, ///< how much of the sun the shadow maps hold back there (0..1)
};

struct RenderSettings {
    glm::vec3 snow_color{0.94f, 0.96f, 1.0f};
    /// How white exposed, sky-facing meshes get, 0..1 ([SKY] snow blend).
    float mesh_snow = 1.0f;
    /// How white the moving bodies' up-facing parts get where the sky map
    /// shows them open to the sky, 0..1 (render-only, docs/rendering.md).
    float body_snow = 1.0f;
    /// A fragment counts as seen from the sky if y >= occlusion top_y − this (m).
    float exposure_tolerance =
        0.05f; ///< the sky map's own tolerance (a static_assert in renderer.cpp)
    /// Snow cover thinner than this (m) is not drawn; the bare top shows.
    float min_snow_depth = 0.002f;
    /// Level of detail of snow surfaces: a tile samples every 2^l-th cell, the
    /// coarsest level whose samples lie at most this many pixels apart ...
    float surface_spacing_px = 4.0f;
    /// ... widened (by √2 steps) until a surface draws at most this many
    /// heightfield samples per frame (llvmpipe is bound by its triangles).
    std::uint32_t surface_samples = 20000;
    /// Falloff k of point lights: intensity / (1 + k·d²), d in metres.
    float light_falloff = 0.01f;

    /// Sprites are drawn this many times the flake's physical diameter.
    float flake_scale = 3.0f;
    float flake_min_px = 1.5f; ///< smaller sprites are enlarged and made fainter
    float flake_max_px = 48.0f;
    float flake_alpha = 0.9f;
    /// Flake alpha is multiplied by e^(−d / fade): far flakes are fainter [SKY].
    float flake_fade_distance = 40.0f;
    FlakeLod flake_lod = FlakeLod::automatic;
    /// Beyond this distance (m) only a fraction (lod_distance / d)² of flakes is drawn.
    float lod_distance = 12.0f;

    /// With a SceneVisuals::sun: draw its cascaded shadow maps (off: lit everywhere).
    bool sun_shadows = true;
    /// Sun shadows reach this far from the eye (m, capped at the far plane) ...
    float shadow_distance = 50.0f;
    /// ... in three cascades of this many texels square each (16 to 2048).
    int shadow_map_size = 1024;
    /// With a sun: scales the exposure the sun sets (flat snow in full sun at
    /// about 220 of 255) before the filmic tone curve.
    float exposure = 1.0f;
    /// With a sun: two octaves of world-anchored detail normals on the snow
    /// surfaces (docs/rendering.md, "Snow detail") ...
    bool detail_normals = true;
    /// ... and glints of the sun in them.
    bool sparkle = true;
    RenderOutput output = RenderOutput::color;

    /// Draw the world's wind field (if it has one) as arrows coloured by speed.
    bool show_wind_field = false;

    /// glFinish after each pass so per-pass times include GPU work (slower).
    bool timing_mode = false;
};

struct PassTiming {
    std::string name;
    bool ran = false;    ///< false when the world had nothing for the pass
    double cpu_ms = 0.0; ///< wall time around the pass (includes GPU work in timing mode)
};

struct FrameTimings {
    std::vector<PassTiming> passes; ///< "setup" (uniforms, shared textures), then each pass
    double frame_ms = 0.0;          ///< whole render() call
    bool synchronous = false;       ///< RenderSettings::timing_mode was on
    std::uint32_t flakes_alive = 0;
    std::uint32_t flakes_drawn = 0;           ///< after culling and level of detail
    std::uint32_t surfaces_uploaded = 0;      ///< snow surfaces with a changed tile this frame
    std::uint32_t surface_tiles_uploaded = 0; ///< their changed tiles (only these are re-uploaded)
    std::uint32_t surface_tiles_drawn = 0;    ///< after culling, every level of detail
    std::uint32_t surface_samples = 0;        ///< heightfield samples of those tiles
    std::uint32_t meshes_uploaded = 0;        ///< scene meshes uploaded this frame
};

/// Create, use and destroy it with `context` current. Passes, in order:
///   ("sun_shadows": the sun's cascaded shadow maps, first, from the first
///    frame with SceneVisuals::sun, run while RenderSettings::sun_shadows)
///   "sky"           fogged sky (only with SceneVisuals::fog; else the clear colour)
///   "meshes"        SceneVisuals::meshes, lit, snow-white where exposed [SKY]
///   (moving bodies at this tick's pose: "bodies", inserted before
///    "snow_surfaces" from the first frame whose world has a Body)
///   "snow_surfaces" SnowSurface tiled heightfields + skirts [WF §6]
///   ("spectral": far-field spectral snow [LZ], from the first frame with
///    SceneVisuals::spectral)
///   "flakes"        the airborne flakes as point sprites ([ZCL], [SKY])
///   ("fog_puffs": Gaussian and Gabor puffs [PE], with fog puffs declared)
///   ("wind_field": the wind field's arrows, last, from the first frame with
///    RenderSettings::show_wind_field on and a wind field in the simulation)
class Renderer {
  public:
    /// Throws RenderError if the context lacks what the renderer needs.
    explicit Renderer(GlContext& context, RenderSettings settings = {});
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Draws one frame of `sim` and `visuals` (the scene loader's meshes,
    /// lights, sky and fog) into the context's framebuffer (no swap).
    void render(const Simulation& sim, const SceneVisuals& visuals, const ViewCamera& camera);
    /// Per-pass times and counters of the last render().
    [[nodiscard]] const FrameTimings& timings() const;
    /// The framebuffer as an image, top row first (any backend).
    [[nodiscard]] Image read_pixels() const;

    [[nodiscard]] RenderSettings& settings();
    [[nodiscard]] const RenderSettings& settings() const;
    [[nodiscard]] std::vector<std::string> pass_names() const;
    /// Shader variants compiled so far (visuals without fog compile no "FOG" one).
    [[nodiscard]] std::vector<std::string> compiled_variants() const;
    /// True on llvmpipe/softpipe, where distant flakes are thinned by default.
    [[nodiscard]] bool software_gl() const;
    /// GL_RENDERER and GL_VERSION of the context.
    [[nodiscard]] std::string gl_description() const;

    struct Impl; ///< render/renderer_internals.hpp

  private:
    friend struct RendererAccess;
    std::unique_ptr<Impl> impl_;
};

} // namespace snow
