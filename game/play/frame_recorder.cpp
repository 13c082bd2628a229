#include "game/play/frame_recorder.hpp"

#include "ecs/staged_files.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <span>
#include <vector>

namespace snow {

void write_png_file(const std::filesystem::path& path, const Image& image) {
    const std::vector<std::uint8_t> png = encode_png(image);
    write_file(path, std::as_bytes(std::span(png)));
}

FrameRecorder::FrameRecorder(std::string dir) : dir_(std::move(dir)) {
    prepare_output_dir(dir_);
}

void FrameRecorder::write(const Image& frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05llu.png", static_cast<unsigned long long>(frames_));
    write_png_file(std::filesystem::path(dir_) / name, frame);
    ++frames_;
}

void FrameRecorder::write_beside(const Image& image, std::string_view suffix) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05llu_",
                  static_cast<unsigned long long>(frames_ == 0 ? 0 : frames_ - 1));
    write_png_file(std::filesystem::path(dir_) / (name + std::string(suffix) + ".png"), image);
}

std::optional<std::string> FrameRecorder::encode_video() const {
    if (frames_ == 0 || std::system("command -v ffmpeg >/dev/null 2>&1") != 0) {
        return std::nullopt;
    }
    const std::string video = dir_ + "/snow.mp4";
    const std::string cmd = "ffmpeg -loglevel error -y -framerate 30 -i '" + dir_ +
                            "/frame_%05d.png' -pix_fmt yuv420p '" + video + "'";
    if (std::system(cmd.c_str()) != 0) {
        return std::nullopt;
    }
    return video;
}

std::string save_screenshot(const Image& image, std::uint64_t n) {
    prepare_output_dir("screenshots");
    const std::string path = "screenshots/snow_" + std::to_string(n) + ".png";
    write_png_file(path, image);
    return std::filesystem::absolute(path).string();
}

} // namespace snow
