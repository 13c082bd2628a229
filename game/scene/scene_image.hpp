/// @file scene_image.hpp
/// @brief Decodes the PNG images a scene's materials use as base colour
/// textures (internal to snow::scene), with stb_image, which snow_render
/// already reads PNGs with (Debian's libstb-dev).
#pragma once

#include <snow/render.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace snow {

/// Most texels all of a scene's textures may have together (RGBA8: 64 MiB),
/// checked from each PNG's header before it is decoded.
inline constexpr std::uint64_t max_scene_texels = 1u << 24;

/// The PNG in `bytes` as RGBA8, rows top first. `texels` counts the scene's
/// texels so far and grows by this image's. Throws SceneError naming `field`
/// when the bytes are not a PNG, not a valid one, or too large.
[[nodiscard]] Image decode_png(std::span<const unsigned char> bytes, const std::string& field,
                               std::uint64_t& texels);

/// Most samples a terrain's height map may have (8192²): 128 MiB of
/// samples, checked from the PNG's header before it is decoded.
inline constexpr std::uint64_t max_height_samples = std::uint64_t{8192} * 8192;

/// A 16-bit grey image: `width` × `height` samples, row 0 first as stored.
struct HeightSamples {
    std::uint32_t width = 0, height = 0;
    std::vector<std::uint16_t> values; ///< width × height, row-major
};

/// The 16-bit grey PNG in `bytes` (a terrain's height map). Throws SceneError
/// naming `field` when the bytes are not a valid PNG, not 16-bit grey (8 bits,
/// RGB, a palette or alpha), smaller than 2 × 2 or over max_height_samples.
[[nodiscard]] HeightSamples decode_height_png(std::span<const unsigned char> bytes,
                                              const std::string& field);

} // namespace snow
