/// @file shader_sources.hpp
/// @brief GLSL files of assets/shaders, embedded into the library at build time
/// (render/gl/embed_shaders.cmake), so an installed library needs no asset path.
#pragma once

#include <string_view>

namespace snow {

/// Text of the embedded shader file `name` (e.g. "flake.vert"); throws RenderError if absent.
[[nodiscard]] std::string_view shader_source(std::string_view name);

} // namespace snow
