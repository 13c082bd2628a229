/// @file staged_files.hpp
/// @brief Writing output files all or nothing, the one way snow's tools write
/// a file (snapshots, exports, PNG frames, reports): each is written beside
/// its final path under a temporary name, flushed to the disk and renamed
/// into place only once every one of them was written, so a crash or a full
/// disk leaves the old file or the whole new one (docs/reliability.md).
/// Its own library, snow::files: snow::ecs and snow::sim never write files.
#pragma once

#include <snow/error.hpp>

#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

namespace snow {

/// A file that cannot be written: "cannot write '<path>': <step>: <reason>".
class FileWriteError : public Error {
  public:
    using Error::Error;
};

/// Throws FileWriteError unless a file can be created at `file` (its folder
/// exists and is writable, `file` is not a folder). Leaves nothing behind.
void check_file_writable(const std::filesystem::path& file);

/// Creates `dir` (and its parents) when missing; throws FileWriteError unless
/// files can be created in it.
void prepare_output_dir(const std::filesystem::path& dir);

/// Writes `bytes` to `file` all or nothing; throws FileWriteError.
void write_file(const std::filesystem::path& file, std::span<const std::byte> bytes);

class StagedFiles {
  public:
    StagedFiles() = default;
    StagedFiles(const StagedFiles&) = delete;
    StagedFiles& operator=(const StagedFiles&) = delete;
    /// Removes every temporary file not yet committed.
    ~StagedFiles();

    /// Writes `bytes` to a temporary file beside `file` and flushes it to the
    /// disk; throws FileWriteError (the temporary file is then gone).
    void stage(const std::filesystem::path& file, std::span<const std::byte> bytes);
    /// Renames every staged file to its final path and flushes the folders;
    /// throws FileWriteError.
    void commit();

  private:
    struct Staged {
        std::filesystem::path temp, final;
    };
    std::vector<Staged> staged_;
};

} // namespace snow
