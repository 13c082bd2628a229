#include "render/surface_pass.hpp"

namespace snow {

bool SurfacePass::wanted(const World& world, const SceneVisuals&) const {
    return world.count<SnowSurface>() > 0;
}

void SurfacePass::run(const World& world, FrameContext& frame) {
    ++frame_;
    const Program& program = frame.programs.get("surface.vert", "surface.frag", frame.fog_defines);
    program.use();
    glUniform1f(program.uniform("min_depth"), frame.settings.min_snow_depth);
    // Pull snow toward the eye so a thin layer wins the depth test over the top below it.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -1.0f);
    world.each<SnowSurface>([&](Entity e, const SnowSurface& surface) {
        GpuSurface& gpu = surfaces_[e.bits];
        gpu.last_frame = frame_;
        const std::uint64_t fingerprint = surface_fingerprint(surface);
        if (!gpu.uploaded || fingerprint != gpu.fingerprint) {
            const bool new_grid = !gpu.uploaded || gpu.nx != surface.nx || gpu.nz != surface.nz;
            build_surface_mesh(surface, vertex_staging_, new_grid ? &index_staging_ : nullptr);
            gpu.fingerprint = fingerprint;
            gpu.uploaded = true;
            ++frame.stats.surfaces_uploaded;
            if (vertex_staging_.empty()) { // malformed grid: draw nothing, rebuild on change
                gpu.index_count = 0;
                gpu.nx = gpu.nz = 0;
                return;
            }
            glBindVertexArray(gpu.vao.id());
            glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
            glBufferData(GL_ARRAY_BUFFER,
                         static_cast<GLsizeiptr>(vertex_staging_.size() * sizeof(float)),
                         vertex_staging_.data(), GL_DYNAMIC_DRAW);
            if (new_grid) {
                constexpr GLsizei stride = surface_vertex_floats * sizeof(float);
                glEnableVertexAttribArray(0);
                glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
                glEnableVertexAttribArray(1);
                glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                                      reinterpret_cast<const void*>(3 * sizeof(float)));
                glEnableVertexAttribArray(2);
                glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                                      reinterpret_cast<const void*>(6 * sizeof(float)));
                glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
                glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                             static_cast<GLsizeiptr>(index_staging_.size() * sizeof(std::uint32_t)),
                             index_staging_.data(), GL_STATIC_DRAW);
                gpu.index_count = static_cast<GLsizei>(index_staging_.size());
                gpu.nx = surface.nx;
                gpu.nz = surface.nz;
            }
        }
        if (gpu.index_count > 0) {
            glBindVertexArray(gpu.vao.id());
            glDrawElements(GL_TRIANGLES, gpu.index_count, GL_UNSIGNED_INT, nullptr);
        }
    });
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    std::erase_if(surfaces_, [&](const auto& entry) { return entry.second.last_frame != frame_; });
}

} // namespace snow
