#include "render/passes/wind_field_pass.hpp"

namespace snow {

bool WindFieldPass::wanted(const World& world, const SceneVisuals&) const {
    return settings_.show_wind_field && world.has_resource<WindField>();
}

void WindFieldPass::run(const World& world, FrameContext& frame) {
    wind_arrows(world.resource<WindField>(), arrows_);
    if (arrows_.vertices.empty()) {
        return;
    }
    constexpr GLsizei stride = 6 * sizeof(float);
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, buffer_.id());
    if (!attributes_set_) {
        glEnableVertexAttribArray(0);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(3 * sizeof(float)));
        attributes_set_ = true;
    }
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(arrows_.vertices.size() * sizeof(float)),
                 arrows_.vertices.data(), GL_STREAM_DRAW);
    frame.programs.get("wind_field.vert", "wind_field.frag", {}).use();
    // Hidden behind what is solid, drawn over the (depth-less) flakes and fog.
    glDepthMask(GL_FALSE);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(arrows_.vertices.size() / 6));
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
}

} // namespace snow
