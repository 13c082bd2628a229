/// @file contact_sheet.hpp
/// @brief One PNG that tells a headless run at a glance: evenly spaced
/// moments of it, shrunk, labelled and tiled in rows.
#pragma once

#include <snow/render.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace snow {

/// `image` shrunk by a whole `factor` (mean of each factor × factor block).
[[nodiscard]] Image shrink_image(const Image& image, int factor);

/// Writes `text` at (x, y) in a 3×5 pixel font scaled by `scale`, white on a
/// dark shadow. Draws digits, ':', '.', '-', ' ', 'c', 'm', 's', 't', 'x';
/// other characters leave a gap.
void draw_label(Image& image, int x, int y, std::string_view text, int scale);

class ContactSheet {
  public:
    /// `moments` frames, evenly spaced over frames 0 .. frames−1 (both ends
    /// included), each shrunk by `shrink` and laid out `columns` to a row.
    ContactSheet(std::uint64_t frames, std::uint32_t moments, std::uint32_t columns, int shrink);

    /// True if frame `frame` is one of the moments.
    [[nodiscard]] bool wants(std::uint64_t frame) const;
    /// Adds a moment (in order) with its label.
    void add(const Image& frame, std::string_view label);
    [[nodiscard]] std::size_t size() const { return tiles_.size(); }
    /// The sheet: tiles on a dark background, 4 px apart.
    [[nodiscard]] Image compose() const;

  private:
    std::vector<std::uint64_t> moments_;
    std::uint32_t columns_;
    int shrink_;
    std::vector<Image> tiles_;
};

} // namespace snow
