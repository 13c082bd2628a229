#include "render/gl/shader.hpp"

#include "render/gl/shader_error.hpp"
#include "render/gl/shader_sources.hpp"

#include <glad/gl.h>

namespace snow {

namespace {

std::string info_log(GLuint object, bool is_program) {
    GLint length = 0;
    if (is_program) {
        glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
    } else {
        glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
    }
    std::string log(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
    if (is_program) {
        glGetProgramInfoLog(object, length, nullptr, log.data());
    } else {
        glGetShaderInfoLog(object, length, nullptr, log.data());
    }
    log.resize(log.find('\0') == std::string::npos ? log.size() : log.find('\0'));
    return log.empty() ? std::string("(empty info log)") : log;
}

GLuint compile(std::string_view program_name, GLenum stage, const std::string& source) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = info_log(shader, false);
        glDeleteShader(shader);
        throw ShaderError("shader program '" + std::string(program_name) +
                          "': " + (stage == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                          " stage failed to compile:\n" + log);
    }
    return shader;
}

std::string variant_key(std::string_view vertex_file, std::string_view fragment_file,
                        const std::vector<std::string>& defines) {
    std::string key = std::string(vertex_file) + "+" + std::string(fragment_file) + "[";
    for (std::size_t i = 0; i < defines.size(); ++i) {
        key += (i == 0 ? "" : ",") + defines[i];
    }
    return key + "]";
}

} // namespace

Program::Program(std::string_view name, const std::string& vertex_source,
                 const std::string& fragment_source) {
    const GLuint vs = compile(name, GL_VERTEX_SHADER, vertex_source);
    GLuint fs = 0;
    try {
        fs = compile(name, GL_FRAGMENT_SHADER, fragment_source);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    id_ = glCreateProgram();
    glAttachShader(id_, vs);
    glAttachShader(id_, fs);
    glLinkProgram(id_);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(id_, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) {
        const std::string log = info_log(id_, true);
        glDeleteProgram(id_);
        throw ShaderError("shader program '" + std::string(name) + "' failed to link:\n" + log);
    }
}

Program::~Program() {
    if (id_ != 0) {
        glDeleteProgram(id_);
    }
}

Program::Program(Program&& other) noexcept : id_(other.id_) {
    other.id_ = 0;
}

void Program::use() const {
    glUseProgram(id_);
}

int Program::uniform(const char* uniform_name) const {
    return glGetUniformLocation(id_, uniform_name);
}

std::string assemble_shader(std::string_view stage_file, const std::vector<std::string>& defines) {
    std::string source = "#version 330 core\n";
    for (const std::string& d : defines) {
        source += "#define " + d + " 1\n";
    }
    // #line keeps driver error line numbers relative to each embedded file.
    source += "#line 1 1\n";
    source += shader_source("common.glsl");
    source += "\n#line 1 2\n";
    source += shader_source(stage_file);
    return source;
}

Program& ProgramCache::get(std::string_view vertex_file, std::string_view fragment_file,
                           const std::vector<std::string>& defines) {
    std::string key = variant_key(vertex_file, fragment_file, defines);
    if (auto it = programs_.find(key); it != programs_.end()) {
        return it->second;
    }
    Program program(key, assemble_shader(vertex_file, defines),
                    assemble_shader(fragment_file, defines));
    const GLuint block = glGetUniformBlockIndex(program.id(), "Frame");
    if (block != GL_INVALID_INDEX) {
        glUniformBlockBinding(program.id(), block, frame_block_binding);
    }
    program.use();
    if (const int loc = program.uniform("occlusion_map"); loc >= 0) {
        glUniform1i(loc, texture_unit::occlusion);
    }
    if (const int loc = program.uniform("fog_table"); loc >= 0) {
        glUniform1i(loc, texture_unit::fog_table);
    }
    if (const int loc = program.uniform("sun_shadow_map"); loc >= 0) {
        glUniform1i(loc, texture_unit::sun_shadow);
    }
    if (const int loc = program.uniform("base_color_texture"); loc >= 0) {
        glUniform1i(loc, texture_unit::base_color);
    }
    return programs_.emplace(std::move(key), std::move(program)).first->second;
}

std::vector<std::string> ProgramCache::variants() const {
    std::vector<std::string> keys;
    keys.reserve(programs_.size());
    for (const auto& [key, program] : programs_) {
        keys.push_back(key);
    }
    return keys;
}

} // namespace snow
