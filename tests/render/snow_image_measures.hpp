/// @file snow_image_measures.hpp
/// @brief Measures of how snow looks, taken on a rendered image with its two
/// masks (RenderOutput::snow_mask, ::shadow_mask): the blue of its shade, its
/// clipped pixels, the spread of its sunlit brightness and its glints.
#pragma once

#include <snow/render.hpp>

#include <glm/vec2.hpp>

#include <cstddef>
#include <functional>
#include <vector>

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

/// Per pixel of `with`, how many levels of luma it is brighter than the same
/// frame drawn `without` the sparkle; 0 where it is not lit snow.
struct SparkleRise {
    int width = 0, height = 0;
    std::vector<double> rise; ///< top row first
};
[[nodiscard]] SparkleRise sparkle_rise(const MaskedFrame& with, const Image& without);

/// Luma rise that makes a pixel part of a glint.
inline constexpr double glint_rise = 12.0;

/// The glints: 8-connected patches of pixels risen by ≥ glint_rise, each as
/// its centroid (pixels, top row first) weighted by the rise.
[[nodiscard]] std::vector<glm::dvec2> find_glints(const SparkleRise& frame);

/// Share of `glints` (found on one frame) still there in `later`: a pixel
/// within 1.5 px of where `to_later` maps the glint's centre risen by at
/// least half of glint_rise.
[[nodiscard]] double persisting_share(const std::vector<glm::dvec2>& glints,
                                      const SparkleRise& later,
                                      const std::function<glm::dvec2(glm::dvec2)>& to_later);

/// How many levels of luma the pixels of two frames of one size differ by, on average.
[[nodiscard]] double mean_luma_difference(const Image& a, const Image& b);

/// The snow's detail normals and glints measured on one view.
struct DetailLook {
    SnowLook look;               ///< the frame as drawn
    double plain_stddev = 0.0;   ///< lit snow's luma deviation without detail normals and sparkle
    std::size_t glints = 0;      ///< glints on the frame (find_glints)
    double per_100px = 0.0;      ///< ... per 100 × 100 pixels of lit snow
    double persisting = 0.0;     ///< share still there after the camera turns 0.1° (yaw)
    double sparkle_change = 0.0; ///< mean |Δ luma| when the sparkle is turned off ...
    double detail_change = 0.0;  ///< ... and when the detail normals are
};

/// Draws `camera`'s view with `draw` (one frame by `renderer` at the given
/// camera, whose settings it toggles) with and without sparkle and detail
/// normals, and turned 0.1°, and measures it.
[[nodiscard]] DetailLook measure_detail(Renderer& renderer, const ViewCamera& camera,
                                        const std::function<void(const ViewCamera&)>& draw);

/// Prints a DetailLook on one line after `what`.
void print_detail(const char* what, const DetailLook& d);

} // namespace snow::test
