/// @file gl_objects.hpp
/// @brief Move-only owners of GL names (buffers, vertex arrays, textures,
/// framebuffers).
/// Internal to snow_render: includes the glad loader header.
#pragma once

#include <glad/gl.h>

#include <utility>

namespace snow {

/// Owns one GL name; `Gen`/`Del` are the glGen*/glDelete* pair.
template <void (*Gen)(GLsizei, GLuint*), void (*Del)(GLsizei, const GLuint*)>
class GlName {
  public:
    GlName() { Gen(1, &id_); }
    ~GlName() {
        if (id_ != 0) {
            Del(1, &id_);
        }
    }
    GlName(GlName&& other) noexcept : id_(std::exchange(other.id_, 0)) {}
    GlName& operator=(GlName&& other) noexcept {
        std::swap(id_, other.id_);
        return *this;
    }
    GlName(const GlName&) = delete;
    GlName& operator=(const GlName&) = delete;
    [[nodiscard]] GLuint id() const { return id_; }

  private:
    GLuint id_ = 0;
};

// glad exposes GL functions as pointer variables, so wrap them in functions.
namespace gl_detail {
inline void gen_buffers(GLsizei n, GLuint* ids) {
    glGenBuffers(n, ids);
}
inline void delete_buffers(GLsizei n, const GLuint* ids) {
    glDeleteBuffers(n, ids);
}
inline void gen_vertex_arrays(GLsizei n, GLuint* ids) {
    glGenVertexArrays(n, ids);
}
inline void delete_vertex_arrays(GLsizei n, const GLuint* ids) {
    glDeleteVertexArrays(n, ids);
}
inline void gen_textures(GLsizei n, GLuint* ids) {
    glGenTextures(n, ids);
}
inline void delete_textures(GLsizei n, const GLuint* ids) {
    glDeleteTextures(n, ids);
}
inline void gen_framebuffers(GLsizei n, GLuint* ids) {
    glGenFramebuffers(n, ids);
}
inline void delete_framebuffers(GLsizei n, const GLuint* ids) {
    glDeleteFramebuffers(n, ids);
}
} // namespace gl_detail

using GlBuffer = GlName<gl_detail::gen_buffers, gl_detail::delete_buffers>;
using GlVertexArray = GlName<gl_detail::gen_vertex_arrays, gl_detail::delete_vertex_arrays>;
using GlTexture = GlName<gl_detail::gen_textures, gl_detail::delete_textures>;
using GlFramebuffer = GlName<gl_detail::gen_framebuffers, gl_detail::delete_framebuffers>;

} // namespace snow
