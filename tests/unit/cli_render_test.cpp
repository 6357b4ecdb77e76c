// `asos render` as a user runs it: images written by extension, statistics,
// the samples AOV; bad options (exit status 2) and scenes (1) give an error
// and no file; the same bytes for any thread count, and regions that tile the image.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "asos/image/image_io.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;
using namespace asos;

namespace {

using Result = asos::test::ProgramResult;
using asos::test::slurp;

fs::path scratchDir() {
    return asos::test::testCaseDir("cli_render", Catch::getResultCapture().getCurrentTestName());
}

Result runAsos(std::vector<std::string> args) { return asos::test::runAsos(scratchDir(), std::move(args)); }

// A small scene with every kind of edge and a shadow.
fs::path sceneFile() {
    const fs::path p = scratchDir() / "scene.pov";
    std::ofstream(p) << R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.3, 0.4, 0.6> }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 45 }
light_source { <-5, 9, -6>, color rgb 1 }
plane { y, 0 pigment { color rgb 0.8 } }
sphere { <-1, 1, 0>, 1 pigment { color rgb <0.9, 0.2, 0.1> } finish { phong 0.5 } }
box { <0.4, 0, -0.5>, <1.6, 1.2, 0.7> rotate y*25 pigment { color rgb <0.2, 0.4, 0.9> } }
cylinder { <0, 0, 2>, <0, 2, 2>, 0.3 pigment { color rgb <0.2, 0.8, 0.3> } }
)";
    return p;
}

}  // namespace

TEST_CASE("ASOS settings: an object's block, then the command line, then global_settings", "[cli]") {
    // The one precedence rule (docs/manual/asos.md, "Which setting wins"),
    // seen in the deepest level of eye pyrays the statistics count. The
    // sphere's outline against the background involves the sphere alone.
    const fs::path dir = scratchDir();
    const auto scene = [&](const std::string& name, const std::string& own) {
        std::ofstream(dir / name) << "#version 3.7;\n"
                                     "global_settings { assumed_gamma 1.0 asos { max 1 } }\n"
                                     "camera { location <0, 0, -4> look_at 0 }\n"
                                     "light_source { <0, 5, -5>, rgb 1 }\n"
                                     "sphere { 0, 1 pigment { rgb 1 } " << own << " }\n";
        return (dir / name).string();
    };
    const std::string global = scene("global.pov", "");
    const std::string own = scene("own.pov", "asos { max 2 }");
    const auto deepest = [&](std::vector<std::string> args) {
        args.insert(args.end(), {"-o", "out.png", "-W", "64", "-H", "48", "--stats", "--quiet"});
        const Result r = runAsos(args);
        INFO(r.err);
        REQUIRE(r.exitCode == 0);
        int level = -1;
        for (int k = 0; k <= 10; ++k)
            if (r.out.find("\n  pyrays level " + std::to_string(k) + " ") != std::string::npos) level = k;
        return level;
    };
    CHECK(deepest({"render", global}) == 1);                  // global_settings over the default 4
    CHECK(deepest({"render", global, "--max", "3"}) == 3);    // the command line over global_settings
    CHECK(deepest({"render", own, "--max", "3"}) == 2);       // the object's own block over both
    CHECK(deepest({"render", own, "--max", "0"}) == 2);
}

TEST_CASE("asos render writes the image, statistics and the samples AOV", "[cli]") {
    const std::string scene = sceneFile().string();
    const fs::path dir = scratchDir();
    fs::remove(dir / "ok.png");
    const Result r = runAsos({"render", scene, "-o", "ok.png", "-W", "64", "-H", "48", "--stats",
                           "--stats-json", "ok.json", "--aov", "samples=ok_samples.exr", "--quiet"});
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK_THAT(r.out, Catch::Contains("Render statistics"));
    CHECK_THAT(r.out, Catch::Contains("pyrays level 0           3072"));
    CHECK_THAT(slurp(dir / "ok.json"), Catch::Contains("\"method\": \"asos\""));
    const ReadResult image = readImage(dir / "ok.png");
    REQUIRE(image.ok());
    CHECK(image.image.width() == 64);
    CHECK(image.image.height() == 48);
    const ReadResult samples = readImage(dir / "ok_samples.exr");
    REQUIRE(samples.ok());
    CHECK(samples.image.channelIndex("rays") >= 0);
    CHECK(samples.image.channelIndex("level") >= 0);

    // --bit-depth 16: POV-Ray's +FN16; a 16-bit PNG holds values between the 8-bit codes.
    const Result deep = runAsos({"render", scene, "-o", "deep.png", "-W", "32", "-H", "24", "--bit-depth",
                                 "16", "--quiet"});
    INFO(deep.err);
    REQUIRE(deep.exitCode == 0);
    const ReadResult deepImage = readImage(dir / "deep.png");
    REQUIRE(deepImage.ok());
    int between = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            const double v = deepImage.image.at(x, y, 0) * 255.0;
            between += std::fabs(v - std::round(v)) > 1e-3;
        }
    CHECK(between > 100);

    for (const char* method : {"single", "grid", "jitter", "adaptive", "am1"}) {
        const Result m = runAsos({"render", scene, "-o", std::string(method) + ".exr", "-W", "32", "-H",
                               "24", "--method", method, "--samples", "2", "--quiet"});
        INFO(method << ": " << m.err);
        CHECK(m.exitCode == 0);
        CHECK(readImage(dir / (std::string(method) + ".exr")).ok());
    }
}

TEST_CASE("asos render writes PFM through its own writer", "[cli]") {
    const std::string scene = sceneFile().string();
    const fs::path dir = scratchDir();
    const std::vector<std::string> common{"render", scene, "-W", "32", "-H", "24", "--quiet"};
    auto run = [&](std::vector<std::string> extra) {
        std::vector<std::string> args = common;
        args.insert(args.end(), extra.begin(), extra.end());
        return runAsos(args);
    };
    fs::remove(dir / "out.pfm");
    const Result r = run({"-o", "out.pfm", "--aov", "samples=out_samples.pfm"});
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(r.err.empty());
    CHECK(slurp(dir / "out.pfm").starts_with("PF\n32 24\n-1.0\n"));
    const ReadResult pfm = readImage(dir / "out.pfm");
    REQUIRE(pfm.ok());
    CHECK(readImage(dir / "out_samples.pfm").ok());  // the heat map, RGB

    // The same linear floats as the EXR of the same render.
    const Result e = run({"-o", "out.exr"});
    INFO(e.err);
    REQUIRE(e.exitCode == 0);
    const ReadResult exr = readImage(dir / "out.exr");
    REQUIRE(exr.ok());
    REQUIRE(pfm.image.width() == 32);
    REQUIRE(pfm.image.height() == 24);
    REQUIRE(pfm.image.channels() == 3);
    const int exrChannel[3] = {exr.image.channelIndex("R"), exr.image.channelIndex("G"),
                               exr.image.channelIndex("B")};  // EXR may reorder them
    int differ = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x)
            for (int c = 0; c < 3; ++c) differ += pfm.image.at(x, y, c) != exr.image.at(x, y, exrChannel[c]);
    CHECK(differ == 0);

    // PFM holds float only: an error before anything is rendered.
    fs::remove(dir / "deep.pfm");
    const Result deep = run({"-o", "deep.pfm", "--bit-depth", "16"});
    CHECK(deep.exitCode == 2);
    CHECK_THAT(deep.err, Catch::Contains("cannot store 16-bit samples"));
    CHECK_FALSE(fs::exists(dir / "deep.pfm"));
}

TEST_CASE("asos render: bad options and scenes give an error and no file", "[cli]") {
    const std::string scene = sceneFile().string();
    const fs::path dir = scratchDir();
    // Every bad option is reported, in one run, before anything is parsed.
    fs::remove(dir / "bad.png");
    const Result r1 = runAsos({"render", scene, "-o", "bad.png", "--method", "stochastic", "--eps",
                               "abc", "--max", "11", "--jitter", "maybe", "--samples", "0", "--depth",
                               "9", "-W", "0", "--threads", "-1", "--aov", "normals=x.exr", "-D",
                               "1x=2"});
    CHECK(r1.exitCode == 2);
    for (const char* mention : {"--method", "--eps", "max", "--jitter", "samples", "depth",
                                "image size", "threads", "--aov", "-D"})
        CHECK_THAT(r1.err, Catch::Contains(std::string("error: ")) && Catch::Contains(mention));
    CHECK_FALSE(fs::exists(dir / "bad.png"));

    const Result r2 = runAsos({"render", scene, "-o", "bad.notaformat", "-W", "16", "-H", "12",
                               "--region", "0,0,100,100", "--eps", "1/0"});
    CHECK(r2.exitCode == 2);
    for (const char* mention : {"-o", "--region", "--eps"}) CHECK_THAT(r2.err, Catch::Contains(mention));
    const Result r4 = runAsos({"render", scene, "-o", "bad.png", "--bit-depth", "half"});
    CHECK(r4.exitCode == 2);
    CHECK_THAT(r4.err, Catch::Contains("cannot store half-float samples"));
    const Result r5 = runAsos({"render", scene, "-o", "bad.png", "--bit-depth", "12"});
    CHECK(r5.exitCode == 2);
    CHECK_THAT(r5.err, Catch::Contains("--bit-depth must be"));
    const Result r6 = runAsos({"render", scene, "-o", "bad.png", "--pattern-filter", "maybe"});
    CHECK(r6.exitCode == 2);
    CHECK_THAT(r6.err, Catch::Contains("--pattern-filter wants on or off"));
    const Result r7 = runAsos({"render", scene, "-o", "bad.png", "--method", "single", "--pattern-filter", "on"});
    CHECK(r7.exitCode == 2);
    CHECK_THAT(r7.err, Catch::Contains("pattern filter needs the ASOS eye method"));
    const Result r3 = runAsos({"render", scene, "-o", "bad.png", "-W", "16", "-H", "12", "--eps", "-0.5"});
    CHECK(r3.exitCode == 2);
    CHECK_THAT(r3.err, Catch::Contains("eps must be"));
    CHECK_FALSE(fs::exists(dir / "bad.png"));

    // A scene error: file:line:col, no image.
    const fs::path broken = dir / "broken.pov";
    std::ofstream(broken) << "sphere { <0, 0, 0>, 1\n";
    fs::remove(dir / "broken.png");
    const Result r = runAsos({"render", broken.string(), "-o", "broken.png", "-W", "8", "-H", "6"});
    CHECK(r.exitCode == 1);
    CHECK_THAT(r.err, Catch::Contains("broken.pov:"));
    CHECK_FALSE(fs::exists(dir / "broken.png"));

    // A scene the renderer cannot render: a flat disc light.
    const fs::path area = dir / "area.pov";
    std::ofstream(area) << "light_source { <0, 5, 0>, 1 area_light x, z, 2, 2 circular }\n"
                           "sphere { 0, 1 }\n";
    const Result a = runAsos({"render", area.string(), "-o", "area.png", "-W", "8", "-H", "6"});
    CHECK(a.exitCode == 1);
    CHECK_THAT(a.err, Catch::Contains("area.pov:1:"));
    CHECK_FALSE(fs::exists(dir / "area.png"));
}

TEST_CASE("asos render gives the same bytes for any thread count and region tiling", "[cli]") {
    const std::string scene = sceneFile().string();
    const fs::path dir = scratchDir();
    const std::vector<std::string> common{"render", scene, "-W", "48", "-H", "36", "--jitter", "on",
                                          "--seed", "9", "--quiet"};
    auto run = [&](const std::string& out, std::vector<std::string> extra) {
        std::vector<std::string> args = common;
        args.push_back("-o");
        args.push_back(out);
        args.insert(args.end(), extra.begin(), extra.end());
        const Result r = runAsos(args);
        INFO(r.err);
        REQUIRE(r.exitCode == 0);
    };
    run("t1.png", {"--threads", "1"});
    run("t2.png", {"--threads", "2"});
    CHECK(slurp(dir / "t1.png") == slurp(dir / "t2.png"));

    // Each region's file holds exactly that part of the whole image.
    const ReadResult whole = readImage(dir / "t1.png");
    REQUIRE(whole.ok());
    const int parts[3][4] = {{0, 0, 48, 20}, {0, 20, 30, 36}, {30, 20, 48, 36}};
    for (const auto& p : parts) {
        const std::string region = std::to_string(p[0]) + "," + std::to_string(p[1]) + "," +
                                   std::to_string(p[2]) + "," + std::to_string(p[3]);
        run("part.png", {"--region", region, "--threads", "2"});
        const ReadResult part = readImage(dir / "part.png");
        REQUIRE(part.ok());
        INFO("region " << region);
        CHECK(part.image == whole.image.cropped(p[0], p[1], p[2], p[3]));
    }
}
