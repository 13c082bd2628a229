/// @file staged_files.hpp
/// @brief Writing output files all or nothing: each is written beside its
/// final path under a temporary name and renamed into place only once every
/// one of them was written.
#pragma once

#include "ecs/error.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace snow {

/// A file that cannot be written; the message names the path and why.
class ExportError : public Error {
  public:
    using Error::Error;
};

/// Throws ExportError unless a file can be created at `file` (its folder
/// exists and is writable, `file` is not a folder). Leaves nothing behind.
void check_file_writable(const std::filesystem::path& file);

/// Creates `dir` (and its parents) when missing; throws ExportError unless
/// files can be created in it.
void prepare_output_dir(const std::filesystem::path& dir);

class StagedFiles {
  public:
    StagedFiles() = default;
    StagedFiles(const StagedFiles&) = delete;
    StagedFiles& operator=(const StagedFiles&) = delete;
    /// Removes every temporary file not yet committed.
    ~StagedFiles();

    /// Writes `bytes` to a temporary file beside `file`; throws ExportError.
    void stage(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes);
    /// Renames every staged file to its final path; throws ExportError.
    void commit();

  private:
    struct Staged {
        std::filesystem::path temp, final;
    };
    std::vector<Staged> staged_;
};

} // namespace snow
