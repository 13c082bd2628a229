#include "render/passes/surface_pass.hpp"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace snow {

bool SurfacePass::wanted(const World& world, const SceneVisuals&) const {
    return world.count<SnowSurface>() > 0;
}

void SurfacePass::upload(GpuSurface& gpu, const SnowSurface& s, FrameContext& frame) {
    const std::vector<std::uint32_t>& changed = gpu.tiles.rescan(s);
    if (changed.empty() && !gpu.tiles.grid_changed()) {
        return;
    }
    ++frame.stats.surfaces_uploaded;
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(surface_cells_unit));
    glBindTexture(GL_TEXTURE_2D, gpu.cells.id());
    if (gpu.tiles.grid_changed()) {
        gpu.edge_patches.clear();
        GLint max_size = 0;
        glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
        const bool fits = std::max(s.nx, s.nz) <= static_cast<std::uint32_t>(max_size);
        gpu.drawable = gpu.tiles.tiles_x() > 0 && fits;
        if (!fits && !too_large_reported_) { // said once, like the renderer's other notes
            std::fprintf(stderr,
                         "snow: a %u x %u snow surface exceeds GL_MAX_TEXTURE_SIZE %d; not drawn\n",
                         s.nx, s.nz, max_size);
            too_large_reported_ = true;
        }
        if (!gpu.drawable) { // malformed or too large: draw nothing, retry on change
            return;
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, static_cast<GLsizei>(s.nx),
                     static_cast<GLsizei>(s.nz), 0, GL_RG, GL_FLOAT, nullptr);
    }
    if (!gpu.drawable) {
        return;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    for (const std::uint32_t t : changed) {
        const glm::uvec2 size = tile_texels(s, t, texel_staging_);
        glTexSubImage2D(GL_TEXTURE_2D, 0,
                        static_cast<GLint>((t % gpu.tiles.tiles_x()) * surface_tile_cells),
                        static_cast<GLint>((t / gpu.tiles.tiles_x()) * surface_tile_cells),
                        static_cast<GLsizei>(size.x), static_cast<GLsizei>(size.y), GL_RG, GL_FLOAT,
                        texel_staging_.data());
    }
    frame.stats.surface_tiles_uploaded += static_cast<std::uint32_t>(changed.size());
}

const SurfacePass::Patch& SurfacePass::patch(std::uint32_t level, std::uint32_t skirts) {
    Patch& p = patches_[level][skirts];
    if (p.count == 0) {
        const std::vector<std::uint32_t> idx = patch_indices(level, skirts);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices.id()); // the pass's VAO is bound
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(idx.size() * sizeof(std::uint32_t)), idx.data(),
                     GL_STATIC_DRAW);
        p.count = static_cast<GLsizei>(idx.size());
    }
    return p;
}

const SurfacePass::EdgePatch& SurfacePass::edge_patch(GpuSurface& gpu, const SnowSurface& s,
                                                      const TileDraw& d) {
    const auto tile =
        static_cast<std::uint32_t>(d.first.y) / surface_tile_cells * gpu.tiles.tiles_x() +
        static_cast<std::uint32_t>(d.first.x) / surface_tile_cells;
    EdgePatch& p = gpu.edge_patches[tile];
    const std::uint32_t version = gpu.tiles.version(tile);
    if (!p.built || p.level != d.level || p.skirts != d.skirts || p.version != version) {
        edge_patch_indices(s, d, index_staging_);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, p.indices.id()); // the pass's VAO is bound
        glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                     static_cast<GLsizeiptr>(index_staging_.size() * sizeof(std::uint32_t)),
                     index_staging_.data(), GL_STATIC_DRAW);
        p.count = static_cast<GLsizei>(index_staging_.size());
        p.level = d.level;
        p.skirts = d.skirts;
        p.version = version;
        p.built = true;
    }
    return p;
}

void SurfacePass::draw(GpuSurface& gpu, const SnowSurface& s, FrameContext& frame) {
    TileView view;
    view.view_proj = frame.view_proj;
    view.eye = frame.camera.position;
    view.px_per_metre = static_cast<float>(frame.viewport.y) /
                        (2.0f * std::tan(glm::radians(frame.camera.fov_y_deg) * 0.5f));
    view.spacing_px = frame.settings.surface_spacing_px;
    view.max_samples = frame.settings.surface_samples;
    frame.stats.surface_samples += static_cast<std::uint32_t>(gpu.tiles.select(s, view, draws_));
    if (draws_.empty()) {
        return;
    }
    frame.stats.surface_tiles_drawn += static_cast<std::uint32_t>(draws_.size());
    instance_staging_.clear();
    for (const TileDraw& d : draws_) {
        instance_staging_.push_back(d.first);
    }
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(surface_cells_unit));
    glBindTexture(GL_TEXTURE_2D, gpu.cells.id());
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
    glBufferData(GL_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(instance_staging_.size() * sizeof(glm::ivec2)),
                 instance_staging_.data(), GL_STREAM_DRAW);
    const Program& program = frame.programs.get("surface.vert", "surface.frag", lit_defines(frame));
    program.use();
    glUniform1f(program.uniform("min_depth"), frame.settings.min_snow_depth);
    glUniform1i(program.uniform("surface_cells"), surface_cells_unit);
    glUniform3f(program.uniform("surface_place"), s.x0, s.z0, s.cell);
    // Runs of tiles drawn alike share one instanced draw; a tile with edges
    // has its own index list (its quads over edges left out).
    for (std::size_t first = 0; first < draws_.size();) {
        const TileDraw& d = draws_[first];
        std::size_t end = first + 1;
        while (!d.edges && end < draws_.size() && draws_[end].same_draw(d)) {
            ++end;
        }
        glUniform4i(program.uniform("surface_grid"), static_cast<GLint>(s.nx),
                    static_cast<GLint>(s.nz), 1 << d.level,
                    static_cast<GLint>(patch_side(d.level)));
        GLuint indices = 0;
        GLsizei count = 0;
        if (d.edges) {
            const EdgePatch& p = edge_patch(gpu, s, d);
            indices = p.indices.id();
            count = p.count;
        } else {
            const Patch& p = patch(d.level, d.skirts);
            indices = p.indices.id();
            count = p.count;
        }
        if (count > 0) {
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices);
            glVertexAttribIPointer(0, 2, GL_INT, 0,
                                   reinterpret_cast<const void*>(first * sizeof(glm::ivec2)));
            glDrawElementsInstanced(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr,
                                    static_cast<GLsizei>(end - first));
        }
        first = end;
    }
}

void SurfacePass::run(const World& world, FrameContext& frame) {
    ++frame_;
    glBindVertexArray(vao_.id());
    glBindBuffer(GL_ARRAY_BUFFER, instances_.id());
    glEnableVertexAttribArray(0);
    glVertexAttribDivisor(0, 1);
    // Pull snow toward the eye so a thin layer wins the depth test over the top
    // below it; blend it over that top by its cover.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -1.0f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    world.each<SnowSurface>([&](Entity e, const SnowSurface& surface) {
        GpuSurface& gpu = surfaces_[e.bits];
        gpu.last_frame = frame_;
        upload(gpu, surface, frame);
        if (gpu.drawable) {
            draw(gpu, surface, frame);
        }
    });
    glBindVertexArray(0);
    glDisable(GL_BLEND);
    glDisable(GL_POLYGON_OFFSET_FILL);
    std::erase_if(surfaces_, [&](const auto& entry) { return entry.second.last_frame != frame_; });
}

} // namespace snow
