// Saves that survive a crash (issue 33, docs/reliability.md). snow_run saves
// a byte snapshot and exports a .glb over older ones and is killed with
// SIGKILL at random moments: each path holds the old file whole or the new
// one whole, never a part, and nothing else is left but its own temporary
// files. A folder it may not write and a full disk (a file size limit) are
// one error naming the file and the step that failed, exit status 2, and the
// old file as it was.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <grp.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// The run whose files are killed: the park's 480 × 480-cell cover makes a
/// snapshot of 4.7 MB, so writing it takes a while; the run takes 0.1 s to
/// load the scene and as long again for its ticks.
const std::vector<std::string> run_args = {"--scene", std::string(SNOW_SOURCE_DIR) +
                                                          "/assets/scenes/park.gltf"};
constexpr const char* old_ticks = "10";
constexpr const char* new_ticks = "30";

std::string bytes_of(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// A scratch folder in /tmp (reachable by any user, for the read-only case).
class Scratch {
  public:
    Scratch() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("snow_saves_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~Scratch() {
        std::error_code ec;
        fs::permissions(path_ / "ro", fs::perms::owner_all, ec);
        fs::remove_all(path_, ec);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    [[nodiscard]] const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

/// What the child changes about itself before it becomes snow_run.
struct ChildLimits {
    rlim_t file_size = RLIM_INFINITY; ///< RLIMIT_FSIZE: a disk that fills
    bool as_nobody = false;           ///< drop root, so folder permissions apply
};

/// Starts snow_run with `args` (stdout dropped, stderr into `errors`).
pid_t start_snow_run(const std::vector<std::string>& args, const fs::path& errors,
                     const ChildLimits& limits = {}) {
    const std::string exe = std::string(SNOW_BINARY_DIR) + "/game/snow_run";
    std::vector<std::string> all = {exe};
    all.insert(all.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : all) {
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) { // only async-signal-safe calls from here on
        const int out = ::open("/dev/null", O_WRONLY);
        const int err = ::open(errors.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        ::dup2(out, STDOUT_FILENO);
        ::dup2(err, STDERR_FILENO);
        const rlimit size{limits.file_size, limits.file_size};
        ::setrlimit(RLIMIT_FSIZE, &size);
        if (limits.as_nobody && ::geteuid() == 0) {
            const gid_t nogroup = 65534;
            if (::setgroups(0, nullptr) != 0 || ::setgid(nogroup) != 0 || ::setuid(65534) != 0) {
                ::_exit(126);
            }
        }
        ::execv(exe.c_str(), argv.data());
        ::_exit(127);
    }
    return pid;
}

/// Waits for `pid`; its exit status, or -signal when a signal ended it.
int wait_for(pid_t pid) {
    int status = 0;
    ::waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

/// Runs snow_run to its end; its exit status and what it said on stderr.
std::pair<int, std::string> run_snow_run(const std::vector<std::string>& args,
                                         const fs::path& scratch, const ChildLimits& limits = {}) {
    const fs::path errors = scratch / "stderr.txt";
    const int status = wait_for(start_snow_run(args, errors, limits));
    std::string said = bytes_of(errors);
    fs::remove(errors);
    return {status, said};
}

std::vector<std::string> with(std::vector<std::string> args, const std::vector<std::string>& more) {
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

/// Both files as a whole run of `ticks` writes them.
struct Saved {
    std::string snap, glb;
    double seconds = 0.0; ///< how long the run took
};

Saved whole_run(const char* ticks, const fs::path& dir) {
    const fs::path snap = dir / "ref.snap", glb = dir / "ref.glb";
    const auto t0 = Clock::now();
    const auto [status, said] = run_snow_run(
        with(run_args, {"--ticks", ticks, "--save-state", snap.string(), "--export", glb.string()}),
        dir);
    Saved s{bytes_of(snap), bytes_of(glb),
            std::chrono::duration<double>(Clock::now() - t0).count()};
    EXPECT_EQ(status, 0) << said;
    fs::remove(snap);
    fs::remove(glb);
    return s;
}

void put(const fs::path& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
}

/// Which version a target holds: "old", "new" or "neither" (a torn file).
std::string version(const fs::path& p, const std::string& old_bytes, const std::string& new_bytes) {
    const std::string b = bytes_of(p);
    return b == old_bytes ? "old" : b == new_bytes ? "new" : "neither";
}

int env_or(const char* name, int fallback) {
    const char* v = std::getenv(name);
    return v != nullptr ? std::atoi(v) : fallback;
}

/// Waits until snow_run `pid` has started writing one of its temporary files
/// (not the empty probes of its start-up check), or has ended.
void wait_for_writing(pid_t pid, const fs::path& dir) {
    const std::string suffix = ".tmp-" + std::to_string(pid);
    const fs::path temps[] = {dir / ("snow.glb" + suffix), dir / ("state.snap" + suffix)};
    const auto give_up = Clock::now() + std::chrono::minutes(2);
    while (Clock::now() < give_up) {
        for (const fs::path& t : temps) {
            struct stat st {};
            if (::stat(t.c_str(), &st) == 0 && st.st_size > 0) {
                return;
            }
        }
        siginfo_t ended{};
        if (::waitid(P_PID, static_cast<id_t>(pid), &ended, WEXITED | WNOHANG | WNOWAIT) == 0 &&
            ended.si_pid == pid) {
            return;
        }
        std::this_thread::sleep_for(std::chrono::microseconds(100));
    }
}

TEST(CrashSafeSaves, KilledAtRandomMomentsLeavesTheOldOrTheNewFileWhole) {
    Scratch scratch;
    const fs::path dir = scratch.path();
    const Saved old_files = whole_run(old_ticks, dir), new_files = whole_run(new_ticks, dir);
    ASSERT_NE(old_files.snap, new_files.snap);
    ASSERT_NE(old_files.glb, new_files.glb);
    const fs::path snap = dir / "state.snap", glb = dir / "snow.glb";
    const std::vector<std::string> args = with(
        run_args, {"--ticks", new_ticks, "--save-state", snap.string(), "--export", glb.string()});

    // How long the writing lasts on this machine (from the first bytes of a
    // temporary file to the process's end), so the kills aimed at it land
    // inside it on a fast disk as on a slow one.
    const pid_t timed = start_snow_run(args, "/dev/null");
    wait_for_writing(timed, dir);
    const auto writing_began = Clock::now();
    ASSERT_EQ(wait_for(timed), 0);
    const double writing = std::chrono::duration<double>(Clock::now() - writing_began).count();

    const int trials = env_or("SNOW_KILL_TRIALS", 50);
    std::mt19937 rng(33);
    std::uniform_real_distribution<double> anywhere(0.0, new_files.seconds);
    std::uniform_real_distribution<double> while_writing(0.0, writing);
    std::map<std::string, int> outcomes; // "glb snap" versions
    int killed = 0, temps_left = 0, torn_temps = 0;
    for (int trial = 0; trial < trials; ++trial) {
        put(snap, old_files.snap);
        put(glb, old_files.glb);
        const pid_t pid = start_snow_run(args, "/dev/null");
        // Half the kills anywhere in the run, half while it writes its files.
        if (trial % 2 == 0) {
            std::this_thread::sleep_for(std::chrono::duration<double>(anywhere(rng)));
        } else {
            wait_for_writing(pid, dir);
            std::this_thread::sleep_for(std::chrono::duration<double>(while_writing(rng)));
        }
        ::kill(pid, SIGKILL);
        killed += wait_for(pid) == -SIGKILL ? 1 : 0;

        const std::string g = version(glb, old_files.glb, new_files.glb);
        const std::string s = version(snap, old_files.snap, new_files.snap);
        EXPECT_NE(g, "neither") << "trial " << trial << ": a torn .glb";
        EXPECT_NE(s, "neither") << "trial " << trial << ": a torn snapshot";
        EXPECT_FALSE(s == "new" && g == "old") << "trial " << trial << ": the export comes first";
        ++outcomes[g + " " + s];
        // Nothing else but this run's own temporary files.
        const std::string own = ".tmp-" + std::to_string(pid);
        for (const auto& e : fs::directory_iterator(dir)) {
            const std::string name = e.path().filename().string();
            if (name == "state.snap" || name == "snow.glb") {
                continue;
            }
            ASSERT_TRUE(name == "state.snap" + own || name == "snow.glb" + own)
                << "trial " << trial << " left " << name;
            ++temps_left;
            const std::string b = bytes_of(e.path());
            torn_temps += !b.empty() && b != new_files.snap && b != new_files.glb ? 1 : 0;
            fs::remove(e.path());
        }
    }
    std::ostringstream said;
    said << trials << " runs, " << killed << " killed (the rest had ended);";
    for (const auto& [o, n] : outcomes) {
        said << " glb/snapshot " << o << ": " << n << ";";
    }
    said << " temporary files left: " << temps_left << " (" << torn_temps << " partly written)";
    std::printf("%s\n", said.str().c_str());
    RecordProperty("outcomes", said.str());
    if (trials >= 20) {
        EXPECT_GT(temps_left, 0) << "no kill landed before a rename: " << said.str();
    }
}

TEST(CrashSafeSaves, AFullDiskIsOneErrorAndTheOldFileStays) {
    Scratch scratch;
    const fs::path dir = scratch.path();
    const fs::path snap = dir / "state.snap";
    put(snap, "the old snapshot");
    // A file size limit stands in for a full disk: the write fails with
    // EFBIG (its SIGXFSZ is held back) after 64 KiB of the snapshot.
    ChildLimits limits;
    limits.file_size = 64 * 1024;
    const auto [status, said] =
        run_snow_run(with(run_args, {"--ticks", "5", "--save-state", snap.string()}), dir, limits);
    EXPECT_EQ(status, 2) << said;
    EXPECT_EQ(said, "snow_run: --save-state: cannot write '" + snap.string() +
                        "': writing failed: File too large\n");
    EXPECT_EQ(bytes_of(snap), "the old snapshot");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1)
        << "no temporary file left";
}

TEST(CrashSafeSaves, AReadOnlyFolderIsOneErrorBeforeTheRun) {
    Scratch scratch;
    const fs::path ro = scratch.path() / "ro";
    fs::create_directories(ro);
    put(ro / "state.snap", "the old snapshot");
    fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                            fs::perms::group_exec | fs::perms::others_read |
                            fs::perms::others_exec);
    ChildLimits limits;
    limits.as_nobody = true; // root writes anywhere
    for (const std::string flag : {"--save-state", "--export"}) {
        const fs::path file = ro / (flag == "--export" ? "snow.glb" : "state.snap");
        // A run this long would not end within the test: the check comes first.
        const auto [status, said] =
            run_snow_run(with(run_args, {"--ticks", "1000000000000", flag, file.string()}),
                         scratch.path(), limits);
        EXPECT_EQ(status, 2) << said;
        EXPECT_EQ(said, "snow_run: " + flag + ": cannot write '" + file.string() +
                            "': cannot create a file in its folder: Permission denied\n");
    }
    EXPECT_EQ(bytes_of(ro / "state.snap"), "the old snapshot");
    EXPECT_EQ(std::distance(fs::directory_iterator(ro), fs::directory_iterator{}), 1);
}

} // namespace
