#include "render/passes/flake_pass.hpp"

#include "render/passes/far_field.hpp"

#include <optional>

namespace snow {

bool FlakePass::wanted(const World& world, const SceneVisuals&) const {
    const FlakePool* pool = world.try_resource<FlakePool>();
    return pool != nullptr && pool->alive > 0;
}

void FlakePass::run(const World& world, FrameContext& frame) {
    const FlakePool& pool = world.resource<FlakePool>();
    const std::size_t floats = static_cast<std::size_t>(pool.capacity()) * 4u;
    if (staging_.size() < floats) {
        staging_.resize(floats);
    }
    FlakeSelection sel;
    sel.view_proj = frame.view_proj;
    sel.eye = frame.camera.position;
    sel.size_scale = frame.settings.flake_scale;
    sel.lod = frame.settings.flake_lod == FlakeLod::always ||
              (frame.settings.flake_lod == FlakeLod::automatic && frame.software_gl);
    sel.lod_distance = frame.settings.lod_distance;
    // With far-field snow the flakes thin out beyond the hand-over as the layer
    // takes their place (far_field.hpp), level of detail or not.
    if (const std::optional<float> handover = far_field_handover(frame.visuals, frame.settings)) {
        sel.lod = true;
        sel.lod_distance = *handover;
    }
    const std::uint32_t count = select_flakes(pool, sel, staging_);
    frame.stats.flakes_alive = pool.alive;
    frame.stats.flakes_drawn = count;
    if (count == 0) {
        return;
    }
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    if (!attributes_set_) {
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
        attributes_set_ = true;
    }
    // The frame's one upload: new storage of exactly the drawn size (orphaning
    // the old, so no stall on a frame still in flight) filled from the staging array.
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(count) * 4 * sizeof(float),
                 staging_.data(), GL_STREAM_DRAW);

    frame.programs.get("flake.vert", "flake.frag", frame.fog_defines).use();
    glEnable(GL_PROGRAM_POINT_SIZE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE); // translucent: test against the scene, do not occlude each other
    glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(count));
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glBindVertexArray(0);
}

} // namespace snow
