#include "render/context/egl_context.hpp"

#include <snow/error.hpp>

#include <glad/gl.h>

#define EGL_NO_X11
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <string>

namespace snow {

namespace {

std::string egl_error(const char* step) {
    char code[16];
    std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
    return std::string("egl: ") + step + " failed (EGL error " + code + ")";
}

} // namespace

EglContext::EglContext(int width, int height) : width_(width), height_(height) {
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
        throw RenderError("egl: framebuffer size " + std::to_string(width) + "x" +
                          std::to_string(height) + " is out of range (1..16384)");
    }
    EGLDisplay display =
        eglGetPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display == EGL_NO_DISPLAY) {
        throw RenderError(egl_error("eglGetPlatformDisplay(surfaceless)"));
    }
    EGLint major = 0, minor = 0;
    if (eglInitialize(display, &major, &minor) != EGL_TRUE) {
        throw RenderError(egl_error("eglInitialize"));
    }
    display_ = display;
    if (eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
        throw RenderError(egl_error("eglBindAPI(OpenGL)"));
    }
    // The default EGL_SURFACE_TYPE asks for window configs, which surfaceless lacks.
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                     EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (eglChooseConfig(display, config_attribs, &config, 1, &configs) != EGL_TRUE ||
        configs == 0) {
        throw RenderError(egl_error("eglChooseConfig(pbuffer, OpenGL)"));
    }
    const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      3,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
    context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
    if (context_ == EGL_NO_CONTEXT) {
        context_ = nullptr;
        throw RenderError(egl_error("eglCreateContext(GL 3.3 core)"));
    }
    try {
        make_current();
    } catch (...) {
        release();
        throw;
    }
    // No window surface: draw into a framebuffer object of the requested size.
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &color_);
    glGenRenderbuffers(1, &depth_);
    glBindRenderbuffer(GL_RENDERBUFFER, color_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glBindRenderbuffer(GL_RENDERBUFFER, depth_);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth_);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        release();
        throw RenderError("egl: the offscreen framebuffer is incomplete");
    }
}

EglContext::~EglContext() {
    release();
}

void EglContext::release() {
    // The EGL display stays initialised: it is shared by every context of the process.
    if (context_ != nullptr) {
        try {
            make_current(); // GL entry points of this context for the deletes
            glDeleteFramebuffers(1, &fbo_);
            glDeleteRenderbuffers(1, &color_);
            glDeleteRenderbuffers(1, &depth_);
        } catch (const RenderError&) {
            // Not current any more: the objects go with the context below.
        }
        eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(display_, context_);
        context_ = nullptr;
    }
}

GlProc EglContext::proc_address(const char* name) const {
    return eglGetProcAddress(name);
}

void EglContext::bind() {
    if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE) {
        throw RenderError(egl_error("eglMakeCurrent(surfaceless)"));
    }
}

} // namespace snow
