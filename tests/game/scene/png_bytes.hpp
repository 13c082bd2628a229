/// @file png_bytes.hpp
/// @brief Test support: PNG files of any bit depth and colour type written in
/// the test itself (stored deflate blocks, no compression library), for the
/// terrain's height maps and the ways they can be wrong.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace snow::test {

inline std::uint32_t png_crc(const std::string& bytes) {
    std::uint32_t c = 0xFFFFFFFFu;
    for (const char ch : bytes) {
        c ^= static_cast<unsigned char>(ch);
        for (int k = 0; k < 8; ++k) {
            c = (c & 1u) != 0 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
        }
    }
    return c ^ 0xFFFFFFFFu;
}

inline void put_be32(std::string& out, std::uint32_t v) {
    for (int i = 3; i >= 0; --i) {
        out += static_cast<char>((v >> (8 * i)) & 0xFFu);
    }
}

inline void png_chunk(std::string& out, const char* type, const std::string& data) {
    put_be32(out, static_cast<std::uint32_t>(data.size()));
    const std::string body = std::string(type) + data;
    out += body;
    put_be32(out, png_crc(body));
}

/// A PNG of `width` × `height` with the given bit depth and colour type (0
/// grey, 2 RGB, 4 grey+alpha, 6 RGBA) whose unfiltered rows are `pixels`
/// (big-endian samples). With `pixels` empty only the signature, header and
/// end are written (enough for a size check that never decodes).
inline std::string png_bytes(std::uint32_t width, std::uint32_t height, int bit_depth,
                             int color_type, const std::vector<unsigned char>& pixels) {
    std::string out = "\x89PNG\r\n\x1a\n";
    std::string ihdr;
    put_be32(ihdr, width);
    put_be32(ihdr, height);
    ihdr += static_cast<char>(bit_depth);
    ihdr += static_cast<char>(color_type);
    ihdr += std::string(3, '\0'); // deflate, adaptive filters, no interlace
    png_chunk(out, "IHDR", ihdr);
    if (!pixels.empty()) {
        const std::size_t row = pixels.size() / height;
        std::string raw;
        for (std::uint32_t j = 0; j < height; ++j) {
            raw += '\0'; // filter: none
            raw.append(pixels.begin() + static_cast<std::ptrdiff_t>(j * row),
                       pixels.begin() + static_cast<std::ptrdiff_t>((j + 1) * row));
        }
        std::string z = "\x78\x01"; // zlib header, no compression
        std::uint32_t a = 1, b = 0; // Adler-32
        for (const char ch : raw) {
            a = (a + static_cast<unsigned char>(ch)) % 65521u;
            b = (b + a) % 65521u;
        }
        for (std::size_t at = 0; at < raw.size(); at += 65535) {
            const std::size_t n = std::min<std::size_t>(65535, raw.size() - at);
            z += static_cast<char>(at + n >= raw.size() ? 1 : 0); // final block?
            z += static_cast<char>(n & 0xFFu);
            z += static_cast<char>(n >> 8);
            z += static_cast<char>(~n & 0xFFu);
            z += static_cast<char>((~n >> 8) & 0xFFu);
            z.append(raw, at, n);
        }
        put_be32(z, (b << 16) | a);
        png_chunk(out, "IDAT", z);
    }
    png_chunk(out, "IEND", "");
    return out;
}

/// A 16-bit grey PNG of the samples, row 0 first.
inline std::string height_png(std::uint32_t width, std::uint32_t height,
                              const std::vector<std::uint16_t>& samples) {
    std::vector<unsigned char> px;
    for (const std::uint16_t v : samples) {
        px.push_back(static_cast<unsigned char>(v >> 8));
        px.push_back(static_cast<unsigned char>(v & 0xFFu));
    }
    return png_bytes(width, height, 16, 0, px);
}

} // namespace snow::test
