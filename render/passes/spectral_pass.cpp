#include "render/passes/spectral_pass.hpp"

#include "render/gl/fullscreen.hpp"
#include "render/passes/far_field.hpp"
#include "render/passes/spectral_volume.hpp"
#include "render/visual_rules.hpp"
#include "systems/core/sim_config.hpp"
#include "systems/flakes/emitter.hpp"
#include "systems/flakes/snowfall.hpp"
#include "systems/wind/wind.hpp"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

namespace snow {

namespace {

/// The settings the volume depends on (speed, opacity and start only change drawing).
bool same_volume(const SpectralSnow& a, const SpectralSnow& b) {
    return a.size_xy == b.size_xy && a.size_t == b.size_t && a.band_low == b.band_low &&
           a.band_high == b.band_high;
}

/// Simulated seconds of the world's clock (0 without one); render reads, never writes.
double world_seconds(const World& world) {
    const SimClock* clock = world.try_resource<SimClock>();
    const SimConfig* config = world.try_resource<SimConfig>();
    if (clock == nullptr || config == nullptr) {
        return 0.0;
    }
    return static_cast<double>(clock->tick) * static_cast<double>(config->dt);
}

/// Sideways drift per metre of fall seen along the camera's azimuth tangent:
/// a flake at any depth moves (w_t, −v_fall)/d in (azimuth, elevation), so the
/// ratio is depth-free and one shear of the volume matches every depth.
float wind_shear(const World& world, const ViewCamera& camera, float fall_speed) {
    const Wind* wind = world.try_resource<Wind>();
    if (wind == nullptr) {
        return 0.0f;
    }
    const glm::vec3 f = camera.forward();
    const float azimuth = std::atan2(f.x, -f.z);
    const glm::vec3 tangent(std::cos(azimuth), 0.0f, std::sin(azimuth));
    const float shear = glm::dot(wind->current, tangent) / fall_speed;
    return std::isfinite(shear) ? std::clamp(shear, -8.0f, 8.0f) : 0.0f;
}

/// NDC depth of the plane the layer is drawn on: view depth start·cos θ, θ the
/// angle to the frustum's corner, so every pixel that may see snow beyond
/// `start` (distance ≥ view depth) passes the depth test and nearer ones fail.
float layer_depth(const FrameContext& frame, float start) {
    const ViewCamera& cam = frame.camera;
    const float aspect =
        static_cast<float>(frame.viewport.x) / static_cast<float>(std::max(frame.viewport.y, 1));
    const float tan_half = std::tan(glm::radians(cam.fov_y_deg) * 0.5f);
    const float cos_corner =
        1.0f / std::sqrt(1.0f + tan_half * tan_half * (1.0f + aspect * aspect));
    const float z = std::clamp(start * cos_corner, cam.near_plane, cam.far_plane);
    const glm::vec4 clip = cam.projection(aspect) * glm::vec4(0.0f, 0.0f, -z, 1.0f);
    return std::min(clip.z / clip.w, 1.0f);
}

/// Mean still-air fall speed (m/s) of the world's emitters (Emitter defaults
/// without any): the speed of the particles the far field continues.
float particle_fall_speed(const World& world) {
    double sum = 0.0;
    int count = 0;
    world.each<Emitter>([&](Entity, const Emitter& e) {
        sum += spectrum_means(e).fall_speed;
        ++count;
    });
    if (count == 0) {
        return static_cast<float>(spectrum_means(Emitter{}).fall_speed);
    }
    const double mean = sum / count;
    return std::isfinite(mean) && mean > 0.0 ? static_cast<float>(mean) : 1.0f;
}

} // namespace

bool SpectralPass::wanted(const World& /*world*/, const SceneVisuals& visuals) const {
    return visuals.spectral.has_value();
}

void SpectralPass::build(const SpectralSnow& s, std::uint64_t seed) {
    const SpectralVolume volume = build_spectral_volume(s, seed);
    std::vector<std::uint8_t> texels(volume.alpha.size());
    for (std::size_t i = 0; i < texels.size(); ++i) {
        texels[i] = static_cast<std::uint8_t>(std::lround(volume.alpha[i] * 255.0f));
    }
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(spectral_volume_unit));
    glBindTexture(GL_TEXTURE_3D, volume_.id());
    // Repeat on all three axes: [LZ] tiles the volume and loops it.
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_R8, static_cast<GLsizei>(volume.size_xy),
                 static_cast<GLsizei>(volume.size_xy), static_cast<GLsizei>(volume.size_t), 0,
                 GL_RED, GL_UNSIGNED_BYTE, texels.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    built_for_ = s;
    built_seed_ = seed;
}

void SpectralPass::run(const World& world, FrameContext& frame) {
    const SpectralSnow& s = *frame.visuals.spectral;
    if (const Invalid error = validate(s); !error.empty()) {
        if (!invalid_reported_) { // said once, like the renderer's other bad-input notes
            std::fprintf(stderr, "snow: spectral snow not drawn: %s\n", error.text().c_str());
            invalid_reported_ = true;
        }
        return;
    }
    const SimConfig* config = world.try_resource<SimConfig>();
    const std::uint64_t seed = config != nullptr ? config->seed : 0;
    if (!built_for_ || !same_volume(*built_for_, s) || built_seed_ != seed) {
        build(s, seed);
    }
    // The layer takes over from the flakes at the hand-over distance (a start
    // of 0: everywhere), and its nearest band falls like a flake there.
    const float start = far_field_handover(frame.visuals, frame.settings).value_or(0.0f);
    SpectralSnow mapped = s;
    mapped.start_distance = start;
    const float fall = particle_fall_speed(world);
    const SpectralMapping map =
        spectral_mapping(mapped, frame.camera.fov_y_deg, frame.viewport.y, fall);
    double phase = world_seconds(world) / map.loop_seconds; // t mod loop, in double
    phase -= std::floor(phase);
    const float full = std::max(2.0f * start, start + 1.0f); // its fog is taken there

    depth_.capture(frame.viewport);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(spectral_volume_unit));
    glBindTexture(GL_TEXTURE_3D, volume_.id());
    const Program& program =
        frame.programs.get("spectral_snow.vert", "spectral_snow.frag", frame.fog_defines);
    program.use();
    glUniform1f(program.uniform("layer_ndc_depth"), layer_depth(frame, start));
    glUniform1i(program.uniform("spectral_volume"), spectral_volume_unit);
    glUniform1i(program.uniform("scene_depth"), scene_depth_unit);
    glUniform4f(program.uniform("spectral_view"),
                static_cast<float>(map.tiles_around / (2.0 * std::numbers::pi)),
                wind_shear(world, frame.camera, fall), static_cast<float>(phase), s.opacity);
    glUniform2f(program.uniform("spectral_fade"), start, full);
    draw_fullscreen_blended(vao_); // depth test on (GL_LESS): nearer surfaces hide the layer
}

} // namespace snow
