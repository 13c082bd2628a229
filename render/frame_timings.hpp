/// @file frame_timings.hpp
/// @brief What the last frame cost, per pass, and what it drew.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace snow {

struct PassTiming {
    std::string name;
    bool ran = false;    ///< false when the world had nothing for the pass
    double cpu_ms = 0.0; ///< wall time around the pass (includes GPU work in timing mode)
};

struct FrameTimings {
    std::vector<PassTiming> passes; ///< "setup" (uniforms, shared textures), then each pass
    double frame_ms = 0.0;          ///< whole render() call
    bool synchronous = false;       ///< RenderSettings::timing_mode was on
    std::uint32_t flakes_alive = 0;
    std::uint32_t flakes_drawn = 0;           ///< after culling and level of detail
    std::uint32_t surfaces_uploaded = 0;      ///< snow surfaces with a changed tile this frame
    std::uint32_t surface_tiles_uploaded = 0; ///< their changed tiles (only these are re-uploaded)
    std::uint32_t surface_tiles_drawn = 0;    ///< after culling, every level of detail
    std::uint32_t surface_samples = 0;        ///< heightfield samples of those tiles
    std::uint32_t meshes_uploaded = 0;        ///< scene meshes uploaded this frame
};

} // namespace snow
