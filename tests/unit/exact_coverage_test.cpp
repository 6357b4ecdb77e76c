// Exact coverage (asos/testing/exact_coverage.hpp): known areas of a pixel
// square, then whole flat scenes, against which the brute-force reference of
// `asos reference` is checked.
#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <numbers>

#include "asos/diag/diagnostics.hpp"
#include "asos/image/image_io.hpp"
#include "asos/lang/interpreter.hpp"
#include "asos/render/renderer.hpp"
#include "asos/scene/scene.hpp"
#include "asos/testing/exact_coverage.hpp"
#include "run_asos.hpp"

namespace fs = std::filesystem;
using namespace asos;
using std::numbers::pi;

namespace {

const std::vector<Vec2> kPixel{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

ImageShape polygon(std::vector<Vec2> points) { return {std::move(points), std::nullopt, Vec3(1.0)}; }

ImageShape circle(Vec2 centre, double radius) {
    return {{}, ImageEllipse{centre, glm::dmat2(1.0 / radius)}, Vec3(1.0)};
}

SceneDescription interpret(const std::string& text) {
    Diagnostics d;
    std::optional<SceneDescription> s = lang::interpretText(text, "flat.pov", {}, d);
    REQUIRE(s);
    return *s;
}

// A flat scene: a slanted polygon, one in front of it, a tilted disc in front
// of both and a small disc between them, across the front polygon's edge.
// Nothing interpenetrates, and no two discs share a pixel.
const char* kFlatScene = R"(#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.3> }
camera { location <0, 0, -5> look_at <0, 0, 0> angle 50 }
polygon { 5, <-1.3, -0.9>, <0.9, -1.2>, <1.2, 0.8>, <-0.7, 1.1>, <-1.3, -0.9>
  rotate y * 25 pigment { color rgb <0.9, 0.8, 0.2> } finish { ambient 1 diffuse 0 } }
polygon { 4, <-0.2, -1.6>, <1.9, 0.3>, <-0.4, 0.2>, <-0.2, -1.6>
  translate -z pigment { color rgb <0.8, 0.1, 0.6> } finish { ambient 1 diffuse 0 } }
disc { <0.7, 0.6, -1.5>, <0.2, 0.3, -1>, 0.4 pigment { color rgb <0.2, 0.9, 0.4> } finish { ambient 1 diffuse 0 } }
disc { <-0.1, 0.15, -0.2>, -z, 0.1 pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }
)";

}  // namespace

TEST_CASE("Exact coverage: known areas in a pixel", "[exact]") {
    SECTION("half a pixel") {
        const auto a = visibleAreas({polygon({{-1, -1}, {0.5, -1}, {0.5, 2}, {-1, 2}})}, kPixel);
        CHECK(a[0] == Approx(0.5));
        CHECK(a[1] == Approx(0.5));
    }
    SECTION("a triangle in a corner, either orientation") {
        CHECK(visibleAreas({polygon({{0, 0}, {0.5, 0}, {0, 0.5}})}, kPixel)[0] == Approx(0.125));
        CHECK(visibleAreas({polygon({{0, 0.5}, {0.5, 0}, {-0.5, -0.5}})}, kPixel)[0] == Approx(0.125));
    }
    SECTION("a disc inside, across an edge, on a corner; an ellipse") {
        CHECK(visibleAreas({circle({0.5, 0.5}, 0.3)}, kPixel)[0] == Approx(pi * 0.09));
        CHECK(visibleAreas({circle({1.0, 0.5}, 0.3)}, kPixel)[0] == Approx(pi * 0.09 / 2));
        CHECK(visibleAreas({circle({0.0, 0.0}, 0.5)}, kPixel)[0] == Approx(pi * 0.25 / 4));
        const ImageShape ellipse{{}, ImageEllipse{{0.5, 0.5}, glm::dmat2(1 / 0.4, 0, 0, 1 / 0.2)}, Vec3(1.0)};
        CHECK(visibleAreas({ellipse}, kPixel)[0] == Approx(pi * 0.08));
        CHECK(visibleAreas({circle({0.5, 0.5}, 2.0)}, kPixel)[0] == Approx(1.0));
    }
    SECTION("two overlapping polygons, the front one hiding part of the back one") {
        const auto a = visibleAreas({polygon({{0, 0}, {0.6, 0}, {0.6, 0.6}, {0, 0.6}}),
                                     polygon({{0.4, 0}, {1, 0}, {1, 1}, {0.4, 1}})},
                                    kPixel);
        CHECK(a[0] == Approx(0.36));
        CHECK(a[1] == Approx(0.6 - 0.12));
        CHECK(a[2] == Approx(0.16));
    }
    SECTION("a disc in front of a polygon, and a polygon in front of a disc") {
        const ImageShape all = polygon({{-1, -1}, {2, -1}, {2, 2}, {-1, 2}});
        auto a = visibleAreas({circle({0.5, 0.5}, 0.25), all}, kPixel);
        CHECK(a[0] == Approx(pi / 16));
        CHECK(a[1] == Approx(1 - pi / 16));
        CHECK(a[2] == Approx(0.0).margin(1e-12));
        a = visibleAreas({polygon({{-1, -1}, {0.5, -1}, {0.5, 2}, {-1, 2}}), circle({0.5, 0.5}, 0.25)}, kPixel);
        CHECK(a[0] == Approx(0.5));
        CHECK(a[1] == Approx(pi / 32));
        CHECK(a[2] == Approx(0.5 - pi / 32));
    }
    SECTION("two discs in one pixel are refused") {
        CHECK_THROWS_AS(visibleAreas({circle({0.3, 0.5}, 0.2), circle({0.7, 0.5}, 0.2)}, kPixel),
                        std::invalid_argument);
    }
}

TEST_CASE("Exact coverage of a scene: areas add up to the projected shapes", "[exact]") {
    // A square facing the camera: its pixels' coverage adds up to its projected area.
    const SceneDescription s = interpret(R"(#version 3.7;
camera { location <0, 0, -5> look_at <0, 0, 0> angle 50 }
polygon { 5, <-1.05, -0.7>, <1.1, -0.7>, <1.1, 0.93>, <-1.05, 0.93>, <-1.05, -0.7>
  pigment { color rgb 1 } finish { ambient 1 diffuse 0 } })");
    const Image image = exactCoverageImage(s, 40, 30);
    double sum = 0.0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) sum += image.at(x, y, 0);
    // The plane z = 0 is 2 * 5 * tan(25 deg) wide in 40 pixels, and 1 / 1.33
    // of that high (right's default length 1.33, up's 1) in 30.
    const double across = 2.0 * 5.0 * std::tan(25.0 * pi / 180.0);
    CHECK(sum == Approx(2.15 * 1.63 * (40.0 / across) * (30.0 * 1.33 / across)).epsilon(1e-6));  // the image holds floats

    const SceneDescription sphere = interpret(R"(camera { location <0, 0, -5> look_at 0 } sphere { 0, 1 })");
    CHECK_THROWS_AS(exactCoverageImage(sphere, 8, 6), std::invalid_argument);
    const SceneDescription lit = interpret(R"(camera { location <0, 0, -5> look_at 0 } disc { 0, z, 1 })");
    CHECK_THROWS_AS(exactCoverageImage(lit, 8, 6), std::invalid_argument);
}

TEST_CASE("The brute-force reference agrees with exact coverage on a flat scene", "[exact][accuracy]") {
    const fs::path dir = asos::test::testCaseDir("exact", "reference");
    std::ofstream(dir / "flat.pov") << kFlatScene;
    const auto r = asos::test::runAsos(dir, {"reference", "flat.pov", "-W", "40", "-H", "30", "--no-cache",
                                             "--cache", (dir / "cache").string(), "-o", "ref.exr"});
    INFO(r.err);
    REQUIRE(r.exitCode == 0);
    const ReadResult ref = readImage(dir / "ref.exr");
    REQUIRE(ref.ok());
    const Image exact = exactCoverageImage(interpret(kFlatScene), 40, 30);
    double sumOfSquares = 0.0, worst = 0.0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x)
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(double(ref.image.at(x, y, c)) - exact.at(x, y, c));
                sumOfSquares += d * d;
                worst = std::max(worst, d);
            }
    const double rmse = std::sqrt(sumOfSquares / (40 * 30 * 3));
    INFO("RMSE " << rmse << ", max " << worst);
    // 32 x 32 jittered rays: a pixel an edge crosses is off by at most the
    // share of the strata it crosses, 32 of 1024, times the contrast (0.9 at
    // most here); measured: max 0.0048, RMSE 0.00038 (linear).
    CHECK(worst < 0.9 / 32);
    CHECK(rmse < 0.001);
}

TEST_CASE("EPS is a promise: ASOS within EPS of the exact image in every pixel", "[exact][asos]") {
    // examples/bench/coverage.pov (slivers, a star of shared edges, discs
    // 0.5-2.5 pixels across, slanted polygons) at 80 x 60: with MAX 8 ASOS's
    // bound stops subdivision before MAX in nearly every pixel, and where it
    // stops, the marginal pyrays' area left is within EPS of the pixel, so
    // no channel of a pixel can be further than EPS (colours at most 1).
    // Measured (asos-bench eps -W 80 -H 60): worst 0.67, 0.39 and 0.72 EPS;
    // with MAX 4 instead, EPS 1/256 holds in 99.3 % of pixels only.
    Diagnostics d;
    lang::InterpreterOptions options;
    options.imageWidth = 80;
    options.imageHeight = 60;
    const std::optional<SceneDescription> description =
        lang::interpretFile(fs::path(ASOS_SOURCE_DIR) / "examples" / "bench" / "coverage.pov", options, d);
    REQUIRE(description);
    const std::unique_ptr<Scene> scene = Scene::build(*description, d);
    REQUIRE(scene);
    const Image exact = exactCoverageImage(*description, 80, 60);
    for (const int e : {16, 64, 256}) {
        RenderSettings settings;
        settings.width = 80;
        settings.height = 60;
        settings.asos.eps = 1.0 / e;
        settings.asos.maxLevel = 8;
        const RenderOutput out = render(*scene, settings);
        double worst = 0.0;
        for (int y = 0; y < 60; ++y)
            for (int x = 0; x < 80; ++x)
                for (int c = 0; c < 3; ++c)
                    worst = std::max(worst, std::abs(double(out.color.at(x, y, c)) - exact.at(x, y, c)));
        INFO("EPS 1/" << e << ": worst " << worst * e << " EPS");
        CHECK(worst <= 1.0 / e);
    }
}
