/// @file png16.hpp
/// @brief A 16-bit grayscale PNG encoder (stb_image_write only writes 8 bits).
#pragma once

#include <cstdint>
#include <vector>

namespace snow {

/// PNG bytes for a width × height image, `pixels` row by row (row 0 first,
/// as PNG stores it). Throws std::invalid_argument for a zero or mismatched size.
[[nodiscard]] std::vector<std::uint8_t> encode_png_gray16(std::uint32_t width, std::uint32_t height,
                                                          const std::vector<std::uint16_t>& pixels);

} // namespace snow
