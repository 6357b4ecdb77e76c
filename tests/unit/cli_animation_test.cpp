// `asos render --frames`: the frame words' values against POV-Ray 3.7's, the
// names the frames take, a failing frame that stops the run and leaves the
// frames before it, and the progress lines written when stderr is not a
// terminal. The bad command lines are in tests/golden/cli/bad_command_lines.txt.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "asos/image/image_io.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;
using asos::test::filesIn;
using asos::test::runAsos;

namespace {

// A scene that prints its frame words (#debug, to stderr) and renders.
fs::path clockScene(const fs::path& dir) {
    const fs::path p = dir / "clock.pov";
    std::ofstream(p) << R"(#version 3.7;
global_settings { assumed_gamma 1 }
#debug concat("CLK frame=", str(frame_number, 0, 3), " clock=", str(clock, 0, 5),
  " delta=", str(clock_delta, 0, 5), " if=", str(initial_frame, 0, 0), " ff=", str(final_frame, 0, 0),
  " ic=", str(initial_clock, 0, 3), " fc=", str(final_clock, 0, 3), " on=", str(clock_on, 0, 0), "\n")
camera { location <0, 0, -3> look_at 0 }
light_source { <2, 3, -4>, rgb 1 }
sphere { <clock, 0, 0>, 1 pigment { rgb 1 } }
)";
    return p;
}

// The lines of `text` that start with `prefix`.
std::vector<std::string> linesStarting(const std::string& text, const std::string& prefix) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line))
        if (line.find(prefix) != std::string::npos) lines.push_back(line.substr(line.find(prefix)));
    return lines;
}

}  // namespace

TEST_CASE("asos render --frames gives each frame POV-Ray's clock and name", "[cli][animation]") {
    const fs::path dir = asos::test::testCaseDir("cli_animation", "clocks");
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    const std::string scene = clockScene(dir).string();

    // What `povray +KFI1 +KFF3` printed for the same #debug (POV-Ray 3.7.0.10).
    const auto three = runAsos(dir, {"render", scene, "--frames", "1-3", "-o", "b#.png", "-W", "8", "-H", "6",
                                     "--quiet"});
    INFO(three.err);
    REQUIRE(three.exitCode == 0);
    CHECK(linesStarting(three.err, "CLK") ==
          std::vector<std::string>{"CLK frame=1.000 clock=0.00000 delta=0.50000 if=1 ff=3 ic=0.000 fc=1.000 on=1",
                                   "CLK frame=2.000 clock=0.50000 delta=0.50000 if=1 ff=3 ic=0.000 fc=1.000 on=1",
                                   "CLK frame=3.000 clock=1.00000 delta=0.50000 if=1 ff=3 ic=0.000 fc=1.000 on=1"});
    CHECK(filesIn(dir) == std::set<std::string>{"clock.pov", "b1.png", "b2.png", "b3.png"});

    // `povray +KFI0 +KFF10 +KI2 +KF3 +SF9 +Oc.png` wrote c09.png and c10.png with these values.
    const auto subset = runAsos(dir, {"render", scene, "--frames", "0-10", "--subset", "9-10", "--clock-from", "2",
                                      "--clock-to", "3", "-o", "c#.png", "-W", "8", "-H", "6", "--quiet"});
    INFO(subset.err);
    REQUIRE(subset.exitCode == 0);
    CHECK(linesStarting(subset.err, "CLK") ==
          std::vector<std::string>{"CLK frame=9.000 clock=2.90000 delta=0.10000 if=0 ff=10 ic=2.000 fc=3.000 on=1",
                                   "CLK frame=10.000 clock=3.00000 delta=0.10000 if=0 ff=10 ic=2.000 fc=3.000 on=1"});
    CHECK(fs::exists(dir / "c09.png"));
    CHECK(fs::exists(dir / "c10.png"));

    // A run of '#' longer than the final frame's digits sets the width; every output takes the number.
    const auto padded = runAsos(dir, {"render", scene, "--frames", "1-12", "--subset", "12", "-o", "p_####.png",
                                      "--stats-json", "p_#.json", "--aov", "samples=p_###_heat.png", "-W", "8", "-H",
                                      "6", "--quiet"});
    INFO(padded.err);
    REQUIRE(padded.exitCode == 0);
    CHECK(linesStarting(padded.err, "CLK") ==
          std::vector<std::string>{"CLK frame=12.000 clock=1.00000 delta=0.09091 if=1 ff=12 ic=0.000 fc=1.000 on=1"});
    for (const char* name : {"p_0012.png", "p_12.json", "p_012_heat.png"}) CHECK(fs::exists(dir / name));

    // One frame: its clock is --clock-from (POV-Ray's would be a NaN), a name without '#' is fine.
    const auto one = runAsos(dir, {"render", scene, "--frames", "5-5", "--clock-from", "0.25", "-o", "one.png", "-W",
                                   "8", "-H", "6", "--quiet"});
    INFO(one.err);
    REQUIRE(one.exitCode == 0);
    CHECK(linesStarting(one.err, "CLK") ==
          std::vector<std::string>{"CLK frame=5.000 clock=0.25000 delta=0.00000 if=5 ff=5 ic=0.250 fc=1.000 on=1"});

    // A frame is the still rendered with that clock: frame 2 of 1-3 is --clock 0.5, byte for byte.
    const auto still = runAsos(dir, {"render", scene, "--clock", "0.5", "-o", "still.png", "-W", "8", "-H", "6",
                                     "--quiet"});
    REQUIRE(still.exitCode == 0);
    CHECK(asos::test::slurp(dir / "still.png") == asos::test::slurp(dir / "b2.png"));
    CHECK(asos::test::slurp(dir / "b1.png") != asos::test::slurp(dir / "b2.png"));
}

TEST_CASE("a frame that fails stops the run and leaves the frames before it", "[cli][animation]") {
    const fs::path dir = asos::test::testCaseDir("cli_animation", "failing-frame");
    for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
    std::ofstream(dir / "fails.pov") << "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n#if (frame_number = 3)\n  #error \"no third frame\"\n#end\n"
                                        "camera { location <0, 0, -3> look_at 0 }\n"
                                        "light_source { <2, 3, -4>, rgb 1 }\nsphere { 0, 1 }\n";
    const auto r = runAsos(dir, {"render", "fails.pov", "--frames", "1-5", "-o", "f_#.png", "-W", "8", "-H", "6",
                                 "--quiet"});
    CHECK(r.exitCode == 1);
    CHECK_THAT(r.err, Catch::Contains("fails.pov:4:3: error: #error: no third frame"));
    CHECK_THAT(r.err, Catch::EndsWith("asos render: error: frame 3 (clock 0.5) failed; frames 1-2 are written\n"));
    CHECK(filesIn(dir) == std::set<std::string>{"fails.pov", "f_1.png", "f_2.png"});

    const auto first = runAsos(dir, {"render", "fails.pov", "--frames", "1-5", "--subset", "3-5", "-o", "g_#.png",
                                     "-W", "8", "-H", "6", "--quiet"});
    CHECK(first.exitCode == 1);
    CHECK_THAT(first.err, Catch::EndsWith("asos render: error: frame 3 (clock 0.5) failed; no frame written\n"));
    CHECK(filesIn(dir) == std::set<std::string>{"fails.pov", "f_1.png", "f_2.png"});
}

TEST_CASE("asos render reports progress in lines when stderr is not a terminal", "[cli][animation]") {
    const fs::path dir = asos::test::testCaseDir("cli_animation", "progress-lines");
    std::ofstream(dir / "plain.pov") << "#version 3.7;\nglobal_settings { assumed_gamma 1 }\ncamera { location <0, 0, -3> look_at 0 }\n"
                                        "light_source { <2, 3, -4>, rgb 1 }\nsphere { 0, 1 }\n";
    // A still: a line at each tenth passed, as POV-Ray's "Rendered N of M pixels"; 64 x 48 is 12 tiles
    // of 16 x 16, a twelfth each: the first line at the second tile, then one a tenth.
    const auto still = runAsos(dir, {"render", "plain.pov", "-o", "still.png", "-W", "64", "-H", "48"});
    REQUIRE(still.exitCode == 0);
    const std::vector<std::string> lines = linesStarting(still.err, "Rendered ");
    CHECK(lines.size() == 10);
    REQUIRE(!lines.empty());
    CHECK(lines.front() == "Rendered 512 of 3072 pixels (16%)");
    CHECK(lines.back() == "Rendered 3072 of 3072 pixels (100%)");
    CHECK(still.err.find('\r') == std::string::npos);  // no bar

    // An animation: a line per frame written, none per tenth.
    const auto frames = runAsos(dir, {"render", "plain.pov", "--frames", "1-3", "-o", "a_#.png", "-W", "16", "-H", "12"});
    REQUIRE(frames.exitCode == 0);
    const std::vector<std::string> frameLines = linesStarting(frames.err, "Rendered ");
    REQUIRE(frameLines.size() == 3);
    CHECK(frameLines[1].starts_with("Rendered frame 2 (2 of 3, clock 0.5) to a_2.png in "));
    CHECK(frameLines[1].ends_with(" s"));

    const auto quiet = runAsos(dir, {"render", "plain.pov", "--frames", "1-3", "-o", "q_#.png", "-W", "16", "-H", "12",
                                     "--quiet"});
    REQUIRE(quiet.exitCode == 0);
    CHECK(quiet.err.empty());
}
