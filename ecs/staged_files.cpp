#include "ecs/staged_files.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <string>

namespace snow {

namespace fs = std::filesystem;

namespace {

/// Beside `file`, a name no other process uses at the same time.
fs::path temp_beside(const fs::path& file) {
    fs::path t = file;
    t += ".tmp-" + std::to_string(::getpid());
    return t;
}

[[noreturn]] void fail(const fs::path& path, const std::string& what) {
    throw FileWriteError("cannot write '" + path.string() + "': " + what);
}

[[noreturn]] void fail(const fs::path& path, const char* step, int error) {
    fail(path, std::string(step) + ": " + std::strerror(error));
}

/// Writing past the file size limit (RLIMIT_FSIZE, `ulimit -f`) raises
/// SIGXFSZ, which ends the process. Held back while a file is written, the
/// write fails with EFBIG instead and is reported like a full disk; the
/// signals our writes raised are dropped before it is let through again.
class FileSizeSignalHeld {
  public:
    FileSizeSignalHeld() {
        sigemptyset(&xfsz_);
        sigaddset(&xfsz_, SIGXFSZ);
        pthread_sigmask(SIG_BLOCK, &xfsz_, &before_);
    }
    ~FileSizeSignalHeld() {
        if (sigismember(&before_, SIGXFSZ) == 1) {
            return; // the caller holds it back itself
        }
        const timespec now{};
        while (sigtimedwait(&xfsz_, nullptr, &now) == SIGXFSZ) {
        }
        pthread_sigmask(SIG_SETMASK, &before_, nullptr);
    }
    FileSizeSignalHeld(const FileSizeSignalHeld&) = delete;
    FileSizeSignalHeld& operator=(const FileSizeSignalHeld&) = delete;

  private:
    sigset_t xfsz_{}, before_{};
};

/// Creates `path` with all of `bytes` and flushes it to the disk; on failure
/// removes it and throws naming `shown` and the step that failed.
void write_whole(const fs::path& path, const fs::path& shown, std::span<const std::byte> bytes) {
    const FileSizeSignalHeld held;
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        fail(shown, "cannot create a file in its folder", errno);
    }
    const char* step = nullptr;
    int error = 0;
    std::size_t done = 0;
    while (done < bytes.size() && step == nullptr) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n > 0) {
            done += static_cast<std::size_t>(n);
        } else if (n == 0 || errno != EINTR) {
            step = "writing failed";
            error = n == 0 ? ENOSPC : errno;
        }
    }
    // Flushed before the rename, so a crash leaves the old file or the whole new one.
    if (step == nullptr && ::fsync(fd) != 0) {
        step = "flushing it to the disk failed";
        error = errno;
    }
    if (::close(fd) != 0 && step == nullptr) {
        step = "closing it failed";
        error = errno;
    }
    if (step != nullptr) {
        ::unlink(path.c_str());
        fail(shown, step, error);
    }
}

/// Flushes a folder's entries, so a rename in it survives a power cut.
void sync_folder(const fs::path& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    const bool synced = fd >= 0 && ::fsync(fd) == 0;
    const int error = errno;
    if (fd >= 0) {
        ::close(fd);
    }
    if (!synced) {
        fail(dir, "flushing the folder's entries to the disk failed", error);
    }
}

} // namespace

void check_file_writable(const fs::path& file) {
    std::error_code ec;
    if (fs::is_directory(file, ec)) {
        fail(file, "it is a folder");
    }
    const fs::path probe = temp_beside(file);
    write_whole(probe, file, {});
    fs::remove(probe, ec);
}

void prepare_output_dir(const fs::path& dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) {
        fail(dir, "cannot create the folder: " + ec.message());
    }
    if (!fs::is_directory(dir, ec)) {
        fail(dir, "not a folder");
    }
    check_file_writable(dir / ".snow-probe");
}

void write_file(const fs::path& file, std::span<const std::byte> bytes) {
    StagedFiles out;
    out.stage(file, bytes);
    out.commit();
}

StagedFiles::~StagedFiles() {
    for (const Staged& s : staged_) {
        std::error_code ignored;
        fs::remove(s.temp, ignored);
    }
}

void StagedFiles::stage(const fs::path& file, std::span<const std::byte> bytes) {
    const fs::path temp = temp_beside(file);
    write_whole(temp, file, bytes);
    staged_.push_back({temp, file});
}

void StagedFiles::commit() {
    std::vector<fs::path> folders;
    for (const Staged& s : staged_) {
        std::error_code ec;
        fs::rename(s.temp, s.final, ec);
        if (ec) {
            fail(s.final, "renaming its temporary file into place failed: " + ec.message());
        }
        const fs::path folder = s.final.has_parent_path() ? s.final.parent_path() : ".";
        if (std::find(folders.begin(), folders.end(), folder) == folders.end()) {
            folders.push_back(folder);
        }
    }
    staged_.clear();
    for (const fs::path& folder : folders) {
        sync_folder(folder);
    }
}

} // namespace snow
