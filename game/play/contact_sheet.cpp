#include "game/play/contact_sheet.hpp"

#include <algorithm>
#include <array>
#include <cstring>

namespace snow {

namespace {

/// A glyph 5 rows high and `width` (3 or 5) pixels wide: one row per entry,
/// bit width−1 the left column.
struct Glyph {
    char c;
    int width;
    std::array<std::uint8_t, 5> rows;
};

constexpr std::array<Glyph, 20> glyphs{{
    {'0', 3, {7, 5, 5, 5, 7}},     {'1', 3, {2, 6, 2, 2, 7}}, {'2', 3, {7, 1, 7, 4, 7}},
    {'3', 3, {7, 1, 3, 1, 7}},     {'4', 3, {5, 5, 7, 1, 1}}, {'5', 3, {7, 4, 7, 1, 7}},
    {'6', 3, {7, 4, 7, 5, 7}},     {'7', 3, {7, 1, 1, 2, 2}}, {'8', 3, {7, 5, 7, 5, 7}},
    {'9', 3, {7, 5, 7, 1, 7}},     {':', 3, {0, 2, 0, 2, 0}}, {'.', 3, {0, 0, 0, 0, 2}},
    {'-', 3, {0, 0, 7, 0, 0}},     {' ', 3, {0, 0, 0, 0, 0}}, {'c', 3, {0, 7, 4, 4, 7}},
    {'m', 5, {0, 30, 21, 21, 21}}, {'s', 3, {0, 3, 6, 1, 6}}, {'t', 3, {2, 7, 2, 2, 3}},
    {'x', 3, {0, 5, 2, 5, 0}},     {'%', 3, {5, 1, 2, 4, 5}},
}};

/// Calls fn(pixel) for the pixels of a rectangle that lie inside the image.
template <typename Fn>
void for_rect(Image& image, int x0, int y0, int w, int h, Fn&& fn) {
    for (int y = std::max(0, y0); y < std::min(image.height, y0 + h); ++y) {
        for (int x = std::max(0, x0); x < std::min(image.width, x0 + w); ++x) {
            fn(image.rgba.data() + (static_cast<std::size_t>(y) * image.width + x) * 4);
        }
    }
}

void fill(Image& image, int x0, int y0, int w, int h, std::uint8_t value) {
    for_rect(image, x0, y0, w, h, [value](std::uint8_t* p) {
        p[0] = p[1] = p[2] = value;
        p[3] = 255;
    });
}

const Glyph* glyph(char c) {
    const auto g =
        std::find_if(glyphs.begin(), glyphs.end(), [c](const Glyph& g) { return g.c == c; });
    return g != glyphs.end() ? &*g : nullptr;
}

int advance(const Glyph* g, int scale) {
    return ((g != nullptr ? g->width : 3) + 1) * scale;
}

} // namespace

Image shrink_image(const Image& image, int factor) {
    Image out;
    out.width = image.width / factor;
    out.height = image.height / factor;
    out.rgba.resize(static_cast<std::size_t>(out.width) * out.height * 4);
    for (int y = 0; y < out.height; ++y) {
        for (int x = 0; x < out.width; ++x) {
            std::array<unsigned, 4> sum{};
            for (int j = 0; j < factor; ++j) {
                for (int i = 0; i < factor; ++i) {
                    const std::uint8_t* p = image.pixel(x * factor + i, y * factor + j);
                    for (int c = 0; c < 4; ++c) {
                        sum[c] += p[c];
                    }
                }
            }
            std::uint8_t* q = out.rgba.data() + (static_cast<std::size_t>(y) * out.width + x) * 4;
            for (int c = 0; c < 4; ++c) {
                q[c] = static_cast<std::uint8_t>(sum[c] / static_cast<unsigned>(factor * factor));
            }
        }
    }
    return out;
}

void draw_label(Image& image, int x, int y, std::string_view text, int scale) {
    int width = 0;
    for (const char c : text) {
        width += advance(glyph(c), scale);
    }
    // A darkened band behind the text keeps it readable on snow and sky alike.
    for_rect(image, x - scale, y - scale, width + scale, 7 * scale, [](std::uint8_t* p) {
        for (int k = 0; k < 3; ++k) {
            p[k] = static_cast<std::uint8_t>(p[k] * 2 / 5);
        }
    });
    for (const char c : text) {
        const Glyph* g = glyph(c);
        for (int row = 0; g != nullptr && row < 5; ++row) {
            for (int col = 0; col < g->width; ++col) {
                if ((g->rows[row] >> (g->width - 1 - col)) & 1u) {
                    fill(image, x + col * scale, y + row * scale, scale, scale, 250);
                }
            }
        }
        x += advance(g, scale);
    }
}

ContactSheet::ContactSheet(std::uint64_t frames, std::uint32_t moments, std::uint32_t columns,
                           int shrink)
    : columns_(std::max(1u, columns)), shrink_(std::max(1, shrink)) {
    for (std::uint32_t k = 0; k < moments && frames > 0; ++k) {
        const std::uint64_t f =
            moments > 1 ? (k * (frames - 1) + (moments - 1) / 2) / (moments - 1) : 0;
        if (moments_.empty() || moments_.back() != f) {
            moments_.push_back(f);
        }
    }
}

bool ContactSheet::wants(std::uint64_t frame) const {
    return std::binary_search(moments_.begin(), moments_.end(), frame);
}

void ContactSheet::add(const Image& frame, std::string_view label) {
    Image tile = shrink_image(frame, shrink_);
    const int scale = std::max(2, tile.height / 60);
    draw_label(tile, 2 * scale, 2 * scale, label, scale);
    tiles_.push_back(std::move(tile));
}

Image ContactSheet::compose() const {
    constexpr int gap = 4;
    Image sheet;
    if (tiles_.empty()) {
        return sheet;
    }
    const int tw = tiles_.front().width, th = tiles_.front().height;
    const int cols = static_cast<int>(std::min<std::size_t>(columns_, tiles_.size()));
    const int rows = static_cast<int>((tiles_.size() + columns_ - 1) / columns_);
    sheet.width = cols * tw + (cols + 1) * gap;
    sheet.height = rows * th + (rows + 1) * gap;
    sheet.rgba.assign(static_cast<std::size_t>(sheet.width) * sheet.height * 4, 0);
    fill(sheet, 0, 0, sheet.width, sheet.height, 24);
    for (std::size_t t = 0; t < tiles_.size(); ++t) {
        const int x0 = gap + static_cast<int>(t % columns_) * (tw + gap);
        const int y0 = gap + static_cast<int>(t / columns_) * (th + gap);
        for (int y = 0; y < std::min(th, tiles_[t].height); ++y) {
            std::memcpy(
                sheet.rgba.data() + (static_cast<std::size_t>(y0 + y) * sheet.width + x0) * 4,
                tiles_[t].pixel(0, y), static_cast<std::size_t>(std::min(tw, tiles_[t].width)) * 4);
        }
    }
    return sheet;
}

} // namespace snow
