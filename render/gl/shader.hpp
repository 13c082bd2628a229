/// @file shader.hpp
/// @brief GLSL programs: assembly of embedded sources with #define variants,
/// compile and link with errors that carry the driver's info log.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

/// A linked GL program (needs a current context to create, use and destroy).
class Program {
  public:
    /// Compiles and links complete GLSL sources; throws ShaderError naming
    /// `name` and the failing stage, with the info log.
    Program(std::string_view name, const std::string& vertex_source,
            const std::string& fragment_source);
    ~Program();
    Program(Program&& other) noexcept;
    Program& operator=(Program&&) = delete;
    Program(const Program&) = delete;
    Program& operator=(const Program&) = delete;

    void use() const;
    [[nodiscard]] std::uint32_t id() const { return id_; }
    /// Location of a uniform, −1 if the program has none of that name.
    [[nodiscard]] int uniform(const char* uniform_name) const;

  private:
    std::uint32_t id_ = 0;
};

/// Full source of a stage: "#version 330 core", one #define per entry of
/// `defines`, common.glsl, then the embedded file `stage_file`.
[[nodiscard]] std::string assemble_shader(std::string_view stage_file,
                                          const std::vector<std::string>& defines);

/// Programs built from embedded shaders, one per (stages, defines) variant,
/// compiled on first use. The uniform block "Frame" is bound to binding 0 and
/// samplers to their fixed units (see texture_unit).
class ProgramCache {
  public:
    /// The program for this variant; compiles it on first request.
    [[nodiscard]] Program& get(std::string_view vertex_file, std::string_view fragment_file,
                               const std::vector<std::string>& defines);
    /// Keys of every variant compiled so far, e.g. "mesh.vert+mesh.frag[FOG_LAYERED]".
    [[nodiscard]] std::vector<std::string> variants() const;

  private:
    std::map<std::string, Program, std::less<>> programs_;
};

/// Fixed texture units shared by all programs.
namespace texture_unit {
inline constexpr int occlusion = 0; ///< sampler2D occlusion_map: sky top_y [SKY]
inline constexpr int fog_table = 1; ///< sampler1D fog_table: layered fog E(y) [PE]
/// sampler2DShadow sun_shadow_map: the sun's cascades side by side [CSM]; 2–4
/// are the effect passes' and the snow surfaces' own.
inline constexpr int sun_shadow = 5;
/// sampler2D base_color_texture: a scene mesh's glTF base colour texture.
inline constexpr int base_color = 6;
} // namespace texture_unit

/// Binding point of the "Frame" uniform block.
inline constexpr std::uint32_t frame_block_binding = 0;

} // namespace snow
