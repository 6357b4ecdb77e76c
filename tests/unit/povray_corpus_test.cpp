// The corpus: POV-Ray's own example scenes (Debian's povray-examples, 396
// scenes that nobody here wrote). Each is parsed, with POV-Ray's include
// folders found as `asos parse` finds them, and each that parses is rendered
// at 40 x 30 (ASOS, one thread); each runs in a child process with a time
// limit. Every scene must finish without crashing; one that does not parse
// must stop at a located error. The outcome of every scene ("renders", or the
// first error's feature: 'color_map', '#fopen', …) is compared with the
// golden table tests/golden/corpus/first_blockers.tsv, so that what a change
// moves is visible (ASOS_UPDATE_GOLDENS=1 rewrites it, docs/goldens.md); the
// counts and the most common first blockers are printed and kept in
// build/corpus/summary.txt. The folder must exist (scripts/setup.sh installs
// povray-examples): a missing corpus fails the test rather than passing it.
#include <catch2/catch.hpp>

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

#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "goldens.hpp"

namespace fs = std::filesystem;
using namespace asos;

namespace {

const fs::path kCorpus = "/usr/share/povray-3.7/scenes";
const fs::path kGolden = fs::path(ASOS_SOURCE_DIR) / "tests" / "golden" / "corpus" / "first_blockers.tsv";
// A guard against hangs, not a speed goal: the slowest scenes (sundial, the
// quartic helix) take about 25 s of one core at 40 x 30, and CI runs two
// tests at once on two cores.
constexpr auto kLimit = std::chrono::seconds(90);

// What happened to one scene: "renders", "parses; the render failed: …", or
// the first error's feature (a crash or a time-out is said as such).
struct Outcome {
    std::string summary;
    std::string firstError;  // as printed, with its location
    bool located = true;     // the first error names a file, line and column
};

// The feature a first error stops at: the quoted word of "'X' is not
// supported by asos", else the message, with the corpus's folder (as given,
// and where its links lead) left out.
std::string featureOf(std::string message) {
    static const std::regex unsupported(R"(^'([^']+)' is not supported by asos.*$)");
    std::smatch m;
    if (std::regex_match(message, m, unsupported)) return "'" + m[1].str() + "'";
    for (const fs::path& root : {kCorpus, fs::weakly_canonical(kCorpus)}) {
        const std::string prefix = root.string() + "/";
        for (std::size_t at; (at = message.find(prefix)) != std::string::npos;) message.erase(at, prefix.size());
        for (std::size_t at; (at = message.find(root.string())) != std::string::npos;)
            message = message.substr(0, at) + "." + message.substr(at + root.string().size());
    }
    return message;
}

// In the child: parse, render, and say what happened on `fd` as one line.
// The files a scene writes (#fopen … write) go to `writes`, a temporary folder.
[[noreturn]] void runScene(const fs::path& scene, const fs::path& writes, int fd) {
    std::string result;
    lang::InterpreterOptions options;
    options.libraryPaths = lang::povrayLibraryPaths();
    options.writeFolder = writes;
    Diagnostics diagnostics;
    auto description = lang::interpretFile(scene, options, diagnostics);
    auto firstError = [&] {
        for (const Diagnostic& d : diagnostics.all())
            if (d.severity == Severity::Error) return d;
        return Diagnostic{};
    };
    if (!description) {
        const Diagnostic e = firstError();
        result = "E" + formatDiagnostic(e).substr(0, formatDiagnostic(e).find('\n'));
    } else {
        diagnostics.clear();
        RenderSettings settings;
        settings.width = 40;
        settings.height = 30;
        settings.threads = 1;
        try {
            result = render(*description, settings, diagnostics) ? "R" : "P" + firstError().message;
        } catch (const std::exception& e) {
            result = std::string("P") + e.what();
        }
    }
    const ssize_t written = write(fd, result.data(), result.size());
    _exit(written == static_cast<ssize_t>(result.size()) ? 0 : 1);
}

Outcome runInChild(const fs::path& scene, const fs::path& writes) {
    int fds[2];
    if (pipe(fds) != 0) return {"the test could not make a pipe", {}, false};
    const pid_t pid = fork();
    if (pid < 0) return {"the test could not fork", {}, false};
    if (pid == 0) {
        close(fds[0]);
        runScene(scene, writes, fds[1]);
    }
    close(fds[1]);
    const auto deadline = std::chrono::steady_clock::now() + kLimit;
    int status = 0;
    bool finished = false;
    while (!finished) {
        const pid_t done = waitpid(pid, &status, WNOHANG);
        if (done == pid) {
            finished = true;
        } else if (std::chrono::steady_clock::now() > deadline) {
            kill(pid, SIGKILL);
            waitpid(pid, &status, 0);
            break;
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    }
    std::string text;
    char buffer[4096];
    for (ssize_t n; (n = read(fds[0], buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<std::size_t>(n));
    close(fds[0]);
    if (!finished) return {"timed out after " + std::to_string(kLimit.count()) + " s", {}, false};
    if (WIFSIGNALED(status)) return {"crashed (signal " + std::to_string(WTERMSIG(status)) + ")", {}, false};
    if (text.empty()) return {"said nothing (exit status " + std::to_string(WEXITSTATUS(status)) + ")", {}, false};
    if (text[0] == 'R') return {"renders", {}, true};
    if (text[0] == 'P') return {"parses; the render failed: " + featureOf(text.substr(1)), {}, true};
    // "file:line:col: error: message"
    static const std::regex located(R"(^(.+):(\d+):(\d+): error: (.*)$)");
    std::smatch m;
    const std::string line = text.substr(1);
    if (!std::regex_match(line, m, located)) return {featureOf(line), line, false};
    return {featureOf(m[4].str()), line, fs::exists(m[1].str())};
}

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("POV-Ray's example scenes: how many parse and render, and what stops the others", "[corpus][povray][golden]") {
    REQUIRE(fs::is_directory(kCorpus));  // install povray-examples (scripts/setup.sh does)
    std::vector<fs::path> scenes;
    for (const auto& entry : fs::recursive_directory_iterator(kCorpus))
        if (entry.is_regular_file() && entry.path().extension() == ".pov") scenes.push_back(entry.path());
    std::sort(scenes.begin(), scenes.end());
    REQUIRE(scenes.size() > 300);

    std::string table = "# scene\toutcome (renders, parses; the render failed: …, or the first error's feature)\n";
    int parsed = 0;
    int rendered = 0;
    std::map<std::string, int> blockers;
    // The scenes' written files (html_gen.inc's pages, fileio.pov's data):
    // a temporary folder, removed at the end.
    const fs::path writes = fs::temp_directory_path() / ("asos-corpus-writes-" + std::to_string(getpid()));
    fs::create_directories(writes);
    for (const auto& scene : scenes) {
        const std::string name = fs::relative(scene, kCorpus).string();
        const Outcome o = runInChild(scene, writes);
        INFO("scene " << scene.string() << "\nfirst error: " << o.firstError);
        CHECK(o.located);
        table += name + '\t' + o.summary + '\n';
        if (o.summary == "renders") {
            ++parsed;
            ++rendered;
        } else if (o.summary.rfind("parses", 0) == 0) {
            ++parsed;
        } else {
            ++blockers[o.summary];
        }
    }

    fs::remove_all(writes);

    std::ostringstream summary;
    summary << parsed << " of " << scenes.size() << " POV-Ray examples parse, " << rendered
            << " render (40 x 30); the first blockers of the others:";
    std::vector<std::pair<int, std::string>> ranked;
    for (const auto& [feature, count] : blockers) ranked.emplace_back(count, feature);
    std::sort(ranked.begin(), ranked.end(), [](const auto& a, const auto& b) {
        return a.first != b.first ? a.first > b.first : a.second < b.second;
    });
    for (const auto& [count, feature] : ranked) summary << "\n  " << count << "  " << feature;
    WARN(summary.str());
    const fs::path out = fs::path(ASOS_BINARY_DIR) / "corpus";
    fs::create_directories(out);
    std::ofstream(out / "summary.txt") << summary.str() << '\n';

    if (test::updatingGoldens()) {
        fs::create_directories(kGolden.parent_path());
        std::ofstream(kGolden, std::ios::binary) << table;
        WARN("rewrote " << fs::relative(kGolden, ASOS_SOURCE_DIR).string());
    }
    const fs::path got = test::goldenOutput(kGolden);
    if (readText(kGolden) == table) {
        fs::remove(got);
    } else {
        std::ofstream(got, std::ios::binary) << table;
        FAIL_CHECK("the outcomes differ from " << fs::relative(kGolden, ASOS_SOURCE_DIR).string() << "; got "
                                               << got.string() << " (diff them; if the change is right, run "
                                               << "scripts/update-goldens.sh)");
    }
}
