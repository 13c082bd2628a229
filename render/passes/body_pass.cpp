// bodies: each Body at this tick's pose. Closed shapes, drawn with back faces
// culled, so an eye inside one (the walk camera in its own capsule) sees out.
#include "render/passes/body_pass.hpp"

#include "systems/bodies/body.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

namespace snow {

namespace {

struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
    float side; ///< +1 upper hemisphere, -1 lower, 0 a cube (body.vert)
};

constexpr glm::vec3 coat_color{0.42f, 0.12f, 0.1f};
constexpr glm::vec3 solid_color{0.5f, 0.48f, 0.45f};

void upload(const std::vector<Vertex>& vertices, const std::vector<std::uint32_t>& indices,
            GlVertexArray& vao, GlBuffer& vbo, GlBuffer& ibo) {
    glBindVertexArray(vao.id());
    glBindBuffer(GL_ARRAY_BUFFER, vbo.id());
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
                 vertices.data(), GL_STATIC_DRAW);
    constexpr GLsizei stride = sizeof(Vertex);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(offsetof(Vertex, side)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo.id());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER,
                 static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
                 GL_STATIC_DRAW);
    glBindVertexArray(0);
}

/// Rings from the south pole to the north pole, the equator twice (once per
/// hemisphere), so a capsule's core is the band between the two equators.
/// Triangles wind counter-clockwise seen from outside.
void round_mesh(std::vector<Vertex>& v, std::vector<std::uint32_t>& idx) {
    constexpr std::uint32_t rings_per_half = 8, slices = 24;
    constexpr float half_pi = 0.5f * std::numbers::pi_v<float>;
    for (std::uint32_t r = 0; r < 2 * (rings_per_half + 1); ++r) {
        const bool upper = r > rings_per_half;
        const std::uint32_t k = upper ? r - rings_per_half - 1 : rings_per_half - r;
        const float phi = (upper ? 1.0f : -1.0f) * half_pi * static_cast<float>(k) /
                          static_cast<float>(rings_per_half);
        for (std::uint32_t s = 0; s < slices; ++s) {
            const float theta = 2.0f * std::numbers::pi_v<float> * static_cast<float>(s) / slices;
            const glm::vec3 p{std::cos(phi) * std::cos(theta), std::sin(phi),
                              std::cos(phi) * std::sin(theta)};
            v.push_back({p, p, upper ? 1.0f : -1.0f});
        }
    }
    for (std::uint32_t r = 0; r + 1 < 2 * (rings_per_half + 1); ++r) {
        for (std::uint32_t s = 0; s < slices; ++s) {
            const std::uint32_t a = r * slices + s, b = (r + 1) * slices + s;
            const std::uint32_t a1 = r * slices + (s + 1) % slices;
            const std::uint32_t b1 = (r + 1) * slices + (s + 1) % slices;
            idx.insert(idx.end(), {a, b, a1, a1, b, b1});
        }
    }
}

/// Six faces with flat normals; (u, v, normal) right-handed, so each face
/// winds counter-clockwise seen from outside.
void cube_mesh(std::vector<Vertex>& v, std::vector<std::uint32_t>& idx) {
    const glm::vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    const std::array<std::array<glm::vec3, 2>, 6> faces{
        {{y, z}, {z, y}, {z, x}, {x, z}, {x, y}, {y, x}}};
    for (const auto& [u, w] : faces) {
        const glm::vec3 n = glm::cross(u, w);
        const auto first = static_cast<std::uint32_t>(v.size());
        for (const glm::vec3& corner : {n - u - w, n + u - w, n + u + w, n - u + w}) {
            v.push_back({corner, n, 0.0f});
        }
        idx.insert(idx.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
    }
}

} // namespace

BodyPass::BodyPass() {
    std::vector<Vertex> v;
    std::vector<std::uint32_t> idx;
    round_mesh(v, idx);
    upload(v, idx, round_.vao, round_.vertices, round_.indices);
    round_.index_count = static_cast<GLsizei>(idx.size());
    v.clear();
    idx.clear();
    cube_mesh(v, idx);
    upload(v, idx, cube_.vao, cube_.vertices, cube_.indices);
    cube_.index_count = static_cast<GLsizei>(idx.size());
}

bool BodyPass::wanted(const World& world, const SceneVisuals&) const {
    return world.count<Body>() > 0;
}

void BodyPass::run(const World& world, FrameContext& frame) {
    std::vector<std::string> defines = lit_defines(frame);
    if (frame.occlusion) {
        defines.emplace_back("OCCLUSION"); // snow on the parts the sky map shows open
    }
    const Program& program = frame.depth_only
                                 ? frame.programs.get("body.vert", "depth.frag", {})
                                 : frame.programs.get("body.vert", "body.frag", defines);
    program.use();
    const int center = program.uniform("center"), scale = program.uniform("scale");
    const int half_height = program.uniform("half_height"), albedo = program.uniform("albedo");
    glUniform1f(program.uniform("snow_amount"), std::clamp(frame.settings.body_snow, 0.0f, 1.0f));
    glEnable(GL_CULL_FACE);
    world.each<Body>([&](Entity, const Body& b) {
        const bool box = b.shape == BodyShape::box;
        const glm::vec3 s = box ? b.half_extents : glm::vec3(b.radius);
        const glm::vec3 c = b.snowball                      ? frame.settings.snow_color
                            : b.shape == BodyShape::capsule ? coat_color
                                                            : solid_color;
        glUniform3f(center, b.position.x, b.position.y, b.position.z);
        glUniform3f(scale, s.x, s.y, s.z);
        glUniform1f(half_height, b.shape == BodyShape::capsule ? b.half_height : 0.0f);
        glUniform3f(albedo, c.r, c.g, c.b);
        const Shape& shape = box ? cube_ : round_;
        glBindVertexArray(shape.vao.id());
        glDrawElements(GL_TRIANGLES, shape.index_count, GL_UNSIGNED_INT, nullptr);
    });
    glDisable(GL_CULL_FACE);
    glBindVertexArray(0);
}

} // namespace snow
