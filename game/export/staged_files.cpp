#include "game/export/staged_files.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace snow {

namespace {

/// Beside `file`, a name no other snow_run process uses at the same time.
std::filesystem::path temp_beside(const std::filesystem::path& file) {
    std::filesystem::path t = file;
    t += ".tmp-" + std::to_string(::getpid());
    return t;
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& why) {
    throw ExportError("cannot write '" + path.string() + "': " + why);
}

void write_bytes(const std::filesystem::path& path, const std::filesystem::path& shown,
                 const std::vector<std::uint8_t>& bytes) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f == nullptr) {
        fail(shown, std::strerror(errno));
    }
    // Flushed to the disk before the rename, so a crash leaves the old file
    // or the whole new one (docs/export.md).
    const bool wrote =
        (bytes.empty() || std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size()) &&
        std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
    const int write_errno = errno;
    if (std::fclose(f) != 0 || !wrote) {
        const int e = wrote ? errno : write_errno;
        std::error_code ignored;
        std::filesystem::remove(path, ignored);
        fail(shown, std::strerror(e));
    }
}

} // namespace

void check_file_writable(const std::filesystem::path& file) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) {
        fail(file, "it is a folder");
    }
    const std::filesystem::path probe = temp_beside(file);
    write_bytes(probe, file, {});
    std::filesystem::remove(probe, ec);
}

void prepare_output_dir(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        fail(dir, ec.message());
    }
    if (!std::filesystem::is_directory(dir, ec)) {
        fail(dir, "not a folder");
    }
    check_file_writable(dir / ".snow-probe");
}

StagedFiles::~StagedFiles() {
    for (const Staged& s : staged_) {
        std::error_code ignored;
        std::filesystem::remove(s.temp, ignored);
    }
}

void StagedFiles::stage(const std::filesystem::path& file, const std::vector<std::uint8_t>& bytes) {
    const std::filesystem::path temp = temp_beside(file);
    write_bytes(temp, file, bytes);
    staged_.push_back({temp, file});
}

void StagedFiles::commit() {
    for (const Staged& s : staged_) {
        std::error_code ec;
        std::filesystem::rename(s.temp, s.final, ec);
        if (ec) {
            fail(s.final, ec.message());
        }
    }
    staged_.clear();
}

} // namespace snow
