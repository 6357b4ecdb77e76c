// The pieces of `asos-bench accuracy` and `asos reference`: the CSV writer,
// the error metrics, the Pareto front, the reference's cache, and a smoke run
// of the whole benchmark on a tiny scene whose errors must fall with effort.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "asos/image/image.hpp"
#include "asos/image/image_io.hpp"
#include "asos/testing/csv_table.hpp"
#include "asos/testing/image_error.hpp"
#include "asos/testing/pareto_front.hpp"
#include "asos/testing/povray_text.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;
using namespace asos;

namespace {

Image uniform(int w, int h, float value) {
    Image image = Image::rgb(w, h);
    for (float& v : image.data()) v = value;
    return image;
}

// A flat scene: a square and a disc in ambient light over a background.
const char* kFlatScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.3> }
camera { location <0, 0, -5> look_at <0, 0, 0> angle 50 }
polygon { 5, <-1.3, -0.9>, <0.9, -1.2>, <1.2, 0.8>, <-0.7, 1.1>, <-1.3, -0.9>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { ambient 1 diffuse 0 } }
disc { <0.7, 0.3, -0.5>, -z, 0.55 pigment { color rgb <0.2, 0.9, 0.4> } finish { ambient 1 diffuse 0 } }
)";

fs::path writeScene(const fs::path& dir) {
    const fs::path scene = dir / "flat.pov";
    std::ofstream(scene) << kFlatScene;
    return scene;
}

std::vector<std::vector<std::string>> readCsv(const fs::path& file) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::stringstream s(line);
        std::string field;
        while (std::getline(s, field, ',')) fields.push_back(field);
        rows.push_back(fields);
    }
    return rows;
}

}  // namespace

TEST_CASE("CsvTable quotes what needs quoting and refuses ragged rows", "[accuracy]") {
    CsvTable t({"a", "b"});
    t.addRow({"1", "x,y"});
    t.addRow({"say \"hi\"", "two\nlines"});
    CHECK(t.rows() == 2);
    CHECK(t.text() == "a,b\n1,\"x,y\"\n\"say \"\"hi\"\"\",\"two\nlines\"\n");
    CHECK(CsvTable::quoted("--eps 1/64 --max 4") == "--eps 1/64 --max 4");
    CHECK_THROWS_AS(t.addRow({"only one"}), std::invalid_argument);
    CHECK_THROWS_AS(CsvTable({}), std::invalid_argument);
}

TEST_CASE("imageError measures display values against the reference", "[accuracy]") {
    SECTION("equal images have no error") {
        const ImageError e = imageError(uniform(4, 3, 0.5f), uniform(4, 3, 0.5f), 1.0);
        CHECK(e.rmse == 0.0);
        CHECK(e.maxError == 0.0);
        CHECK(e.offShare == 0.0);
    }
    SECTION("one pixel off: the RMSE over all values, the share of pixels") {
        // Linear 1 against linear 0 is display 1 against 0 in one pixel of 4 x 3.
        Image a = uniform(4, 3, 0.0f);
        a.setRgb(2, 1, Vec3(1.0));
        const ImageError e = imageError(a, uniform(4, 3, 0.0f), 1.0);
        CHECK(e.rmse == Approx(std::sqrt(3.0 / 36.0)));
        CHECK(e.maxError == Approx(1.0));
        CHECK(e.offShare == Approx(1.0 / 12.0));
    }
    SECTION("errors are sRGB-encoded: a small linear difference in the dark counts more") {
        const ImageError dark = imageError(uniform(2, 2, 0.011f), uniform(2, 2, 0.01f), 1.0);
        const ImageError light = imageError(uniform(2, 2, 0.801f), uniform(2, 2, 0.8f), 1.0);
        CHECK(dark.rmse > 3.0 * light.rmse);
        // 1/64 is the threshold: sRGB(0.011) - sRGB(0.01) is about 0.0057, within it.
        CHECK(dark.offShare == 0.0);
    }
    SECTION("values beyond display white are clipped, as a file holds them") {
        CHECK(imageError(uniform(2, 2, 3.0f), uniform(2, 2, 1.0f), 1.0).rmse == 0.0);
    }
    CHECK_THROWS_AS(imageError(uniform(2, 2, 0.f), uniform(3, 2, 0.f), 1.0), std::invalid_argument);
}

TEST_CASE("paretoFront keeps the settings nothing beats on both", "[accuracy]") {
    //                 cost:  1    2    3    4    2    5
    //                error: 0.5  0.3  0.3  0.1  0.3  0.2
    const std::vector<bool> front = paretoFront({1, 2, 3, 4, 2, 5}, {0.5, 0.3, 0.3, 0.1, 0.3, 0.2});
    CHECK(front == std::vector<bool>{true, true, false, true, true, false});
    CHECK(paretoFront({}, {}).empty());
    CHECK_THROWS_AS(paretoFront({1.0}, {}), std::invalid_argument);
}

TEST_CASE("asos reference renders once and then reads its cache", "[accuracy][cli]") {
    const fs::path dir = asos::test::testCaseDir("accuracy", "reference cache");
    fs::remove_all(dir / "cache");
    const fs::path scene = writeScene(dir);
    const std::vector<std::string> args{"reference", scene.string(), "-W", "12", "-H", "9", "--eye-samples", "4",
                                        "--cache", (dir / "cache").string(), "-o", "ref.exr"};
    const auto first = asos::test::runAsos(dir, args);
    INFO(first.err);
    REQUIRE(first.exitCode == 0);
    CHECK(first.err.find("rendered in") != std::string::npos);
    std::vector<fs::path> cached;
    for (const auto& f : fs::directory_iterator(dir / "cache")) cached.push_back(f.path());
    REQUIRE(cached.size() == 1);
    CHECK(cached[0].filename().string().starts_with("flat-"));
    CHECK(cached[0].filename().string().ends_with("-12x9.exr"));
    const auto second = asos::test::runAsos(dir, args);
    CHECK(second.exitCode == 0);
    CHECK(second.err.find("from the cache") != std::string::npos);
    CHECK(asos::test::slurp(dir / "ref.exr").size() > 0);

    // Another eye count is another reference; bad counts are refused.
    auto other = args;
    other[7] = "2";
    CHECK(asos::test::runAsos(dir, other).err.find("rendered in") != std::string::npos);
    other[7] = "0";
    CHECK(asos::test::runAsos(dir, other).exitCode == 2);
}

TEST_CASE("withoutAsosBlocks blanks our blocks and nothing else", "[accuracy]") {
    const std::string scene = "sphere { 0, 1 asos { eps 1/64 max 4 } }\n"
                              "global_settings { asos /* ours { */ {\n jitter on } ambient_light 1 }\n"
                              "#declare asos_eps = 1; // asos { in a comment\n"
                              "#debug \"asos { in a string\"\n"
                              "/* nested /* asos { */ still a comment */ box { 0, 1 asos{max 3} }\n";
    const std::string out = withoutAsosBlocks(scene);
    REQUIRE(out.size() == scene.size());
    CHECK(out == "sphere { 0, 1                         }\n"
                 "global_settings {                    \n             ambient_light 1 }\n"
                 "#declare asos_eps = 1; // asos { in a comment\n"
                 "#debug \"asos { in a string\"\n"
                 "/* nested /* asos { */ still a comment */ box { 0, 1             }\n");
    CHECK(withoutAsosBlocks("asos") == "asos");                   // no block: kept
    CHECK(withoutAsosBlocks("x asos { max 2") == "x             ");  // left open: to the end
}

TEST_CASE("asos reference: a penumbra under a rectangle light as the closed form has it", "[accuracy][cli]") {
    // A wall (the plane z = 0, white, diffuse only) under a 2 x 2 square
    // light at z = -4; halfway, at z = -2, an opaque half-plane covers
    // x < 0. From the wall's point (x, y), the ray to the light's point
    // (lx, ly) crosses z = -2 at (x + lx) / 2: the light's points with
    // lx > -x reach it, the visible fraction is clamp((1 + x) / 2, 0, 1),
    // a penumbra from x = -1 to x = 1. POV-Ray's emitter lights the point
    // by that fraction along the light centre's direction: the wall's value
    // is fraction x cos, cos = 4 / |(x, y, -4)|. An orthographic camera
    // between the half-plane and the wall sees 4 x 1 of the wall.
    // POV-Ray's jittered lattice of 4 x 4 points reaches half a step past
    // the light's edges, a light 8/3 wide: a penumbra wider by a third,
    // off by up to 0.11 near its ends.
    const fs::path dir = asos::test::testCaseDir("accuracy", "reference penumbra");
    std::ofstream(dir / "penumbra.pov") << R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -0.5> look_at <0, 0, 0> right x * 4 up y * 1 }
light_source { <0, 0, -4> color rgb 1 area_light <2, 0, 0>, <0, 2, 0>, 4, 4 jitter }
plane { -z, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
polygon { 5, <-10, -10>, <0, -10>, <0, 10>, <-10, 10>, <-10, -10> translate -2 * z
  pigment { color rgb 0 } finish { ambient 0 diffuse 0 } }
)";
    const int w = 64, h = 16;
    const auto r = asos::test::runAsos(dir, {"reference", "penumbra.pov", "-W", std::to_string(w), "-H",
                                             std::to_string(h), "--eye-samples", "16", "--no-cache", "--cache",
                                             (dir / "cache").string(), "-o", "ref.exr"});
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
    CHECK(r.err.find("Rendered 1024 of 1024 pixels (100%)") != std::string::npos);  // its progress
    const ReadResult ref = readImage(dir / "ref.exr");
    REQUIRE(ref.ok());
    // Each pixel's closed-form value, averaged over the pixel (64 x 64 points).
    const auto exact = [](double x, double y) {
        return std::clamp((1.0 + x) / 2.0, 0.0, 1.0) * 4.0 / std::sqrt(x * x + y * y + 16.0);
    };
    double sumOfSquares = 0.0, worst = 0.0, penumbraSum = 0.0, expectedSum = 0.0;
    for (int py = 0; py < h; ++py)
        for (int px = 0; px < w; ++px) {
            double expected = 0.0;
            for (int j = 0; j < 64; ++j)
                for (int i = 0; i < 64; ++i)
                    expected += exact(-2.0 + (px + (i + 0.5) / 64.0) * 4.0 / w, 0.5 - (py + (j + 0.5) / 64.0) / h);
            expected /= 64.0 * 64.0;
            const double d = std::abs(double(ref.image.at(px, py, 1)) - expected);
            sumOfSquares += d * d;
            worst = std::max(worst, d);
            penumbraSum += ref.image.at(px, py, 1);
            expectedSum += expected;
        }
    const double rmse = std::sqrt(sumOfSquares / (w * h));
    INFO("RMSE " << rmse << ", max " << worst << ", mean " << penumbraSum / (w * h) << " against "
                 << expectedSum / (w * h));
    // 16 x 16 eye rays, 4 x 4 light strata each: noise alone.
    CHECK(worst < 0.02);
    CHECK(rmse < 0.005);
}

TEST_CASE("asos-bench accuracy: a quick ladder on a tiny scene", "[accuracy][bench]") {
    const fs::path dir = asos::test::testCaseDir("accuracy", "bench quick");
    fs::remove_all(dir / "out");
    const fs::path scene = writeScene(dir);
    const auto r = asos::test::runProgram(
        ASOS_BENCH_EXE, dir,
        {"accuracy", scene.string(), "-o", "out", "-W", "24", "-H", "18", "--quick", "--eye-samples", "8",
         "--cache", (dir / "cache").string(), "--povray", "off", "--no-gnuplot"});
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
    for (const char* f : {"accuracy.csv", "summary.md", "flat.dat", "flat.gp", "flat-reference.png"})
        CHECK(fs::exists(dir / "out" / f));
    const auto rows = readCsv(dir / "out" / "accuracy.csv");
    REQUIRE(rows.size() > 1);
    CHECK(rows[0] == std::vector<std::string>{"scene", "method", "setting", "width", "height", "seconds", "rays",
                                              "rmse", "max_error", "off_share", "pareto"});
    // The quick ladder: asos 2 x 2, grid and jitter 3 each, adaptive 2 x 2, am1 2 x 2.
    CHECK(rows.size() == 1 + 4 + 3 + 3 + 4 + 4);
    std::map<std::string, double> rmse;
    int onFront = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        REQUIRE(rows[i].size() == 11);
        CHECK(rows[i][0] == "flat");
        CHECK(std::stod(rows[i][5]) >= 0.0);
        CHECK(std::stoull(rows[i][6]) > 0);
        const double e = std::stod(rows[i][7]);
        CHECK(e >= 0.0);
        CHECK(std::stod(rows[i][8]) >= e);
        onFront += rows[i][10] == "1";
        rmse[rows[i][1] + " " + rows[i][2]] = e;
    }
    CHECK(onFront >= 1);
    // More effort, less error.
    CHECK(rmse.at("grid --samples 4") < rmse.at("grid --samples 1"));
    CHECK(rmse.at("jitter --samples 4") < rmse.at("jitter --samples 1"));
    CHECK(rmse.at("asos --eps 1/64 --max 4") < rmse.at("asos --eps 1/4 --max 2"));
    CHECK(rmse.at("adaptive --threshold 0.1 --depth 2") < rmse.at("adaptive --threshold 0.3 --depth 1"));
}
