// Faults while `asos render` writes or renders, through the built program: a
// full disk (a file size limit, always; a full tmpfs where this process may
// mount one), a read-only folder, SIGINT and SIGKILL during the render and
// during the write. After each the old output is intact (byte for byte), no
// temporary file is left, and the exit code says what happened
// (docs/cli.md, "Exit codes" and "Half-failed runs"). Cases that need
// mount(2) (root with CAP_SYS_ADMIN) report a WARN and return where it fails.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "run_asos.hpp"

namespace fs = std::filesystem;

namespace {

fs::path scratchDir() {
    return asos::test::testCaseDir("cli_faults", Catch::getResultCapture().getCurrentTestName());
}

// A scene that renders in well under a second at 64 x 48, and for seconds at
// the sizes the signal tests use.
void writeScene(const fs::path& file) {
    std::ofstream(file) << "#version 3.7;\nglobal_settings { assumed_gamma 1.0 }\n"
                           "camera { location <0, 2, -6> look_at <0, 0.5, 0> }\n"
                           "light_source { <-4, 8, -5>, 1 }\n"
                           "plane { y, 0 pigment { checker color rgb 1 color rgb 0.2 } }\n"
                           "#for (I, 0, 99)\n"
                           "  sphere { <mod(I, 10) - 4.5, 0.3, div(I, 10) - 2>, 0.3 pigment { color rgb <I / 99, 0.5, 0.2> } }\n"
                           "#end\n";
}

// An old output, to be found intact.
std::string plantOld(const fs::path& file) {
    std::string old = "old contents of " + file.filename().string() + "\n";
    old.resize(4000, '#');
    std::ofstream(file, std::ios::binary) << old;
    return old;
}

struct Child {
    pid_t pid = -1;
};

// Starts asos in `dir` without waiting; stdout and stderr go to files there.
Child spawnAsos(const fs::path& dir, std::vector<std::string> args) {
    const fs::path err = dir / ("stderr-" + std::to_string(getpid()) + "-spawn.txt");
    const pid_t pid = fork();
    if (pid == 0) {
        const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (e < 0 || chdir(dir.c_str()) != 0) _exit(126);
        dup2(e, STDOUT_FILENO);
        dup2(e, STDERR_FILENO);
        std::vector<char*> argv{const_cast<char*>(ASOS_EXE)};
        for (auto& a : args) argv.push_back(a.data());
        argv.push_back(nullptr);
        execv(ASOS_EXE, argv.data());
        _exit(127);
    }
    return {pid};
}

int waitStatus(const Child& c) {
    int status = 0;
    waitpid(c.pid, &status, 0);
    return status;
}

// Whether the process has a file open in `dir`: the staged output (a named
// temporary file, or an unnamed O_TMPFILE one, "dir/#123 (deleted)").
bool writesInto(pid_t pid, const fs::path& dir) {
    std::error_code ec;
    const std::string prefix = fs::canonical(dir).string() + "/";
    for (const auto& fd : fs::directory_iterator("/proc/" + std::to_string(pid) + "/fd", ec)) {
        const fs::path target = fs::read_symlink(fd.path(), ec);
        const std::string t = target.string();
        if (!ec && t.starts_with(prefix) && (t.ends_with(" (deleted)") || t.find(".tmp-") != std::string::npos))
            return true;
    }
    return false;
}

}  // namespace

TEST_CASE("a write that fails part way (a file size limit) leaves the old files and exits 3", "[cli][faults]") {
    const fs::path dir = scratchDir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    writeScene(dir / "scene.pov");
    // ulimit -f: every write past 3000 bytes fails (EFBIG), as on a full disk.
    auto limited = [] {
        const rlimit limit{3000, 3000};
        setrlimit(RLIMIT_FSIZE, &limit);
    };
    for (const char* name : {"out.png", "out.jpg", "out.exr", "out.pfm", "out.tif"}) {
        const std::string old = plantOld(dir / name);
        const std::set<std::string> before = asos::test::filesIn(dir);
        const asos::test::ProgramResult r = asos::test::runProgram(
            ASOS_EXE, dir, {"render", "scene.pov", "-o", name, "-W", "96", "-H", "72", "--quiet"}, limited);
        INFO(name << ": " << r.err);
        CHECK(r.exitCode == 3);
        // The formats asos writes the bytes of itself give the system's
        // reason; TIFF, written by libtiff itself, gives libtiff's.
        if (std::string(name) != "out.tif")
            CHECK(r.err == "asos render: error: cannot write '" + std::string(name) + "': File too large\n");
        else
            CHECK(r.err.starts_with("asos render: error: cannot write 'out.tif': TIFFWriteScanline failed"));
        CHECK(asos::test::slurp(dir / name) == old);
        CHECK(asos::test::filesIn(dir) == before);
    }

    // Half-failed: the image fits, the statistics do not: neither is put in place.
    const std::string oldImage = plantOld(dir / "small.png");
    const std::string oldStats = plantOld(dir / "stats.json");
    const std::set<std::string> before = asos::test::filesIn(dir);
    auto tiny = [] {
        const rlimit limit{400, 400};
        setrlimit(RLIMIT_FSIZE, &limit);
    };
    const asos::test::ProgramResult r = asos::test::runProgram(
        ASOS_EXE, dir,
        {"render", "scene.pov", "-o", "small.png", "-W", "4", "-H", "3", "--stats-json", "stats.json", "--quiet"},
        tiny);
    INFO(r.err);
    CHECK(r.exitCode == 3);
    CHECK(r.err == "asos render: error: cannot write 'stats.json': File too large\n");
    CHECK(asos::test::slurp(dir / "small.png") == oldImage);
    CHECK(asos::test::slurp(dir / "stats.json") == oldStats);
    CHECK(asos::test::filesIn(dir) == before);

    // Likewise the samples AOV (an EXR of 433 bytes) beside an image that fits.
    const std::string oldAov = plantOld(dir / "aov.exr");
    const std::set<std::string> beforeAov = asos::test::filesIn(dir);
    const asos::test::ProgramResult aov = asos::test::runProgram(
        ASOS_EXE, dir,
        {"render", "scene.pov", "-o", "small.png", "-W", "4", "-H", "3", "--aov", "samples=aov.exr", "--quiet"},
        tiny);
    INFO(aov.err);
    CHECK(aov.exitCode == 3);
    CHECK(aov.err == "asos render: error: cannot write 'aov.exr': File too large\n");
    CHECK(asos::test::slurp(dir / "small.png") == oldImage);
    CHECK(asos::test::slurp(dir / "aov.exr") == oldAov);
    CHECK(asos::test::filesIn(dir) == beforeAov);

    // Without the limit the same run writes both.
    const asos::test::ProgramResult ok = asos::test::runAsos(
        dir, {"render", "scene.pov", "-o", "small.png", "-W", "4", "-H", "3", "--stats-json", "stats.json", "--quiet"});
    CHECK(ok.exitCode == 0);
    CHECK(asos::test::slurp(dir / "small.png") != oldImage);
    CHECK(asos::test::slurp(dir / "stats.json").starts_with("{"));
}

TEST_CASE("a full disk (a full tmpfs) leaves the old image and exits 3", "[cli][faults]") {
    const fs::path dir = scratchDir();
    const fs::path disk = dir / "disk";  // the full one; the run's own captures stay outside
    fs::create_directories(disk);
    umount2(disk.c_str(), MNT_DETACH);  // one an interrupted run left
    if (mount("asos-test", disk.c_str(), "tmpfs", 0, "size=256k") != 0) {
        WARN("skipped: cannot mount a tmpfs here (" << std::strerror(errno)
                                                    << "); the file size limit test covers a failing write");
        return;
    }
    struct Unmount {
        fs::path dir;
        ~Unmount() { umount2(dir.c_str(), MNT_DETACH); }
    } unmount{disk};
    writeScene(dir / "scene.pov");
    for (const char* name : {"out.png", "out.jpg", "out.exr"}) {
        const std::string old = plantOld(disk / name);
        {
            // Fill the disk.
            std::ofstream filler(disk / "filler", std::ios::binary | std::ios::app);
            const std::string block(4096, 'x');
            while (filler.write(block.data(), block.size()) && filler.flush()) {
            }
        }
        const std::set<std::string> before = asos::test::filesIn(disk);
        const std::string output = "disk/" + std::string(name);
        const asos::test::ProgramResult r =
            asos::test::runAsos(dir, {"render", "scene.pov", "-o", output, "-W", "96", "-H", "72", "--quiet"});
        INFO(name << ": " << r.err);
        CHECK(r.exitCode == 3);
        CHECK(r.err == "asos render: error: cannot write '" + output + "': No space left on device\n");
        CHECK(asos::test::slurp(disk / name) == old);
        CHECK(asos::test::filesIn(disk) == before);
        fs::remove(disk / "filler");
    }
}

TEST_CASE("a read-only folder is refused before rendering", "[cli][faults]") {
    const fs::path dir = scratchDir();
    const fs::path ro = dir / "ro";
    fs::create_directories(ro);
    umount2(ro.c_str(), MNT_DETACH);
    writeScene(dir / "scene.pov");
    const std::string old = plantOld(ro / "out.png");
    // Root writes through any mode bits: a read-only bind mount then.
    if (geteuid() == 0) {
        if (mount(ro.c_str(), ro.c_str(), nullptr, MS_BIND, nullptr) != 0 ||
            mount(nullptr, ro.c_str(), nullptr, MS_BIND | MS_REMOUNT | MS_RDONLY, nullptr) != 0) {
            umount2(ro.c_str(), MNT_DETACH);
            WARN("skipped: root here cannot make a read-only bind mount (" << std::strerror(errno) << ")");
            return;
        }
    } else {
        fs::permissions(ro, fs::perms::owner_read | fs::perms::owner_exec);
    }
    struct Restore {
        fs::path ro;
        ~Restore() {
            umount2(ro.c_str(), MNT_DETACH);
            std::error_code ec;
            fs::permissions(ro, fs::perms::owner_all, ec);
        }
    } restore{ro};
    const std::string reason = geteuid() == 0 ? "Read-only file system" : "Permission denied";
    const asos::test::ProgramResult r =
        asos::test::runAsos(dir, {"render", "scene.pov", "-o", "ro/out.png", "-W", "32", "-H", "24", "--quiet"});
    CHECK(r.exitCode == 2);
    CHECK(r.err == "asos render: error: -o: cannot write 'ro/out.png': folder 'ro': " + reason +
                       "\nRun with --help for more information.\n");
    CHECK(asos::test::slurp(ro / "out.png") == old);
    CHECK(asos::test::filesIn(ro) == std::set<std::string>{"out.png"});
}

TEST_CASE("SIGINT or SIGKILL during the render leaves the old image", "[cli][faults]") {
    const fs::path dir = scratchDir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    writeScene(dir / "scene.pov");
    for (const int signal : {SIGINT, SIGKILL}) {
        const std::string old = plantOld(dir / "out.png");
        const std::set<std::string> before = asos::test::filesIn(dir);
        // Seconds of work: the signal comes during the render.
        const Child c = spawnAsos(dir, {"render", "scene.pov", "-o", "out.png", "-W", "2000", "-H", "1500",
                                        "--threads", "1", "--quiet"});
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        const auto sent = std::chrono::steady_clock::now();
        kill(c.pid, signal);
        const int status = waitStatus(c);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
        INFO("signal " << signal);
        CHECK(WIFSIGNALED(status));
        CHECK(WTERMSIG(status) == signal);  // a shell reports 128 + the signal: 130 for SIGINT
        CHECK(seconds < 2.0);               // promptly
        CHECK(asos::test::slurp(dir / "out.png") == old);
        std::set<std::string> after = asos::test::filesIn(dir);
        CHECK(after == before);
    }
}

TEST_CASE("SIGINT or SIGKILL during the write leaves the old image or the whole new one", "[cli][faults]") {
    const fs::path dir = scratchDir();
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    writeScene(dir / "scene.pov");
    // A large, quickly rendered float image: tens of megabytes to write.
    const std::vector<std::string> args{"render", "scene.pov", "-o", "out.pfm", "-W", "3000", "-H", "2000",
                                        "--method", "single", "--quiet"};
    int landed = 0;
    for (const int signal : {SIGINT, SIGKILL}) {
        for (int attempt = 0; attempt < 3; ++attempt) {
            const std::string old = plantOld(dir / "out.pfm");
            const std::set<std::string> before = asos::test::filesIn(dir);
            const Child c = spawnAsos(dir, args);
            // Wait until it has the output open in the folder, then signal it.
            bool during = false;
            int status = 0;
            bool done = false;
            while (!done) {
                if (writesInto(c.pid, dir)) {
                    kill(c.pid, signal);
                    during = true;
                    break;
                }
                done = waitpid(c.pid, &status, WNOHANG) != 0;
            }
            if (!done) waitpid(c.pid, &status, 0);
            const std::string now = asos::test::slurp(dir / "out.pfm");
            INFO("signal " << signal << ", attempt " << attempt);
            CHECK(asos::test::filesIn(dir) == before);  // no temporary file
            if (!during) continue;          // it finished first: try again
            ++landed;
            if (WIFSIGNALED(status)) {
                CHECK(WTERMSIG(status) == signal);
                CHECK(now == old);
            } else {
                // The signal came as the files were put in place: they are whole.
                CHECK(WEXITSTATUS(status) == 0);
                CHECK(now.starts_with("PF\n3000 2000\n-1.0\n"));
                CHECK(now.size() == 17 + std::size_t(3000) * 2000 * 12);
            }
            break;
        }
    }
    CHECK(landed == 2);
}

TEST_CASE("memory running out is an error with exit 1, not an abort", "[cli][faults]") {
    const fs::path dir = scratchDir();
    writeScene(dir / "scene.pov");
    // 2 GiB of address space; the images of a 20000 x 20000 render need 8.
    auto limited = [] {
        const rlimit limit{rlim_t(2) << 30, rlim_t(2) << 30};
        setrlimit(RLIMIT_AS, &limit);
    };
    const asos::test::ProgramResult r = asos::test::runProgram(
        ASOS_EXE, dir,
        {"render", "scene.pov", "-o", "big.png", "-W", "20000", "-H", "20000", "--max-memory", "1T", "--quiet"},
        limited);
    CHECK(r.exitCode == 1);
    CHECK(r.err == "asos: error: out of memory (the scene or the image needs more than there is)\n");
    CHECK_FALSE(fs::exists(dir / "big.png"));
}
