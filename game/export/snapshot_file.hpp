/// @file snapshot_file.hpp
/// @brief Byte snapshots (Simulation::save_bytes) as files: written all or
/// nothing (a temporary file beside the target, flushed to disk, renamed
/// into place), read whole and refused with one error naming the file.
#pragma once

#include "ecs/staged_files.hpp"
#include "systems/api/simulation_internals.hpp"

#include <filesystem>

namespace snow {

/// Writes `sim`'s snapshot to `file`; throws FileWriteError naming the path
/// (an old file there stays whole).
void save_snapshot_file(const Simulation& sim, const std::filesystem::path& file);

/// Restores `sim` from a file save_snapshot_file wrote for the same scene;
/// throws snow::Error naming the file and what is wrong, `sim` unchanged.
void load_snapshot_file(Simulation& sim, const std::filesystem::path& file);

} // namespace snow
