#include <catch2/catch.hpp>

#include <filesystem>

#include "asos/image/aov.hpp"

using namespace asos;
namespace fs = std::filesystem;

TEST_CASE("The heat map runs from black through red to white", "[aov]") {
    CHECK(heatMapColor(0.0) == Vec3(0.0));
    CHECK(heatMapColor(-1.0) == Vec3(0.0));
    CHECK(heatMapColor(1.0) == Vec3(1.0));
    CHECK(heatMapColor(0.5) == Vec3(0.85, 0.15, 0.25));
    CHECK(heatMapColor(0.125).x == Approx(0.165));
    // Brighter with more work: the channel sum never decreases.
    double previous = -1.0;
    for (int i = 0; i <= 100; ++i) {
        const Vec3 c = heatMapColor(i / 100.0);
        const double sum = c.x + c.y + c.z;
        CHECK(sum >= previous - 1e-12);
        previous = sum;
    }
}

TEST_CASE("Samples AOV maps rays on a log scale and writes EXR or a heat map", "[aov]") {
    Image samples(4, 1, {"rays", "level"});
    samples.at(0, 0, 0) = 1;
    samples.at(1, 0, 0) = 4;
    samples.at(2, 0, 0) = 16;
    samples.at(3, 0, 0) = 256;
    samples.at(3, 0, 1) = 4;
    const Image heat = samplesHeatMap(samples);
    CHECK(heat.rgbAt(0, 0) == Vec3(0.0));
    CHECK(glm::length(heat.rgbAt(1, 0) - heatMapColor(0.25)) < 1e-6);
    CHECK(glm::length(heat.rgbAt(2, 0) - heatMapColor(0.5)) < 1e-6);
    CHECK(heat.rgbAt(3, 0) == Vec3(1.0));
    // A fixed scale (say 4^MAX) makes maps of different renders comparable.
    CHECK(glm::length(samplesHeatMap(samples, 65536).rgbAt(3, 0) - heatMapColor(0.5)) < 1e-6);
    CHECK_THROWS(samplesHeatMap(Image::rgb(2, 2)));

    const fs::path dir = fs::path(ASOS_BINARY_DIR) / "test-output" / "aov";
    fs::create_directories(dir);
    REQUIRE(writeSamplesAov(samples, dir / "samples.exr").ok());
    const ReadResult exr = readImage(dir / "samples.exr");
    REQUIRE(exr.ok());
    CHECK(exr.image.at(3, 0, exr.image.channelIndex("rays")) == 256.0f);
    CHECK(exr.image.at(3, 0, exr.image.channelIndex("level")) == 4.0f);
    REQUIRE(writeSamplesAov(samples, dir / "samples.png").ok());
    const ReadResult png = readImage(dir / "samples.png");
    REQUIRE(png.ok());
    CHECK(png.image.channels() == 3);
    // Display values are written as they are, not sRGB-encoded again.
    CHECK(png.image.at(2, 0, 0) == Approx(std::lround(0.85 * 255) / 255.0).margin(1e-6));
    CHECK(png.image.at(3, 0, 1) == 1.0f);
    CHECK_FALSE(writeSamplesAov(Image::rgb(2, 2), dir / "bad.png").ok());
}
