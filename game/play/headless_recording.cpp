#include "game/play/headless_recording.hpp"

#include "game/play/session_report.hpp"

#include <filesystem>

namespace snow {

HeadlessRecording::HeadlessRecording(const GameOptions& options)
    : recorder_(options.out_dir), video_(options.video) {
    if (options.contact_sheet > 0 && options.frames > 0) {
        // Tiles at most 320 px wide: four to a row make a README-sized sheet.
        sheet_.emplace(options.frames, options.contact_sheet, 4, (options.width + 319) / 320);
    }
}

void HeadlessRecording::add(const Image& image, const GameSession& session, std::uint64_t frame) {
    recorder_.write(image);
    if (sheet_ && sheet_->wants(frame)) {
        sheet_->add(image, moment_label(session));
    }
}

void HeadlessRecording::add_mask(const Image& mask, std::string_view suffix) {
    recorder_.write_beside(mask, suffix);
}

std::string HeadlessRecording::finish() const {
    std::string said = "snow_game: wrote " + std::to_string(recorder_.frames()) + " frames to " +
                       std::filesystem::absolute(recorder_.dir()).string() + "\n";
    if (sheet_ && sheet_->size() > 0) {
        const std::filesystem::path sheet =
            std::filesystem::absolute(std::filesystem::path(recorder_.dir()) / "contact_sheet.png");
        write_png_file(sheet, sheet_->compose());
        said += "snow_game: contact sheet (" + std::to_string(sheet_->size()) + " moments) " +
                sheet.string() + "\n";
    }
    if (video_) {
        if (const auto video = recorder_.encode_video()) {
            said += "snow_game: video " + std::filesystem::absolute(*video).string() + "\n";
        } else {
            said += "snow_game: no video (ffmpeg is not installed: scripts/deps.sh installs it)\n";
        }
    }
    return said;
}

} // namespace snow
