#include "render/context/osmesa_context.hpp"

#include <snow/error.hpp>

#include <GL/osmesa.h>

#include <string>

namespace snow {

OsMesaContext::OsMesaContext(int width, int height) : width_(width), height_(height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
        throw RenderError("osmesa: framebuffer size " + std::to_string(width) + "x" +
                          std::to_string(height) + " is out of range (1..16384)");
    }
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (context_ == nullptr) {
        throw RenderError("osmesa: OSMesaCreateContextAttribs failed (no GL 3.3 core profile)");
    }
    buffer_.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4u);
    try {
        make_current();
    } catch (...) {
        OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
        throw;
    }
}

OsMesaContext::~OsMesaContext() {
    OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

GlProc OsMesaContext::proc_address(const char* name) const {
    return OSMesaGetProcAddress(name);
}

void OsMesaContext::bind() {
    if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                           width_, height_)) {
        throw RenderError("osmesa: OSMesaMakeCurrent failed");
    }
}

} // namespace snow
