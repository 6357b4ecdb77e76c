// The pieces of `asos-bench accuracy` and `asos reference`: the CSV writer,
// the error metrics, the Pareto front, the reference's cache, and a smoke run
// of the whole benchmark on a tiny scene whose errors must fall with effort.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "asos/image/image.hpp"
#include "asos/testing/csv_table.hpp"
#include "asos/testing/image_error.hpp"
#include "asos/testing/pareto_front.hpp"
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
