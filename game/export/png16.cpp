// A PNG is the signature, then chunks of (length, type, data, CRC-32 of type
// and data): IHDR, IDAT holding the zlib stream of the filtered rows, IEND.
// Rows use filter 0 (none); samples are big-endian (PNG spec §7, §11).
#include "game/export/png16.hpp"

#include <zlib.h>

#include <stdexcept>
#include <string>

namespace snow {

namespace {

void put_u32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) {
        out.push_back(static_cast<std::uint8_t>(v >> shift));
    }
}

void put_chunk(std::vector<std::uint8_t>& out, const char (&type)[5],
               const std::vector<std::uint8_t>& data) {
    put_u32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t start = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    const uLong crc =
        crc32(crc32(0L, Z_NULL, 0), out.data() + start, static_cast<uInt>(out.size() - start));
    put_u32(out, static_cast<std::uint32_t>(crc));
}

} // namespace

std::vector<std::uint8_t> encode_png_gray16(std::uint32_t width, std::uint32_t height,
                                            const std::vector<std::uint16_t>& pixels) {
    if (width == 0 || height == 0 || pixels.size() != static_cast<std::size_t>(width) * height) {
        throw std::invalid_argument("png: " + std::to_string(width) + "x" + std::to_string(height) +
                                    " image with " + std::to_string(pixels.size()) + " pixels");
    }
    std::vector<std::uint8_t> rows;
    rows.reserve(static_cast<std::size_t>(height) * (1 + 2 * static_cast<std::size_t>(width)));
    for (std::uint32_t y = 0; y < height; ++y) {
        rows.push_back(0); // filter: none
        for (std::uint32_t x = 0; x < width; ++x) {
            const std::uint16_t v = pixels[static_cast<std::size_t>(y) * width + x];
            rows.push_back(static_cast<std::uint8_t>(v >> 8));
            rows.push_back(static_cast<std::uint8_t>(v & 0xFF));
        }
    }
    uLongf packed_size = compressBound(static_cast<uLong>(rows.size()));
    std::vector<std::uint8_t> packed(packed_size);
    if (compress2(packed.data(), &packed_size, rows.data(), static_cast<uLong>(rows.size()),
                  Z_BEST_SPEED) != Z_OK) {
        throw std::runtime_error("png: zlib could not compress the image");
    }
    packed.resize(packed_size);
    std::vector<std::uint8_t> header;
    put_u32(header, width);
    put_u32(header, height);
    header.insert(header.end(),
                  {16, 0, 0, 0, 0}); // 16 bits, grayscale, deflate, filter 0, no interlace
    std::vector<std::uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    put_chunk(out, "IHDR", header);
    put_chunk(out, "IDAT", packed);
    put_chunk(out, "IEND", {});
    return out;
}

} // namespace snow
