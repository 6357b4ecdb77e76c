// Bad command lines, run through the built `asos` as a user runs it: each case
// of tests/golden/cli/bad_command_lines.txt gives the arguments, the exit code
// and the exact standard error, and writes no file. The format:
//
//   ## what the case shows (any number of comment lines)
//   $ render scene.pov -o out.png --eps 0      arguments, split at spaces; '...' keeps spaces
//   exit 2
//   | asos render: error: ...                  each line of stderr ("|" alone: an empty line)
//
// The cases run in a scratch folder holding scene.pov (a small valid scene),
// folder.png/ and scenes.pov/ (folders), fifo.pov (a FIFO), and nothing else.
// ASOS_UPDATE_GOLDENS=1 rewrites the exit codes and stderr from what the
// build gives (docs/goldens.md).
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "goldens.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;

namespace {

struct Case {
    std::vector<std::string> comments;
    std::string command;  // as written after "$ "
    int exitCode = -1;
    std::string err;
};

std::vector<std::string> splitArguments(const std::string& command) {
    std::vector<std::string> args;
    std::string current;
    bool quoted = false, any = false;
    for (const char c : command) {
        if (c == '\'') {
            quoted = !quoted;
            any = true;
        } else if (c == ' ' && !quoted) {
            if (any) args.push_back(current);
            current.clear();
            any = false;
        } else {
            current += c;
            any = true;
        }
    }
    if (any) args.push_back(current);
    return args;
}

std::vector<Case> readCases(const fs::path& file) {
    std::vector<Case> cases;
    std::ifstream in(file);
    std::string line;
    std::vector<std::string> comments;
    while (std::getline(in, line)) {
        if (line.starts_with("##") || line.empty()) {
            if (line.starts_with("##")) comments.push_back(line);
        } else if (line.starts_with("$ ")) {
            cases.push_back({std::move(comments), line.substr(2), -1, {}});
            comments.clear();
        } else if (line.starts_with("exit ") && !cases.empty()) {
            cases.back().exitCode = std::stoi(line.substr(5));
        } else if (line.starts_with("|") && !cases.empty()) {
            cases.back().err += line.size() > 1 ? line.substr(2) : "";
            cases.back().err += '\n';
        } else {
            FAIL("bad_command_lines.txt: cannot read the line '" << line << "'");
        }
    }
    return cases;
}

std::string writeCases(const std::vector<Case>& cases) {
    std::string out;
    for (const Case& c : cases) {
        if (!out.empty()) out += '\n';
        for (const std::string& comment : c.comments) out += comment + '\n';
        out += "$ " + c.command + '\n';
        out += "exit " + std::to_string(c.exitCode) + '\n';
        std::istringstream lines(c.err);
        std::string line;
        while (std::getline(lines, line)) out += line.empty() ? "|\n" : "| " + line + '\n';
    }
    return out;
}

}  // namespace

TEST_CASE("asos refuses bad command lines with the golden message and exit code", "[cli][golden]") {
    const fs::path golden = fs::path(ASOS_SOURCE_DIR) / "tests/golden/cli/bad_command_lines.txt";
    std::vector<Case> cases = readCases(golden);
    REQUIRE(cases.size() >= 30);

    const fs::path dir = asos::test::testCaseDir("cli_bad", "command-lines");
    fs::remove_all(dir);
    fs::create_directories(dir / "folder.png");
    fs::create_directories(dir / "scenes.pov");
    std::ofstream(dir / "scene.pov") << "camera { location <0, 1, -3> look_at 0 }\n"
                                        "light_source { <2, 4, -3>, 1 }\nsphere { 0, 1 }\n";
    REQUIRE(mkfifo((dir / "fifo.pov").c_str(), 0644) == 0);
    const std::set<std::string> before = asos::test::filesIn(dir);

    const bool update = asos::test::updatingGoldens();
    std::vector<Case> got = cases;
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const asos::test::ProgramResult r = asos::test::runAsos(dir, splitArguments(cases[i].command));
        got[i].exitCode = r.exitCode;
        got[i].err = r.err;
        INFO("$ " << cases[i].command);
        if (!update) {
            CHECK(r.exitCode == cases[i].exitCode);
            CHECK(r.err == cases[i].err);
        }
        CHECK(asos::test::filesIn(dir) == before);  // nothing written, no temporary file left
    }
    const std::string text = writeCases(got);
    const fs::path out = asos::test::goldenOutput(golden);
    if (update) {
        std::ofstream(golden) << text;
    } else if (text != asos::test::slurp(golden)) {
        std::ofstream(out) << text;
        FAIL("what this build gives is in " << out.string());
    } else {
        fs::remove(out);
    }
}
