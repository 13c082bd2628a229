/// @file snow_image_measures.hpp
/// @brief Measures of how snow looks, taken on a rendered image with its two
/// masks (RenderOutput::snow_mask, ::shadow_mask): the blue of its shade, its
/// clipped pixels and the spread of its sunlit brightness.
#pragma once

#include <snow/render.hpp>

#include <cstddef>
#include <functional>

namespace snow::test {

/// One frame as colour and both masks, all the same size.
struct MaskedFrame {
    Image color, snow, shadow;
};

/// Draws the same frame three times through `draw` (which renders one frame
/// with `renderer`): as colour, as the snow mask and as the shadow mask.
[[nodiscard]] MaskedFrame render_masked(Renderer& renderer, const std::function<void()>& draw);

struct SnowLook {
    std::size_t snow_pixels = 0;     ///< snow mask ≥ 50 %
    std::size_t shadowed_pixels = 0; ///< of those, shadow mask ≥ 50 %
    std::size_t lit_pixels = 0;      ///< of those, shadow mask ≤ 10 %
    double shadow_blue_red = 0.0;    ///< mean B / R over the shadowed snow pixels
    double clipped_share = 0.0;      ///< share of snow pixels with a channel ≥ 254
    double lit_luma_mean = 0.0;      ///< Rec. 709 luma (0..255) of the lit snow pixels ...
    double lit_luma_stddev = 0.0;    ///< ... and its standard deviation
};

[[nodiscard]] SnowLook measure_snow(const MaskedFrame& frame);

} // namespace snow::test
