#include "render/passes/fog_puff_pass.hpp"

#include "render/gl/fullscreen.hpp"
#include <snow/error.hpp>

#include <algorithm>
#include <cstdio>

namespace snow {

namespace {

/// Uploads the first max_drawn_puffs puffs to the program's puff uniforms.
void set_puff_uniforms(const Program& program, std::span<const FogPuff> puffs) {
    const std::size_t count = std::min(puffs.size(), max_drawn_puffs);
    std::vector<float> shape(count * 4), wave(count * 4), density(count);
    for (std::size_t i = 0; i < count; ++i) {
        const FogPuff& p = puffs[i];
        const float s[4] = {p.center.x, p.center.y, p.center.z, p.sigma};
        const float w[4] = {p.frequency.x, p.frequency.y, p.frequency.z, p.phase};
        std::copy(s, s + 4, shape.begin() + static_cast<std::ptrdiff_t>(i * 4));
        std::copy(w, w + 4, wave.begin() + static_cast<std::ptrdiff_t>(i * 4));
        density[i] = p.density;
    }
    const auto n = static_cast<GLsizei>(count);
    glUniform1i(program.uniform("puff_count"), n);
    if (count > 0) {
        glUniform4fv(program.uniform("puff_shape"), n, shape.data());
        glUniform4fv(program.uniform("puff_wave"), n, wave.data());
        glUniform1fv(program.uniform("puff_density"), n, density.data());
    }
}

/// A framebuffer object name, deleted on scope exit.
struct ScopedFramebuffer {
    GLuint id = 0;
    ScopedFramebuffer() { glGenFramebuffers(1, &id); }
    ~ScopedFramebuffer() { glDeleteFramebuffers(1, &id); }
    ScopedFramebuffer(const ScopedFramebuffer&) = delete;
    ScopedFramebuffer& operator=(const ScopedFramebuffer&) = delete;
};

/// Segments per probe draw: one row of a texture no wider than GL 3.3's minimum limit.
constexpr std::size_t probe_batch = 1024;

} // namespace

bool FogPuffPass::wanted(const World& /*world*/, const SceneVisuals& visuals) const {
    return visuals.fog && !visuals.fog->puffs.empty();
}

void FogPuffPass::run(const World& /*world*/, FrameContext& frame) {
    const Fog& fog = *frame.visuals.fog;
    if (fog.puffs.size() > max_drawn_puffs && !cap_reported_) {
        std::fprintf(stderr, "snow: fog has %zu puffs; the first %zu are drawn\n", fog.puffs.size(),
                     max_drawn_puffs);
        cap_reported_ = true;
    }
    depth_.capture(frame.viewport);
    // No fog defines: the puffs' own closed form replaces the global fog code.
    const Program& program = frame.programs.get("sky.vert", "fog_puffs.frag", {});
    program.use();
    glUniform1i(program.uniform("scene_depth"), scene_depth_unit);
    set_puff_uniforms(program, fog.puffs);
    // src alpha = 1 − 0.5^depth: colour = mix(fog colour, colour, 0.5^depth) [PE].
    glDisable(GL_DEPTH_TEST);
    draw_fullscreen_blended(vao_);
    glEnable(GL_DEPTH_TEST);
}

std::vector<float> shader_puff_optical_depths(std::span<const FogPuff> puffs,
                                              std::span<const PuffSegment> segments) {
    std::vector<float> depths(segments.size());
    if (segments.empty()) {
        return depths;
    }
    GLint previous_fbo = 0;
    GLint previous_viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &previous_fbo);
    glGetIntegerv(GL_VIEWPORT, previous_viewport);

    ProgramCache programs;
    const Program& program = programs.get("sky.vert", "fog_puffs.frag", {"PUFF_PROBE"});
    program.use();
    set_puff_uniforms(program, puffs);
    constexpr int segment_unit = scene_depth_unit; // the probe draws no scene
    glUniform1i(program.uniform("probe_segments"), segment_unit);

    GlTexture segment_texture;
    GlTexture target;
    GlVertexArray vao;
    ScopedFramebuffer fbo;
    const auto width = static_cast<GLsizei>(probe_batch);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(segment_unit));
    glBindTexture(GL_TEXTURE_2D, segment_texture.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, 2, 0, GL_RGBA, GL_FLOAT, nullptr);
    glBindTexture(GL_TEXTURE_2D, target.id());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, width, 1, 0, GL_RED, GL_FLOAT, nullptr);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo.id);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target.id(), 0);
    const bool complete = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (complete) {
        glBindTexture(GL_TEXTURE_2D, segment_texture.id());
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glBindVertexArray(vao.id());
        std::vector<float> texels(probe_batch * 8);
        for (std::size_t first = 0; first < segments.size(); first += probe_batch) {
            const std::size_t n = std::min(probe_batch, segments.size() - first);
            for (std::size_t i = 0; i < n; ++i) {
                const PuffSegment& s = segments[first + i];
                const float a[4] = {s.a.x, s.a.y, s.a.z, 1.0f};
                const float b[4] = {s.b.x, s.b.y, s.b.z, 1.0f};
                std::copy(a, a + 4, texels.begin() + static_cast<std::ptrdiff_t>(i * 4));
                std::copy(b, b + 4,
                          texels.begin() + static_cast<std::ptrdiff_t>((probe_batch + i) * 4));
            }
            glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, 2, GL_RGBA, GL_FLOAT, texels.data());
            glViewport(0, 0, static_cast<GLsizei>(n), 1);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glPixelStorei(GL_PACK_ALIGNMENT, 4);
            glReadPixels(0, 0, static_cast<GLsizei>(n), 1, GL_RED, GL_FLOAT, depths.data() + first);
        }
        glBindVertexArray(0);
        glEnable(GL_DEPTH_TEST);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_fbo));
    glViewport(previous_viewport[0], previous_viewport[1], previous_viewport[2],
               previous_viewport[3]);
    if (!complete) {
        throw RenderError("fog puff probe: an R32F colour target is not renderable here");
    }
    return depths;
}

} // namespace snow
