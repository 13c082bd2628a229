#include <snow/render.hpp>

#include <snow/error.hpp>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <cstring>

namespace snow {

void write_png(const std::filesystem::path& path, const Image& image) {
    const std::size_t expected =
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4u;
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != expected) {
        throw RenderError("write_png " + path.string() + ": image size does not match its data");
    }
    if (stbi_write_png(path.c_str(), image.width, image.height, 4, image.rgba.data(),
                       image.width * 4) == 0) {
        throw RenderError("write_png " + path.string() + ": cannot write the file");
    }
}

Image read_png(const std::filesystem::path& path) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
    if (data == nullptr) {
        throw RenderError("read_png " + path.string() + ": " + stbi_failure_reason());
    }
    Image image;
    image.width = w;
    image.height = h;
    image.rgba.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 4u);
    std::memcpy(image.rgba.data(), data, image.rgba.size());
    stbi_image_free(data);
    return image;
}

} // namespace snow
