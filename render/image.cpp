#include <snow/render.hpp>

#include <snow/error.hpp>

#include "ecs/staged_files.hpp"

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include <cstring>
#include <span>
#include <vector>

namespace snow {

namespace {

/// stb's output callback: appends the encoded bytes to a vector.
void append_bytes(void* out, void* data, int size) {
    auto& bytes = *static_cast<std::vector<std::uint8_t>*>(out);
    const auto* b = static_cast<const std::uint8_t*>(data);
    bytes.insert(bytes.end(), b, b + size);
}

} // namespace

std::vector<std::uint8_t> encode_png(const Image& image) {
    const std::size_t expected =
        static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4u;
    if (image.width <= 0 || image.height <= 0 || image.rgba.size() != expected) {
        throw RenderError("encode_png: image size does not match its data");
    }
    std::vector<std::uint8_t> png;
    if (stbi_write_png_to_func(append_bytes, &png, image.width, image.height, 4, image.rgba.data(),
                               image.width * 4) == 0) {
        throw RenderError("encode_png: cannot encode the image");
    }
    return png;
}

void write_png(const std::filesystem::path& path, const Image& image) {
    // Encoded in memory, then written all or nothing like every file snow writes.
    const std::vector<std::uint8_t> png = encode_png(image);
    try {
        write_file(path, std::as_bytes(std::span(png)));
    } catch (const FileWriteError& e) {
        throw RenderError("write_png: " + std::string(e.what()));
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
