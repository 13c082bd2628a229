#include <snow/render.hpp>

#ifdef SNOW_RENDER_EGL
#include "render/context/egl_context.hpp"
#endif
#include "render/context/glfw_context.hpp"
#include "render/context/osmesa_context.hpp"
#include <snow/error.hpp>

#include <iostream>

namespace snow {

std::unique_ptr<GlContext> make_context(const ContextRequest& request,
                                        std::string* fallback_reason) {
    if (fallback_reason != nullptr) {
        fallback_reason->clear();
    }
    switch (request.backend) {
    case ContextBackend::headless:
        return std::make_unique<OsMesaContext>(request.width, request.height);
    case ContextBackend::window:
        return std::make_unique<GlfwContext>(request);
    case ContextBackend::egl:
#ifdef SNOW_RENDER_EGL
        return std::make_unique<EglContext>(request.width, request.height);
#else
        throw RenderError("egl: snow_render was built without EGL (install libegl-dev)");
#endif
    case ContextBackend::automatic:
        break;
    }
    try {
        return std::make_unique<GlfwContext>(request);
    } catch (const RenderError& e) {
        if (fallback_reason != nullptr) {
            *fallback_reason = e.what();
        }
        if (!request.quiet) {
            std::cerr << "snow: no window (" << e.what() << "); rendering headless with OSMesa\n";
        }
    }
    return std::make_unique<OsMesaContext>(request.width, request.height);
}

} // namespace snow
