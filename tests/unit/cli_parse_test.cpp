// `asos parse` as a user runs it: the dump on stdout, diagnostics on stderr
// as file:line:col: error: message, the source line and a caret, exit 1.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "run_asos.hpp"

namespace fs = std::filesystem;

namespace {

using Result = asos::test::ProgramResult;

const fs::path kDir = fs::path(ASOS_BINARY_DIR) / "test-scratch" / "cli";

Result runAsos(std::vector<std::string> args) { return asos::test::runAsos(kDir, std::move(args)); }

fs::path scene(const std::string& name, const std::string& text) {
    fs::create_directories(kDir);
    std::ofstream(kDir / name) << text;
    return kDir / name;
}

}  // namespace

TEST_CASE("asos parse prints the dump and exits 0", "[cli]") {
    scene("good.pov", "#version 3.7; global_settings { assumed_gamma 1 }\nsphere { <0, 1, 0>, 0.5 }\n");
    const Result r = runAsos({"parse", "good.pov"});
    CHECK(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(r.out.rfind("// asos scene description", 0) == 0);
    CHECK(r.out.find("// good.pov:2:1\nsphere {\n  <0, 1, 0>, 0.5\n") != std::string::npos);
}

TEST_CASE("asos parse prints warnings on stderr and still exits 0", "[cli]") {
    scene("old.pov", "sphere { <0, 1, 0>, 0.5 }\n");
    const Result r = runAsos({"parse", "old.pov"});
    CHECK(r.exitCode == 0);
    CHECK(r.err ==
          "old.pov: warning: assumed_gamma not specified, so gamma correction is turned off for this scene "
          "older than POV-Ray 3.7 (no #version, read as 3.62), as POV-Ray does: its colours go to the image "
          "file as they are; set assumed_gamma in global_settings to turn it on\n"
          "old.pov: warning: this scene has no #version directive: like POV-Ray 3.7, asos reads it as a "
          "scene older than 3.7; start it with '#version 3.7;'\n");
    CHECK(r.out.rfind("// asos scene description", 0) == 0);
}

TEST_CASE("asos parse reports errors with the source line and a caret, exit 1", "[cli]") {
    scene("bad.pov", "sphere { 0, 1 }\nsphere { <0, 1, 0>, -2 }\nbox { 0, 1 scale 0 }\n");
    const Result r = runAsos({"parse", "bad.pov"});
    CHECK(r.exitCode == 1);
    CHECK(r.out.empty());
    CHECK(r.err ==
          "bad.pov:2:21: error: the radius of a sphere must be positive, not -2\n"
          "sphere { <0, 1, 0>, -2 }\n"
          "                    ^\n"
          "bad.pov:3:18: error: scale by zero (<0, 0, 0>) flattens everything\n"
          "box { 0, 1 scale 0 }\n"
          "                 ^\n");
}

TEST_CASE("asos parse takes -L, -D and --clock", "[cli]") {
    const fs::path lib = fs::path(ASOS_BINARY_DIR) / "test-scratch" / "cli" / "lib";
    fs::create_directories(lib);
    std::ofstream(lib / "size.inc") << "#declare Size = 2;\n";
    scene("opts.pov", "#include \"size.inc\"\nsphere { Where, Size * Scale + clock }\n");
    const Result r = runAsos({"parse", "opts.pov", "-L", lib.string(), "-D", "Scale=3", "-D", "Where=<1,2,3>",
                           "--clock", "0.5", "--no-locations"});
    INFO(r.err);
    CHECK(r.exitCode == 0);
    CHECK(r.out.find("sphere {\n  <1, 2, 3>, 6.5\n") != std::string::npos);

    const Result bad = runAsos({"parse", "opts.pov", "-D", "sphere=1"});
    CHECK(bad.exitCode == 2);  // a bad command line
    CHECK(bad.err.find("-D wants NAME=VALUE") != std::string::npos);
}

TEST_CASE("asos parse on a missing file fails cleanly", "[cli]") {
    const Result r = runAsos({"parse", "no-such-file.pov"});
    CHECK(r.exitCode == 3);  // a file that cannot be read
    CHECK(r.err == "asos parse: error: cannot read 'no-such-file.pov': No such file or directory\n");
}

TEST_CASE("asos parse echoes at most 200 bytes of a long source line", "[cli]") {
    // One 1 MB line with a mistake in its middle: the echo is a window
    // around the caret, "…" at both cuts, and the caret under the mistake.
    std::string line(500000, ' ');
    line += "sphere { 0, -1 }";
    line += std::string(500000, ' ');
    scene("long.pov", line + "\n");
    const Result r = runAsos({"parse", "long.pov"});
    CHECK(r.exitCode == 1);
    CHECK(r.err.size() < 1000);
    const std::string window = std::string(88, ' ') + "sphere { 0, -1 }" + std::string(96, ' ');
    CHECK_THAT(r.err, Catch::Contains("\n\u2026" + window + "\u2026\n" + std::string(101, ' ') + "^\n"));
}

TEST_CASE("asos parse clips a long word quoted in a message", "[cli]") {
    // A 1 MB undeclared identifier: the message quotes its first and last
    // 100 bytes around "…", not the whole word (issue 25).
    const std::string word = "b" + std::string(1000000, 'a') + "c";
    scene("long_word.pov", "#declare X = " + word + ";\n");
    const Result r = runAsos({"parse", "long_word.pov"});
    CHECK(r.exitCode == 1);
    CHECK(r.err.size() < 1000);
    CHECK_THAT(r.err, Catch::Contains("error: 'b" + std::string(98, 'a') + "\u2026" + std::string(98, 'a') +
                                      "c' is not declared\n"));
}

TEST_CASE("asos parse sets clock_on with --clock and finds POV-Ray's includes by itself", "[cli]") {
    scene("clock_on.pov", "sphere { 0, 1 + clock_on }\n");
    const Result off = runAsos({"parse", "clock_on.pov", "--no-locations"});
    CHECK(off.out.find("sphere {\n  <0, 0, 0>, 1\n") != std::string::npos);
    const Result on = runAsos({"parse", "clock_on.pov", "--clock", "0", "--no-locations"});
    CHECK(on.out.find("sphere {\n  <0, 0, 0>, 2\n") != std::string::npos);

    // POV-Ray's colors.inc, with no -L (scripts/setup.sh installs povray).
    REQUIRE(fs::is_regular_file("/usr/share/povray-3.7/include/colors.inc"));
    scene("colors.pov", "#include \"colors.inc\"\nsphere { 0, 1 pigment { CHSV2RGB(<120, 1, 1>) } }\n");
    const Result colors = runAsos({"parse", "colors.pov", "--no-locations"});
    INFO(colors.err);
    CHECK(colors.exitCode == 0);
    CHECK(colors.out.find("pigment { color rgbft <0, 1, 0, 0, 0> }") != std::string::npos);
}

TEST_CASE("asos parse writes a scene's files into --write-folder", "[cli][files]") {
    const fs::path writes = fs::temp_directory_path() / ("asos-cli-writes-" + std::to_string(::getpid()));
    fs::remove_all(writes);
    fs::create_directories(writes);
    scene("writes.pov", "#version 3.7;\n#fopen F \"out.txt\" write\n#write (F, 1.5, \",\", <1,2,3>)\n"
                        "#fclose F\nsphere { 0, 1 }\n");
    const Result r = runAsos({"parse", "writes.pov", "--write-folder", writes.string()});
    CHECK(r.exitCode == 0);
    std::ifstream in(writes / "out.txt");
    std::string text;
    std::getline(in, text);
    CHECK(text == "1.5,<1,2,3> ");
    CHECK_FALSE(fs::exists(kDir / "out.txt"));
    fs::remove_all(writes);

    const Result bad = runAsos({"parse", "writes.pov", "--write-folder", (writes / "missing").string()});
    CHECK(bad.exitCode != 0);
    CHECK(bad.err.find("--write-folder: '" + (writes / "missing").string() + "' is not a folder (it does not exist)") !=
          std::string::npos);
}
