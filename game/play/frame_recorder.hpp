/// @file frame_recorder.hpp
/// @brief What snow_game writes to disk: headless frames as numbered PNGs
/// (and a video of them when ffmpeg is installed), and window screenshots.
#pragma once

#include <snow/render.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace snow {

/// Writes `image` as a PNG all or nothing; throws FileWriteError naming the
/// path, which snow_game reports with exit status 2 like snow_run does.
void write_png_file(const std::filesystem::path& path, const Image& image);

class FrameRecorder {
  public:
    /// Frames go to `dir` (created if missing) as frame_00000.png, frame_00001.png, ...;
    /// throws FileWriteError when no file can be written there.
    explicit FrameRecorder(std::string dir);

    /// Writes the next numbered frame; throws FileWriteError naming the file on failure.
    void write(const Image& frame);
    /// Writes `image` beside the last frame written, as frame_<n>_<suffix>.png
    /// (an AOV of that frame); throws FileWriteError like write().
    void write_beside(const Image& image, std::string_view suffix);
    [[nodiscard]] std::uint64_t frames() const { return frames_; }
    [[nodiscard]] const std::string& dir() const { return dir_; }
    /// Encodes the frames written so far into <dir>/snow.mp4 (30 frames/s) if
    /// ffmpeg is on the PATH; returns the video's path, or nothing.
    [[nodiscard]] std::optional<std::string> encode_video() const;

  private:
    std::string dir_;
    std::uint64_t frames_ = 0;
};

/// Writes screenshot number `n` to screenshots/snow_<n>.png; returns its
/// absolute path. Throws FileWriteError naming the file on failure.
[[nodiscard]] std::string save_screenshot(const Image& image, std::uint64_t n);

} // namespace snow
