/// @file image.hpp
/// @brief An RGBA8 image (top row first) and PNG files via stb.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace snow {

/// RGBA, 8 bits per channel, rows top to bottom (as a PNG stores them).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;

    /// Pointer to the 4 channels of pixel (x, y), y = 0 at the top.
    [[nodiscard]] const std::uint8_t* pixel(int x, int y) const {
        return rgba.data() + (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                              static_cast<std::size_t>(x)) *
                                 4u;
    }
};

/// Writes `image` as a PNG; throws RenderError naming the path on failure.
void write_png(const std::filesystem::path& path, const Image& image);

/// Reads a PNG as RGBA8; throws RenderError naming the path. For trusted files
/// only (golden images): stb_image is not hardened against hostile input.
[[nodiscard]] Image read_png(const std::filesystem::path& path);

} // namespace snow
