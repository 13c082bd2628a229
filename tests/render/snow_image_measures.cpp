#include "tests/render/snow_image_measures.hpp"

#include <algorithm>
#include <cmath>

namespace snow::test {

MaskedFrame render_masked(Renderer& renderer, const std::function<void()>& draw) {
    MaskedFrame f;
    for (const auto& [output, image] :
         {std::pair{RenderOutput::color, &f.color}, std::pair{RenderOutput::snow_mask, &f.snow},
          std::pair{RenderOutput::shadow_mask, &f.shadow}}) {
        renderer.settings().output = output;
        draw();
        *image = renderer.read_pixels();
    }
    renderer.settings().output = RenderOutput::color;
    return f;
}

SnowLook measure_snow(const MaskedFrame& frame) {
    SnowLook look;
    double blue_red = 0.0, luma = 0.0, luma2 = 0.0;
    std::size_t clipped = 0;
    for (std::size_t i = 0; i + 3 < frame.color.rgba.size(); i += 4) {
        if (frame.snow.rgba[i] < 128) {
            continue;
        }
        const std::uint8_t* c = &frame.color.rgba[i];
        ++look.snow_pixels;
        clipped += std::max({c[0], c[1], c[2]}) >= 254 ? 1u : 0u;
        const std::uint8_t shadow = frame.shadow.rgba[i];
        if (shadow >= 128) {
            ++look.shadowed_pixels;
            blue_red += static_cast<double>(c[2]) / std::max<double>(c[0], 1.0);
        } else if (shadow <= 26) {
            ++look.lit_pixels;
            const double y = 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
            luma += y;
            luma2 += y * y;
        }
    }
    if (look.snow_pixels > 0) {
        look.clipped_share = static_cast<double>(clipped) / static_cast<double>(look.snow_pixels);
    }
    if (look.shadowed_pixels > 0) {
        look.shadow_blue_red = blue_red / static_cast<double>(look.shadowed_pixels);
    }
    if (look.lit_pixels > 0) {
        const auto n = static_cast<double>(look.lit_pixels);
        look.lit_luma_mean = luma / n;
        look.lit_luma_stddev =
            std::sqrt(std::max(luma2 / n - look.lit_luma_mean * look.lit_luma_mean, 0.0));
    }
    return look;
}

} // namespace snow::test
