#include "game/play/frame_recorder.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace snow {

FrameRecorder::FrameRecorder(std::string dir) : dir_(std::move(dir)) {
    std::filesystem::create_directories(dir_);
}

void FrameRecorder::write(const Image& frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%05llu.png", static_cast<unsigned long long>(frames_));
    write_png(std::filesystem::path(dir_) / name, frame);
    ++frames_;
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
    std::filesystem::create_directories("screenshots");
    const std::string path = "screenshots/snow_" + std::to_string(n) + ".png";
    write_png(path, image);
    return std::filesystem::absolute(path).string();
}

} // namespace snow
