// POV-Ray's own example scenes (Debian package povray-examples), which nobody
// here wrote: `asos parse` on each must finish within 5 s without crashing,
// and either parse or name the first unsupported feature with its location.
// The directory must exist (scripts/test.sh installs the package): a missing
// directory fails the test rather than passing it silently.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;

namespace {

const fs::path kExamples = "/usr/share/doc/povray/examples";
const fs::path kIncludes = "/usr/share/povray-3.7/include";
constexpr auto kLimit = std::chrono::seconds(5);

struct Outcome {
    bool finished = false;  // within the limit
    int exitCode = -1;      // -1: killed by a signal
    int signal = 0;
    std::string firstLine;  // of stderr
};

// Runs `asos parse FILE -L <its folder> -L <POV-Ray's includes>`, its stdout
// thrown away and its stderr kept in the build tree.
Outcome runParse(const fs::path& scene, const fs::path& errFile) {
    Outcome outcome;
    const pid_t pid = fork();
    if (pid < 0) return outcome;
    if (pid == 0) {
        const int devNull = open("/dev/null", O_WRONLY);
        const int err = open(errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (devNull < 0 || err < 0) _exit(126);
        dup2(devNull, STDOUT_FILENO);
        dup2(err, STDERR_FILENO);
        const std::string folder = scene.parent_path().string();
        execl(ASOS_EXE, ASOS_EXE, "parse", scene.c_str(), "-L", folder.c_str(), "-L", kIncludes.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    const auto deadline = std::chrono::steady_clock::now() + kLimit;
    int status = 0;
    while (true) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) {
            outcome.finished = true;
            break;
        }
        if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (WIFEXITED(status)) outcome.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
    std::ifstream err(errFile);
    std::string line;
    // #debug and warnings may come first: the first error is what counts.
    while (std::getline(err, line))
        if (line.find(": error: ") != std::string::npos) break;
    outcome.firstLine = line;
    return outcome;
}

}  // namespace

TEST_CASE("POV-Ray's example scenes parse or name what is not supported", "[lang][povray]") {
    REQUIRE(fs::is_directory(kExamples));  // install povray-examples (scripts/test.sh does)
    REQUIRE(fs::is_directory(kIncludes));
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::recursive_directory_iterator(kExamples))
        if (entry.is_regular_file() && entry.path().extension() == ".pov") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    REQUIRE(scenes.size() > 300);

    const fs::path errDir = fs::path(ASOS_BINARY_DIR) / "povray-examples";
    fs::create_directories(errDir);
    // "file:line:col: error: 'word' is not supported by asos" (or a more
    // specific "… not supported by asos …").
    const std::regex unsupported(R"(^(.+):(\d+):(\d+): error: (('[^']+')|.+) (is|are) not supported by asos.*$)");
    int parsed = 0;
    std::map<std::string, int> firstUnsupported;
    for (const auto& scene : scenes) {
        const std::string name = fs::relative(scene, kExamples).string();
        INFO("scene " << scene.string());
        const Outcome o = runParse(scene, errDir / (fs::path(name).filename().string() + ".err"));
        CHECK(o.finished);
        CHECK(o.signal == 0);
        if (o.exitCode == 0) {
            ++parsed;
            continue;
        }
        INFO("first error: " << o.firstLine);
        CHECK(o.exitCode == 1);
        std::smatch m;
        const bool named = std::regex_match(o.firstLine, m, unsupported);
        CHECK(named);
        if (named) {
            CHECK(fs::exists(m[1].str()));
            ++firstUnsupported[m[5].matched ? m[5].str() : m[4].str()];
        }
    }
    std::ostringstream summary;
    summary << parsed << " of " << scenes.size() << " POV-Ray examples parse fully; first unsupported feature of "
            << "the others:";
    std::vector<std::pair<int, std::string>> ranked;
    for (const auto& [feature, count] : firstUnsupported) ranked.emplace_back(count, feature);
    std::sort(ranked.rbegin(), ranked.rend());
    for (const auto& [count, feature] : ranked) summary << "\n  " << count << "  " << feature;
    WARN(summary.str());
    std::ofstream(errDir / "summary.txt") << summary.str() << '\n';
}
