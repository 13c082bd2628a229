/// @file make_context.hpp
/// @brief The factory over the GL context backends (OSMesa or EGL headless,
/// GLFW window): picks the one a ContextRequest asks for, falling back to
/// headless. The only unit that knows every backend.
#pragma once

#include "render/context/context_request.hpp"
#include "render/context/gl_context.hpp"

#include <memory>
#include <string>

namespace snow {

/// Creates a context (already current, GL loaded). With `automatic`, a window
/// that cannot be made falls back to headless; the reason goes to stderr and to
/// `fallback_reason` (left empty when no fallback happened).
[[nodiscard]] std::unique_ptr<GlContext> make_context(const ContextRequest& request,
                                                      std::string* fallback_reason = nullptr);

} // namespace snow
