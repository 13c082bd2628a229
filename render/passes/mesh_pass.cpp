#include "render/passes/mesh_pass.hpp"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iostream>
#include <string>
#include <vector>

namespace snow {

namespace {

/// Area-weighted vertex normals, for meshes that come without usable normals.
std::vector<glm::vec3> computed_normals(const MeshRenderable& mesh,
                                        const std::vector<std::uint32_t>& indices) {
    std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::vec3& a = mesh.positions[indices[t]];
        const glm::vec3 n =
            glm::cross(mesh.positions[indices[t + 1]] - a, mesh.positions[indices[t + 2]] - a);
        for (std::size_t k = 0; k < 3; ++k) {
            normals[indices[t + k]] += n;
        }
    }
    for (glm::vec3& n : normals) {
        const float len = glm::length(n);
        n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    }
    return normals;
}

/// Why a mesh cannot be drawn, or an empty string.
std::string mesh_problem(const MeshRenderable& mesh, const std::vector<std::uint32_t>& indices) {
    if (indices.size() % 3 != 0) {
        return "index count " + std::to_string(indices.size()) + " is not a multiple of 3";
    }
    for (const std::uint32_t i : indices) {
        if (i >= mesh.positions.size()) {
            return "index " + std::to_string(i) + " is past the " +
                   std::to_string(mesh.positions.size()) + " positions";
        }
    }
    if (mesh.texture && mesh.texcoords.size() != mesh.positions.size()) {
        return "it has a texture but " + std::to_string(mesh.texcoords.size()) + " texcoords for " +
               std::to_string(mesh.positions.size()) + " positions";
    }
    if (mesh.texture &&
        (mesh.texture->width <= 0 || mesh.texture->height <= 0 ||
         mesh.texture->rgba.size() != static_cast<std::size_t>(mesh.texture->width) *
                                          static_cast<std::size_t>(mesh.texture->height) * 4u)) {
        return "its texture's size does not match its data";
    }
    return {};
}

} // namespace

bool MeshPass::wanted(const World&, const SceneVisuals& visuals) const {
    return !visuals.meshes.empty();
}

void MeshPass::upload(const MeshRenderable& mesh, GpuMesh& gpu) {
    std::vector<std::uint32_t> sequential;
    if (mesh.indices.empty()) {
        sequential.resize(mesh.positions.size());
        for (std::size_t i = 0; i < sequential.size(); ++i) {
            sequential[i] = static_cast<std::uint32_t>(i);
        }
    }
    const std::vector<std::uint32_t>& indices = mesh.indices.empty() ? sequential : mesh.indices;
    if (const std::string problem = mesh_problem(mesh, indices); !problem.empty()) {
        std::cerr << "snow: mesh '" << mesh.name << "' is not drawn: " << problem << "\n";
        gpu.drawable = false;
        return;
    }
    const bool has_normals = mesh.normals.size() == mesh.positions.size();
    const std::vector<glm::vec3> normals =
        has_normals ? std::vector<glm::vec3>{} : computed_normals(mesh, indices);
    const bool textured = mesh.texture != nullptr;
    const std::size_t floats = textured ? 8 : 6; // position, normal[, texcoord]
    std::vector<float> interleaved(mesh.positions.size() * floats);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const glm::vec3& p = mesh.positions[i];
        const glm::vec3& n = has_normals ? mesh.normals[i] : normals[i];
        const glm::vec2 uv = textured ? mesh.texcoords[i] : glm::vec2(0.0f);
        const std::array<float, 8> vertex{p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y};
        std::copy_n(vertex.begin(), floats,
                    interleaved.begin() + static_cast<std::ptrdiff_t>(i * floats));
    }
    glBindVertexArray(gpu.vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)),
                 interleaved.data(), GL_STATIC_DRAW);
    const auto stride = static_cast<GLsizei>(floats * sizeof(float));
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(3 * sizeof(float)));
    if (textured) {
        glEnableVertexAttribArray(2);
        glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(6 * sizeof(float)));
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    gpu.index_count = static_cast<GLsizei>(indices.size());
    gpu.drawable = true;
}

GLuint MeshPass::texture_of(const std::shared_ptr<const Image>& image) {
    GpuTexture& t = textures_[image.get()];
    t.last_frame = frame_;
    if (!t.image) {
        t.image = image;
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(texture_unit::base_color));
        glBindTexture(GL_TEXTURE_2D, t.texture.id());
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        // Rows top first, so texcoord v = 0 is the image's top, as glTF has it.
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image->width, image->height, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, image->rgba.data());
        glGenerateMipmap(GL_TEXTURE_2D); // a far textured roof must not shimmer
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT); // glTF's default sampler
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    }
    return t.texture.id();
}

void MeshPass::run(const World&, FrameContext& frame) {
    ++frame_;
    std::vector<std::string> defines = lit_defines(frame);
    if (frame.occlusion) {
        defines.emplace_back("OCCLUSION");
    }
    // The TEXTURE variant only for textured meshes: an untextured scene
    // compiles and draws exactly what it did before textures.
    const auto program_for = [&](bool textured) -> const Program& {
        if (frame.depth_only) {
            return frame.programs.get("mesh.vert", "depth.frag", {});
        }
        std::vector<std::string> d = defines;
        if (textured) {
            d.emplace_back("TEXTURE");
        }
        return frame.programs.get("mesh.vert", "mesh.frag", d);
    };
    const Program* in_use = nullptr;
    int albedo = -1;
    for (std::size_t m = 0; m < frame.visuals.meshes.size(); ++m) {
        const MeshRenderable& mesh = frame.visuals.meshes[m];
        GpuMesh& gpu = meshes_[m];
        if (gpu.source != mesh.positions.data() || gpu.vertex_count != mesh.positions.size() ||
            gpu.source_index_count != mesh.indices.size() || gpu.texture != mesh.texture.get()) {
            gpu.source = mesh.positions.data();
            gpu.texture = mesh.texture.get();
            gpu.vertex_count = mesh.positions.size();
            gpu.source_index_count = mesh.indices.size();
            upload(mesh, gpu);
            ++frame.stats.meshes_uploaded;
        }
        gpu.last_frame = frame_;
        if (!gpu.drawable || gpu.index_count == 0) {
            continue;
        }
        const Program& program = program_for(mesh.texture != nullptr);
        if (&program != in_use) {
            in_use = &program;
            program.use();
            albedo = program.uniform("albedo");
        }
        if (mesh.texture && !frame.depth_only) {
            const GLuint texture = texture_of(mesh.texture);
            glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(texture_unit::base_color));
            glBindTexture(GL_TEXTURE_2D, texture);
        }
        glUniform3f(albedo, mesh.color.r, mesh.color.g, mesh.color.b);
        glBindVertexArray(gpu.vao.id());
        glDrawElements(GL_TRIANGLES, gpu.index_count, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    std::erase_if(meshes_, [&](const auto& entry) { return entry.second.last_frame != frame_; });
    if (!frame.depth_only) { // the shadow pass draws no textures
        std::erase_if(textures_,
                      [&](const auto& entry) { return entry.second.last_frame != frame_; });
    }
}

} // namespace snow
