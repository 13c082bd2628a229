/// @file render_error.hpp
/// @brief ShaderError, the RenderError (<snow/error.hpp>) of a shader that
/// does not compile or a program that does not link.
#pragma once

#include <snow/error.hpp>

namespace snow {

/// Thrown when a shader does not compile or a program does not link; the
/// message names the program and stage and carries the driver's info log.
class ShaderError : public RenderError {
  public:
    using RenderError::RenderError;
};

} // namespace snow
