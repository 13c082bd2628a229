/// @file headless_recording.hpp
/// @brief The recording part of a headless snow_game run: every frame as a
/// numbered PNG, chosen moments tiled on a contact sheet, and at the end a
/// video of the frames. It reads the session for the sheet's labels only.
#pragma once

#include "game/play/contact_sheet.hpp"
#include "game/play/frame_recorder.hpp"
#include "game/play/game_options.hpp"
#include "game/play/game_session.hpp"

#include <snow/render.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace snow {

/// The masks --aov writes beside each frame, and the suffixes of their files.
inline constexpr std::pair<RenderOutput, std::string_view> aov_masks[] = {
    {RenderOutput::snow_mask, "snow"},
    {RenderOutput::shadow_mask, "shadow"},
};

class HeadlessRecording {
  public:
    /// Frames go to options.out_dir; with options.contact_sheet moments and a
    /// frame limit, a contact sheet of them too; options.video: a video at the end.
    explicit HeadlessRecording(const GameOptions& options);

    /// Writes frame `frame` (from 0); keeps it on the sheet, labelled with
    /// the session's moment, when it is one of the sheet's moments.
    void add(const Image& image, const GameSession& session, std::uint64_t frame);
    /// Writes a mask of the frame added last beside it (frame_<n>_<suffix>.png).
    void add_mask(const Image& mask, std::string_view suffix);
    /// Writes the contact sheet and encodes the video; says what it wrote where.
    [[nodiscard]] std::string finish() const;

  private:
    FrameRecorder recorder_;
    std::optional<ContactSheet> sheet_;
    bool video_;
};

} // namespace snow
