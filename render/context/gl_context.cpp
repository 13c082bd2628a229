#include <snow/render.hpp>

#include <snow/error.hpp>

#include <glad/gl.h>

#include <string>

namespace snow {

namespace {

// glad keeps one process-wide table of entry points; entry points from one
// backend (OSMesa) are not valid for another (GLX), so the table is reloaded
// whenever a different context becomes current.
std::uint64_t next_serial = 1;
std::uint64_t loaded_serial = 0;

GLADapiproc load_entry_point(void* context, const char* name) {
    return static_cast<const GlContext*>(context)->proc_address(name);
}

} // namespace

GlContext::GlContext() : serial_(next_serial++) {}

void GlContext::make_current() {
    bind();
    if (loaded_serial == serial_) {
        return;
    }
    const int version = gladLoadGLUserPtr(load_entry_point, this);
    if (version == 0) {
        loaded_serial = 0;
        throw RenderError(std::string(name()) + ": loading GL entry points failed");
    }
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
        loaded_serial = 0;
        throw RenderError(std::string(name()) + ": GL 3.3 core is required, got " +
                          std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                          std::to_string(GLAD_VERSION_MINOR(version)));
    }
    loaded_serial = serial_;
}

} // namespace snow
