// Golden files of the language: the dump of every example and of the focused
// scenes in tests/golden/parse/ (NAME.pov → NAME.dump), and the diagnostics
// of the mistakes and warnings in tests/golden/diag/ and of the bad-scene
// corpus in tests/golden/errors/ (NAME.pov → NAME.err, exact text).
// Goldens are rewritten only by the golden switch (goldens.hpp,
// scripts/update-goldens.sh); a failing comparison leaves what it got in the
// build tree (build/golden-out/tests/golden/...) and the golden alone.
//
// Also here: parse → dump → parse → dump is a fixed point for all of them.
#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "asos/lang/interpreter.hpp"
#include "asos/scene/dump.hpp"
#include "goldens.hpp"

using namespace asos;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = ASOS_SOURCE_DIR;

std::string readText(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// Paths in the text relative to the source tree, so goldens do not depend on
// where the tree lives.
std::string relative(std::string text) {
    const std::string prefix = fs::weakly_canonical(kSource).string() + "/";
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
    return text;
}

std::vector<fs::path> scenesIn(const fs::path& dir) {
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".pov") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<fs::path> parseScenes() {
    auto files = scenesIn(kSource / "examples");
    auto bench = scenesIn(kSource / "examples" / "bench");
    files.insert(files.end(), bench.begin(), bench.end());
    auto focused = scenesIn(kSource / "tests" / "golden" / "parse");
    files.insert(files.end(), focused.begin(), focused.end());
    return files;
}

void compareGolden(const fs::path& golden, const std::string& actual) {
    const std::string name = fs::relative(golden, kSource).string();
    if (test::updatingGoldens()) {
        std::ofstream(golden, std::ios::binary) << actual;
        WARN("rewrote " << name);
    }
    INFO("golden " << name);
    CHECK(fs::exists(golden));
    const fs::path out = test::goldenOutput(golden);
    if (readText(golden) == actual) {
        fs::remove(out);
        return;
    }
    std::ofstream(out, std::ios::binary) << actual;
    FAIL_CHECK("differs from the golden; got " << out.string() << " (diff them; if the change is "
                                              << "right, run scripts/update-goldens.sh)");
}

// Where the scenes' #write files go: a folder of the system's temporary
// folder, never the source or build tree; "<writes>" in goldens.
const fs::path& writesFolder() {
    static const fs::path folder = [] {
        const fs::path f = fs::temp_directory_path() / "asos-lang-golden-writes";
        fs::create_directories(f);
        return f;
    }();
    return folder;
}

lang::InterpreterOptions optionsFor(const fs::path&) {
    lang::InterpreterOptions options;
    options.includePaths = {kSource / "tests" / "golden" / "include"};
    options.writeFolder = writesFolder();
    return options;
}

std::string formatAll(const Diagnostics& diagnostics) {
    std::string out;
    for (const auto& d : diagnostics.all()) out += formatDiagnostic(d);
    out = relative(out);
    const std::string writes = writesFolder().string();
    for (std::size_t at; (at = out.find(writes)) != std::string::npos;) out.replace(at, writes.size(), "<writes>");
    return out;
}

}  // namespace

TEST_CASE("golden dumps of the examples and the focused scenes", "[lang][golden]") {
    const auto files = parseScenes();
    REQUIRE(files.size() >= 20);
    for (const auto& file : files) {
        INFO("scene " << fs::relative(file, kSource).string());
        Diagnostics diagnostics;
        auto scene = lang::interpretFile(file, optionsFor(file), diagnostics);
        INFO(formatAll(diagnostics));
        CHECK(scene);
        if (!scene) continue;
        // An example's dump lies in tests/golden/ at the example's own path.
        fs::path golden = file;
        golden.replace_extension(".dump");
        const fs::path fromSource = fs::relative(golden, kSource);
        if (*fromSource.begin() == "examples") golden = kSource / "tests" / "golden" / fromSource;
        compareGolden(golden, relative(dumpScene(*scene)));
    }
}

namespace {

// A scene named warning_*.pov is read, with warnings only; any other is a
// mistake that stops it.
void checkDiagnostics(const fs::path& folder, const lang::InterpreterOptions& options, std::size_t atLeast) {
    const auto files = scenesIn(folder);
    REQUIRE(files.size() >= atLeast);
    for (const auto& file : files) {
        INFO("scene " << fs::relative(file, kSource).string());
        Diagnostics diagnostics;
        auto scene = lang::interpretFile(file, options, diagnostics);
        if (file.filename().string().starts_with("warning_")) {
            CHECK(scene);
            CHECK_FALSE(diagnostics.hasErrors());
            CHECK_FALSE(diagnostics.all().empty());
        } else {
            CHECK_FALSE(scene);
            CHECK(diagnostics.hasErrors());
        }
        fs::path golden = file;
        golden.replace_extension(".err");
        compareGolden(golden, formatAll(diagnostics));
    }
}

}  // namespace

TEST_CASE("golden diagnostics of mistakes", "[lang][golden]") {
    checkDiagnostics(kSource / "tests" / "golden" / "diag", optionsFor(kSource), 30);
}

// The corpus of bad scenes: a class of mistake or a boundary each (limits,
// nesting, float-to-integer conversions, non-finite values, the newer
// constructs). The limits are lowered so that the scenes that pass them stay
// small and quick; the messages name these values.
TEST_CASE("golden diagnostics of the bad-scene corpus", "[lang][golden]") {
    lang::InterpreterOptions options = optionsFor(kSource);
    options.maxObjects = 50'000;
    options.maxStringLength = 1'000'000;
    options.maxArrayElements = 2'000'000;
    options.maxMemoryMiB = 32;
    options.maxLoopIterations = 1'000'000;
    checkDiagnostics(kSource / "tests" / "golden" / "errors", options, 80);
}

TEST_CASE("parse, dump, parse, dump is a fixed point", "[lang][dump]") {
    DumpOptions noLocations;
    noLocations.locations = false;
    for (const auto& file : parseScenes()) {
        INFO("scene " << fs::relative(file, kSource).string());
        Diagnostics first;
        auto scene = lang::interpretFile(file, optionsFor(file), first);
        CHECK(scene);
        if (!scene) continue;
        const std::string dump1 = dumpScene(*scene);
        Diagnostics second;
        auto again = lang::interpretText(dump1, "dump.pov", {}, second);
        INFO(formatAll(second));
        CHECK(again);
        if (!again) continue;
        const std::string dump2 = dumpScene(*again, noLocations);
        CHECK(dump2 == dumpScene(*scene, noLocations));
        // The records of the second dump point into the first one.
        if (!again->objects.empty()) CHECK(*again->objects.front().loc.file == "dump.pov");
    }
}
