/// @file snow_export.hpp
/// @brief Baking a simulation's settled snow out (docs/export.md): every
/// surface and cover as a mesh in one .glb, or each one's depth as a 16-bit
/// PNG with a JSON sidecar. All or nothing: on failure no file is left.
#pragma once

#include "ecs/staged_files.hpp"
#include "systems/api/simulation_internals.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace snow {

/// Writes the snow of every surface of `sim` to `file` (glTF 2.0 binary).
/// Throws FileWriteError naming the path.
void export_snow_glb(const Simulation& sim, const std::filesystem::path& file);

/// Writes `<name>.png` and `<name>.json` for every surface into `dir`
/// (created when missing). Throws FileWriteError naming the path.
void export_snow_depth(const Simulation& sim, const std::filesystem::path& dir);

/// Depth in millimetres per cell (clamped to 65535; void cells 0), row-major
/// from min z: the pixels of a surface's depth PNG.
[[nodiscard]] std::vector<std::uint16_t> depth_mm(const SnowSurface& s);

} // namespace snow
