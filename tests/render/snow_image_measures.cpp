#include "tests/render/snow_image_measures.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

namespace snow::test {
namespace {

double luma_of(const std::uint8_t* c) {
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; // Rec. 709
}

/// Where pixel `px` of a frame `from` sees lies in one `to` sees from the same
/// place (a turn moves pixels whatever their depth).
glm::dvec2 turned_pixel(const ViewCamera& from, const ViewCamera& to, glm::dvec2 px, int width,
                        int height) {
    const float aspect = static_cast<float>(width) / static_cast<float>(height);
    const glm::dmat4 a = from.projection(aspect) * from.view();
    const glm::dmat4 b = to.projection(aspect) * to.view();
    const glm::dvec4 ndc{2.0 * (px.x + 0.5) / width - 1.0, 1.0 - 2.0 * (px.y + 0.5) / height, 0.5,
                         1.0};
    const glm::dvec4 world = glm::inverse(a) * ndc;
    glm::dvec4 q = b * (world / world.w);
    q /= q.w;
    return {(q.x + 1.0) * 0.5 * width - 0.5, (1.0 - q.y) * 0.5 * height - 0.5};
}

} // namespace

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
            const double y = luma_of(c);
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

SparkleRise sparkle_rise(const MaskedFrame& with, const Image& without) {
    SparkleRise r{with.color.width, with.color.height, {}};
    r.rise.resize(with.color.rgba.size() / 4, 0.0);
    for (std::size_t p = 0; p < r.rise.size(); ++p) {
        const std::size_t i = 4 * p;
        if (with.snow.rgba[i] >= 128 && with.shadow.rgba[i] <= 26) {
            r.rise[p] = luma_of(&with.color.rgba[i]) - luma_of(&without.rgba[i]);
        }
    }
    return r;
}

std::vector<glm::dvec2> find_glints(const SparkleRise& frame) {
    std::vector<glm::dvec2> glints;
    std::vector<bool> seen(frame.rise.size(), false);
    std::vector<int> stack;
    for (int start = 0; start < static_cast<int>(frame.rise.size()); ++start) {
        const auto s = static_cast<std::size_t>(start);
        if (seen[s] || frame.rise[s] < glint_rise) {
            continue;
        }
        seen[s] = true;
        stack.push_back(start);
        glm::dvec2 sum{0.0};
        double weight = 0.0;
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            const int x = p % frame.width, y = p / frame.width;
            const double w = frame.rise[static_cast<std::size_t>(p)];
            sum += w * glm::dvec2(x, y);
            weight += w;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= frame.width || ny >= frame.height) {
                        continue;
                    }
                    const auto n = static_cast<std::size_t>(ny * frame.width + nx);
                    if (!seen[n] && frame.rise[n] >= glint_rise) {
                        seen[n] = true;
                        stack.push_back(ny * frame.width + nx);
                    }
                }
            }
        }
        glints.push_back(sum / weight);
    }
    return glints;
}

double persisting_share(const std::vector<glm::dvec2>& glints, const SparkleRise& later,
                        const std::function<glm::dvec2(glm::dvec2)>& to_later) {
    if (glints.empty()) {
        return 0.0;
    }
    std::size_t kept = 0;
    for (const glm::dvec2& g : glints) {
        const glm::dvec2 c = to_later(g);
        bool found = false;
        for (int y = static_cast<int>(std::floor(c.y - 1.5)); y <= static_cast<int>(c.y + 1.5);
             ++y) {
            for (int x = static_cast<int>(std::floor(c.x - 1.5)); x <= static_cast<int>(c.x + 1.5);
                 ++x) {
                const bool inside = x >= 0 && y >= 0 && x < later.width && y < later.height;
                const double d2 = (x - c.x) * (x - c.x) + (y - c.y) * (y - c.y);
                found = found || (inside && d2 <= 2.25 &&
                                  later.rise[static_cast<std::size_t>(y * later.width + x)] >=
                                      0.5 * glint_rise);
            }
        }
        kept += found ? 1u : 0u;
    }
    return static_cast<double>(kept) / static_cast<double>(glints.size());
}

double mean_luma_difference(const Image& a, const Image& b) {
    double sum = 0.0;
    for (std::size_t i = 0; i + 3 < a.rgba.size(); i += 4) {
        sum += std::abs(luma_of(&a.rgba[i]) - luma_of(&b.rgba[i]));
    }
    return a.rgba.empty() ? 0.0 : sum / static_cast<double>(a.rgba.size() / 4);
}

DetailLook measure_detail(Renderer& renderer, const ViewCamera& camera,
                          const std::function<void(const ViewCamera&)>& draw) {
    ViewCamera turned = camera;
    turned.turn(glm::radians(0.1f), 0.0f);
    const auto color = [&](const ViewCamera& c) {
        draw(c);
        return renderer.read_pixels();
    };
    RenderSettings& settings = renderer.settings();
    const MaskedFrame frame = render_masked(renderer, [&] { draw(camera); });
    const MaskedFrame frame_turned = render_masked(renderer, [&] { draw(turned); });
    settings.sparkle = false;
    const Image no_sparkle = color(camera);
    const Image no_sparkle_turned = color(turned);
    settings.detail_normals = false;
    const Image plain = color(camera);
    settings.sparkle = true;
    const Image no_detail = color(camera);
    settings.detail_normals = true;

    DetailLook d;
    d.look = measure_snow(frame);
    d.plain_stddev = measure_snow(MaskedFrame{plain, frame.snow, frame.shadow}).lit_luma_stddev;
    const std::vector<glm::dvec2> glints = find_glints(sparkle_rise(frame, no_sparkle));
    d.glints = glints.size();
    d.per_100px = 1e4 * static_cast<double>(glints.size()) /
                  static_cast<double>(std::max<std::size_t>(d.look.lit_pixels, 1));
    const int w = frame.color.width, h = frame.color.height;
    d.persisting =
        persisting_share(glints, sparkle_rise(frame_turned, no_sparkle_turned),
                         [&](glm::dvec2 px) { return turned_pixel(camera, turned, px, w, h); });
    d.sparkle_change = mean_luma_difference(frame.color, no_sparkle);
    d.detail_change = mean_luma_difference(frame.color, no_detail);
    return d;
}

void print_detail(const char* what, const DetailLook& d) {
    std::printf("%s: lit luma %.1f ± %.2f (without detail and sparkle ± %.2f), clipped %.4f; "
                "%zu glints on %zu lit px = %.2f per 100x100 px, %.4f persist a 0.1° turn; "
                "mean |Δluma| without sparkle %.3f, without detail normals %.3f\n",
                what, d.look.lit_luma_mean, d.look.lit_luma_stddev, d.plain_stddev,
                d.look.clipped_share, d.glints, d.look.lit_pixels, d.per_100px, d.persisting,
                d.sparkle_change, d.detail_change);
}

} // namespace snow::test
