#include "render/passes/mesh_pass.hpp"

#include <glm/geometric.hpp>

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
    std::vector<glm::vec3> interleaved(mesh.positions.size() * 2);
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        interleaved[2 * i] = mesh.positions[i];
        interleaved[2 * i + 1] = has_normals ? mesh.normals[i] : normals[i];
    }
    glBindVertexArray(gpu.vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertices.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(interleaved.size() * sizeof(glm::vec3)),
                 interleaved.data(), GL_STATIC_DRAW);
    constexpr GLsizei stride = 2 * sizeof(glm::vec3);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(sizeof(glm::vec3)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indices.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
    gpu.index_count = static_cast<GLsizei>(indices.size());
    gpu.drawable = true;
}

void MeshPass::run(const World&, FrameContext& frame) {
    ++frame_;
    std::vector<std::string> defines = lit_defines(frame);
    if (frame.occlusion) {
        defines.emplace_back("OCCLUSION");
    }
    const Program& program = frame.depth_only
                                 ? frame.programs.get("mesh.vert", "depth.frag", {})
                                 : frame.programs.get("mesh.vert", "mesh.frag", defines);
    program.use();
    const int albedo = program.uniform("albedo");
    for (std::size_t m = 0; m < frame.visuals.meshes.size(); ++m) {
        const MeshRenderable& mesh = frame.visuals.meshes[m];
        GpuMesh& gpu = meshes_[m];
        if (gpu.source != mesh.positions.data() || gpu.vertex_count != mesh.positions.size() ||
            gpu.source_index_count != mesh.indices.size()) {
            gpu.source = mesh.positions.data();
            gpu.vertex_count = mesh.positions.size();
            gpu.source_index_count = mesh.indices.size();
            upload(mesh, gpu);
            ++frame.stats.meshes_uploaded;
        }
        gpu.last_frame = frame_;
        if (!gpu.drawable || gpu.index_count == 0) {
            continue;
        }
        glUniform3f(albedo, mesh.color.r, mesh.color.g, mesh.color.b);
        glBindVertexArray(gpu.vao.id());
        glDrawElements(GL_TRIANGLES, gpu.index_count, GL_UNSIGNED_INT, nullptr);
    }
    glBindVertexArray(0);
    std::erase_if(meshes_, [&](const auto& entry) { return entry.second.last_frame != frame_; });
}

} // namespace snow
