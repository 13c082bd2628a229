/// @file render_error.hpp
/// @brief Errors of the renderer: context creation, GL loading, shaders, files.
#pragma once

#include "ecs/error.hpp"

namespace snow {

/// Thrown when a GL context, the GL loader, a GPU resource or an image file fails.
class RenderError : public Error {
  public:
    using Error::Error;
};

/// Thrown when a shader does not compile or a program does not link; the
/// message names the program and stage and carries the driver's info log.
class ShaderError : public RenderError {
  public:
    using RenderError::RenderError;
};

} // namespace snow
