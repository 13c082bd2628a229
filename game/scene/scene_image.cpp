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

/// What a PNG's header says, read before a pixel is decoded.
struct PngHeader {
    int length = 0; ///< of the bytes, as stb takes it
    int width = 0, height = 0, channels = 0;
    [[nodiscard]] std::uint64_t texels() const {
        return static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
    }
};

/// One error naming `field`: stb could not read the PNG.
[[noreturn]] void fail_invalid(const std::string& field) {
    scene_fail(field, std::string("is not a valid PNG (") + stbi_failure_reason() + ")");
}

/// The header of the PNG in `bytes` (`what`: the kind of image, for the
/// error); throws naming `field` unless they start with the PNG signature,
/// fit an int and hold a header stb reads.
PngHeader read_png_header(std::span<const unsigned char> bytes, const std::string& field,
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
    PngHeader header;
    header.length = static_cast<int>(bytes.size());
    if (stbi_info_from_memory(bytes.data(), header.length, &header.width, &header.height,
                              &header.channels) == 0) {
        fail_invalid(field);
    }
    return header;
}

/// Throws naming `field` unless stb decoded pixels (`data`) of the size the
/// header gave.
void check_decoded(const void* data, int width, int height, const PngHeader& header,
                   const std::string& field) {
    if (data == nullptr) {
        fail_invalid(field);
    }
    if (static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height) != header.texels()) {
        scene_fail(field, "is not a valid PNG (its size changed while it was decoded)");
    }
}

} // namespace

Image decode_png(std::span<const unsigned char> bytes, const std::string& field,
                 std::uint64_t& texels) {
    const PngHeader header = read_png_header(bytes, field, "textures");
    const std::uint64_t count = header.texels();
    if (count > max_scene_texels - texels) { // texels <= the cap: no wrap-around
        scene_fail(field, "is " + std::to_string(header.width) + " x " +
                              std::to_string(header.height) + " texels, more than the " +
                              std::to_string(max_scene_texels) +
                              " all textures of a scene may have together");
    }
    int w = 0, h = 0, channels = 0;
    const std::unique_ptr<stbi_uc, void (*)(void*)> data(
        stbi_load_from_memory(bytes.data(), header.length, &w, &h, &channels, 4), stbi_image_free);
    check_decoded(data.get(), w, h, header, field);
    texels += count;
    Image image;
    image.width = w;
    image.height = h;
    image.rgba.resize(static_cast<std::size_t>(count) * 4u);
    std::memcpy(image.rgba.data(), data.get(), image.rgba.size());
    return image;
}

HeightSamples decode_height_png(std::span<const unsigned char> bytes, const std::string& field) {
    const PngHeader header = read_png_header(bytes, field, "height maps");
    const int channels = header.channels;
    // stb reports a palette as 3 or 4 channels and grey with alpha as 2.
    const bool grey16 =
        channels == 1 && stbi_is_16_bit_from_memory(bytes.data(), header.length) != 0;
    if (!grey16) {
        constexpr const char* kinds[] = {"another colour type", "8-bit grey", "grey with alpha",
                                         "RGB", "RGBA"};
        scene_fail(field, std::string("must be a 16-bit grey PNG (got ") +
                              kinds[channels >= 1 && channels <= 4 ? channels : 0] + ")");
    }
    const std::uint64_t count = header.texels();
    if (header.width < 2 || header.height < 2 || count > max_height_samples) {
        scene_fail(field, "is " + std::to_string(header.width) + " x " +
                              std::to_string(header.height) +
                              " samples; a height map needs at least 2 x 2 and at most " +
                              std::to_string(max_height_samples) + " samples");
    }
    int w = 0, h = 0, decoded_channels = 0;
    const std::unique_ptr<stbi_us, void (*)(void*)> data(
        stbi_load_16_from_memory(bytes.data(), header.length, &w, &h, &decoded_channels, 1),
        stbi_image_free);
    check_decoded(data.get(), w, h, header, field);
    HeightSamples out;
    out.width = static_cast<std::uint32_t>(w);
    out.height = static_cast<std::uint32_t>(h);
    out.values.assign(data.get(), data.get() + count);
    return out;
}

} // namespace snow
