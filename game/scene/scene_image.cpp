// PNG decoding for base colour textures. Scene files are untrusted input: the
// signature is checked first and the header's size against the cap before a
// pixel is decoded, so a hostile file cannot make the decoder allocate much.
#include "game/scene/scene_image.hpp"

#include "game/scene/scene_error.hpp"

#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#define STBI_NO_STDIO // bytes only: the loader reads files itself, fenced to the scene's folder
#include <stb/stb_image.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cstring>
#include <memory>

namespace snow {

namespace {

/// Throws naming `field` unless `bytes` start with the PNG signature and fit an int.
void check_png_signature(std::span<const unsigned char> bytes, const std::string& field,
                         const char* what) {
    constexpr std::array<unsigned char, 8> signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    if (bytes.size() < signature.size() ||
        !std::equal(signature.begin(), signature.end(), bytes.begin())) {
        scene_fail(field, std::string("is not a PNG (its bytes do not start with the PNG "
                                      "signature; only PNG ") +
                              what + " are read)");
    }
    if (bytes.size() > INT_MAX) {
        scene_fail(field, "has " + std::to_string(bytes.size()) + " bytes, too many for a PNG");
    }
}

} // namespace

Image decode_png(std::span<const unsigned char> bytes, const std::string& field,
                 std::uint64_t& texels) {
    check_png_signature(bytes, field, "textures");
    const int length = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (stbi_info_from_memory(bytes.data(), length, &w, &h, &channels) == 0) {
        scene_fail(field, std::string("is not a valid PNG (") + stbi_failure_reason() + ")");
    }
    const std::uint64_t count = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    if (count > max_scene_texels - texels) { // texels <= the cap: no wrap-around
        scene_fail(field, "is " + std::to_string(w) + " x " + std::to_string(h) +
                              " texels, more than the " + std::to_string(max_scene_texels) +
                              " all textures of a scene may have together");
    }
    const std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), length, &w, &h, &channels, 4), stbi_image_free);
    if (!data) {
        scene_fail(field, std::string("is not a valid PNG (") + stbi_failure_reason() + ")");
    }
    if (static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) != count) {
        scene_fail(field, "is not a valid PNG (its size changed while it was decoded)");
    }
    texels += count;
    Image image;
    image.width = w;
    image.height = h;
    image.rgba.resize(static_cast<std::size_t>(count) * 4u);
    std::memcpy(image.rgba.data(), data.get(), image.rgba.size());
    return image;
}

HeightSamples decode_height_png(std::span<const unsigned char> bytes, const std::string& field) {
    check_png_signature(bytes, field, "height maps");
    const int length = static_cast<int>(bytes.size());
    int w = 0, h = 0, channels = 0;
    if (stbi_info_from_memory(bytes.data(), length, &w, &h, &channels) == 0) {
        scene_fail(field, std::string("is not a valid PNG (") + stbi_failure_reason() + ")");
    }
    // stb reports a palette as 3 or 4 channels and grey with alpha as 2.
    const bool grey16 = channels == 1 && stbi_is_16_bit_from_memory(bytes.data(), length) != 0;
    if (!grey16) {
        constexpr const char* kinds[] = {"another colour type", "8-bit grey", "grey with alpha",
                                         "RGB", "RGBA"};
        scene_fail(field, std::string("must be a 16-bit grey PNG (got ") +
                              kinds[channels >= 1 && channels <= 4 ? channels : 0] + ")");
    }
    const std::uint64_t count = static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h);
    if (w < 2 || h < 2 || count > max_height_samples) {
        scene_fail(field, "is " + std::to_string(w) + " x " + std::to_string(h) +
                              " samples; a height map needs at least 2 x 2 and at most " +
                              std::to_string(max_height_samples) + " samples");
    }
    const std::unique_ptr<stbi_us, void (*)(void*)> data(
        stbi_load_16_from_memory(bytes.data(), length, &w, &h, &channels, 1), stbi_image_free);
    if (!data) {
        scene_fail(field, std::string("is not a valid PNG (") + stbi_failure_reason() + ")");
    }
    if (static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) != count) {
        scene_fail(field, "is not a valid PNG (its size changed while it was decoded)");
    }
    HeightSamples out;
    out.width = static_cast<std::uint32_t>(w);
    out.height = static_cast<std::uint32_t>(h);
    out.values.assign(data.get(), data.get() + count);
    return out;
}

} // namespace snow
