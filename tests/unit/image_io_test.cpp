#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "asos/image/encoding.hpp"
#include "asos/image/image_io.hpp"

using namespace asos;
namespace fs = std::filesystem;

namespace {
fs::path outputDir(const std::string& name) {
    const fs::path dir = fs::path(ASOS_BINARY_DIR) / "test-output" / "image_io" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// A 4x2 RGB image whose values cover the encoding's interesting cases.
Image sampleImage() {
    Image img = Image::rgb(4, 2);
    const double values[] = {0.0, 0.0078125, 0.2578125, 0.5078125, 0.8828125, 1.0, 1.25, -0.5};
    for (int i = 0; i < 8; ++i) img.setRgb(i % 4, i / 4, Vec3(values[i], values[7 - i], 0.5));
    return img;
}

std::size_t filesIn(const fs::path& dir) {
    std::size_t n = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
    return n;
}

std::string fileBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The float stored little-endian at `bytes[offset]`.
float littleEndianFloat(const std::string& bytes, std::size_t offset) {
    std::uint32_t bits = 0;
    for (int i = 0; i < 4; ++i)
        bits |= std::uint32_t(static_cast<unsigned char>(bytes[offset + i])) << (8 * i);
    return std::bit_cast<float>(bits);
}

// `channels` channels of distinct values, each exact in float: negative, in
// [0, 1] and above 1, so that any clipping, encoding, swapped channel or row
// shows.
Image distinctImage(int width, int height, std::vector<std::string> channels) {
    Image img(width, height, std::move(channels));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < img.channels(); ++c)
                img.at(x, y, c) = float(10 * y + x) * 0.25f - 0.75f + float(c) / 16;
    return img;
}
}  // namespace

TEST_CASE("8-bit encoding matches the codes POV-Ray 3.7 writes", "[image]") {
    // Measured: `povray` with assumed_gamma 1, flat patches of these linear
    // values, +FN8 (docs/rendering.md). sRGB, not a 2.2 power: 0.0078125
    // would be 28 under a 2.2 power.
    CHECK(encodeSrgb8(0.0078125) == 22);
    CHECK(encodeSrgb8(0.0234375) == 42);
    CHECK(encodeSrgb8(0.2578125) == 139);
    CHECK(encodeSrgb8(0.5078125) == 189);
    CHECK(encodeSrgb8(0.8828125) == 241);
    CHECK(encodeSrgb8(1.25) == 255);   // clipped
    CHECK(encodeSrgb8(-0.5) == 0);
    // 16-bit codes from `povray +FN16` of linear ramps (POV-Ray works in
    // float, so about 0.3% of its codes, those within 0.004 of a rounding
    // tie, differ from these by one).
    CHECK(encodeSrgb16(0.00341796875) == 2884);
    CHECK(encodeSrgb16(0.09814453125) == 22678);
    CHECK(encodeSrgb16(0.50048828125) == 48213);
    CHECK(encodeSrgb16(0.87939453125) == 61930);
    CHECK(srgbDecode(srgbEncode(0.3)) == Approx(0.3).epsilon(1e-12));
    // assumed_gamma 2.2: POV-Ray decodes the working value first.
    CHECK(encodeSrgb8(0.5, 2.2) == encodeSrgb8(std::pow(0.5, 2.2)));
}

// Measured: `povray` on a `#version 3.6` scene without assumed_gamma (gamma
// correction off), flat patches of these values, +FN8, +FN16 and +FE.
TEST_CASE("With gamma correction off values are written as they are", "[image]") {
    CHECK(encodeSrgb8(0.2, std::nullopt) == 51);
    CHECK(encodeSrgb8(0.5, std::nullopt) == 128);
    CHECK(encodeSrgb8(0.05, std::nullopt) == 13);
    CHECK(encodeSrgb8(1.5, std::nullopt) == 255);
    CHECK(encodeSrgb8(-0.2, std::nullopt) == 0);
    CHECK(encodeSrgb16(0.2, std::nullopt) == 13107);
    CHECK(encodeSrgb16(0.5, std::nullopt) == 32768);
    CHECK(encodeSrgb16(0.05, std::nullopt) == 3277);
    // EXR holds the working value decoded as sRGB, the curve continued
    // outside [0, 1] (POV-Ray's half floats: 0.0331116, 0.213989, 2.53711,
    // 12.8281, -0.01548).
    CHECK(workingToLinear(0.2, std::nullopt) == Approx(0.0331116).epsilon(1e-3));
    CHECK(workingToLinear(0.5, std::nullopt) == Approx(0.213989).epsilon(1e-3));
    CHECK(workingToLinear(1.5, std::nullopt) == Approx(2.53711).epsilon(1e-3));
    CHECK(workingToLinear(3.0, std::nullopt) == Approx(12.8281).epsilon(1e-3));
    CHECK(workingToLinear(-0.2, std::nullopt) == Approx(-0.01548).epsilon(1e-3));
}

TEST_CASE("PNG and TIFF and EXR files round-trip through OpenImageIO", "[image]") {
    const fs::path dir = outputDir("roundtrip");
    const Image img = sampleImage();

    SECTION("8-bit PNG stores sRGB codes") {
        REQUIRE(writeImage(img, dir / "a.png").ok());
        const ReadResult r = readImage(dir / "a.png");
        REQUIRE(r.ok());
        REQUIRE(r.image.width() == 4);
        REQUIRE(r.image.channels() == 3);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 4; ++x)
                for (int c = 0; c < 3; ++c)
                    CHECK(r.image.at(x, y, c) == Approx(encodeSrgb8(img.at(x, y, c)) / 255.0).margin(1e-7));
    }
    SECTION("16-bit PNG") {
        REQUIRE(writeImage(img, dir / "b.png", {.format = SampleFormat::UInt16}).ok());
        const ReadResult r = readImage(dir / "b.png");
        REQUIRE(r.ok());
        CHECK(r.image.at(3, 0, 0) == Approx(encodeSrgb16(0.5078125) / 65535.0).margin(1e-9));
    }
    SECTION("EXR is linear float and keeps channel names") {
        Image aov(3, 2, {"rays", "level"});
        aov.at(1, 1, 0) = 256.0f;
        aov.at(2, 0, 1) = 4.0f;
        REQUIRE(writeImage(aov, dir / "aov.exr").ok());
        const ReadResult r = readImage(dir / "aov.exr");
        REQUIRE(r.ok());
        REQUIRE(r.image.channels() == 2);
        const int rays = r.image.channelIndex("rays"), level = r.image.channelIndex("level");
        REQUIRE(rays >= 0);
        REQUIRE(level >= 0);
        CHECK(r.image.at(1, 1, rays) == 256.0f);
        CHECK(r.image.at(2, 0, level) == 4.0f);
        CHECK(r.image.at(0, 0, rays) == 0.0f);
        REQUIRE(writeImage(img, dir / "c.exr").ok());
        const ReadResult c = readImage(dir / "c.exr");
        REQUIRE(c.ok());
        CHECK(c.image.at(2, 1, 0) == 1.25f);  // not clipped
        CHECK(c.image.at(3, 1, 0) == -0.5f);
    }
    SECTION("TIFF: 8-bit by default, float on request") {
        REQUIRE(writeImage(img, dir / "d.tif").ok());
        const ReadResult r = readImage(dir / "d.tif");
        REQUIRE(r.ok());
        CHECK(r.image.at(0, 1, 0) == Approx(241 / 255.0).margin(1e-7));
        REQUIRE(writeImage(img, dir / "e.tif", {.format = SampleFormat::Float}).ok());
        const ReadResult f = readImage(dir / "e.tif");
        REQUIRE(f.ok());
        CHECK(f.image.at(0, 1, 0) == 0.8828125f);
    }
    CHECK(filesIn(dir) >= 1);
}

TEST_CASE("Failed writes report an error and leave no file behind", "[image]") {
    const fs::path dir = outputDir("errors");
    const Image img = sampleImage();

    const IoStatus missingDir = writeImage(img, dir / "no" / "such" / "dir.png");
    CHECK_FALSE(missingDir.ok());
    CHECK_THAT(missingDir.error, Catch::Contains("dir.png"));

    const IoStatus unknown = writeImage(img, dir / "image.nosuchformat");
    CHECK_FALSE(unknown.ok());
    CHECK_THAT(unknown.error, Catch::Contains(".nosuchformat"));

    CHECK_FALSE(writeImage(img, dir / "noextension").ok());
    CHECK_FALSE(writeImage(img, dir / "float.png", {.format = SampleFormat::Float}).ok());
    CHECK_FALSE(writeImage(img, dir / "int.exr", {.format = SampleFormat::UInt8}).ok());
    CHECK_FALSE(writeImage(Image(), dir / "empty.png").ok());
    CHECK_FALSE(checkOutputPath(dir / "x.jpg", SampleFormat::UInt16).ok());
    CHECK(checkOutputPath(dir / "x.jpg").ok());

    // The file is complete before it takes the name: when the final rename
    // fails (a directory is in the way) the temporary file is removed too.
    fs::create_directory(dir / "taken.png");
    fs::create_directory(dir / "taken.png" / "child");
    const IoStatus blocked = writeImage(img, dir / "taken.png");
    CHECK_FALSE(blocked.ok());
    CHECK(filesIn(dir) == 1);  // only the directory

    const ReadResult missing = readImage(dir / "missing.png");
    CHECK_FALSE(missing.ok());
    CHECK_THAT(missing.error, Catch::Contains("missing.png"));
}

TEST_CASE("PFM files are written by asos and read back by OpenImageIO", "[image]") {
    const fs::path dir = outputDir("pfm");

    SECTION("RGB: the bytes the format says, rows bottom to top") {
        const Image img = distinctImage(4, 3, {"R", "G", "B"});
        REQUIRE(writeImage(img, dir / "rgb.pfm").ok());
        const std::string bytes = fileBytes(dir / "rgb.pfm");
        const std::string header = "PF\n4 3\n-1.0\n";  // -1.0: little-endian, scale 1
        REQUIRE(bytes.size() == header.size() + 4 * 3 * 3 * 4);
        CHECK(bytes.substr(0, header.size()) == header);
        for (int row = 0; row < 3; ++row)  // the file's first row is the image's bottom one
            for (int x = 0; x < 4; ++x)
                for (int c = 0; c < 3; ++c) {
                    INFO("file row " << row << ", x " << x << ", channel " << c);
                    const std::size_t offset = header.size() + 4 * std::size_t((row * 4 + x) * 3 + c);
                    CHECK(littleEndianFloat(bytes, offset) == img.at(x, 2 - row, c));
                }
        const ReadResult r = readImage(dir / "rgb.pfm");
        REQUIRE(r.ok());
        REQUIRE(r.image.width() == 4);
        REQUIRE(r.image.height() == 3);
        REQUIRE(r.image.channels() == 3);
        CHECK(r.image.data() == img.data());  // linear, unclipped, exact
        CHECK(filesIn(dir) == 1);             // no temporary file left
    }
    SECTION("grey: one channel") {
        const Image img = distinctImage(3, 2, {"Y"});
        REQUIRE(writeImage(img, dir / "grey.pfm").ok());
        const std::string bytes = fileBytes(dir / "grey.pfm");
        const std::string header = "Pf\n3 2\n-1.0\n";
        REQUIRE(bytes.size() == header.size() + 3 * 2 * 4);
        CHECK(bytes.substr(0, header.size()) == header);
        CHECK(littleEndianFloat(bytes, header.size()) == img.at(0, 1, 0));
        const ReadResult r = readImage(dir / "grey.pfm");
        REQUIRE(r.ok());
        REQUIRE(r.image.channels() == 1);
        CHECK(r.image.data() == img.data());
    }
    SECTION("what PFM cannot hold is an error that leaves no file") {
        CHECK(checkOutputPath(dir / "x.pfm").ok());
        CHECK(checkOutputPath(dir / "X.PFM", SampleFormat::Float).ok());
        CHECK_FALSE(checkOutputPath(dir / "x.pfm", SampleFormat::Half).ok());
        CHECK_FALSE(checkOutputPath(dir / "x.pfm", SampleFormat::UInt16).ok());
        const Image rgb = distinctImage(2, 2, {"R", "G", "B"});
        CHECK_FALSE(writeImage(rgb, dir / "half.pfm", {.format = SampleFormat::Half}).ok());
        // No alpha in PFM, and no silent drop of it.
        const IoStatus rgba = writeImage(distinctImage(2, 2, {"R", "G", "B", "A"}), dir / "rgba.pfm");
        CHECK_FALSE(rgba.ok());
        CHECK_THAT(rgba.error, Catch::Contains("rgba.pfm") && Catch::Contains("not 4"));
        CHECK_FALSE(writeImage(distinctImage(2, 2, {"rays", "level"}), dir / "two.pfm").ok());
        const IoStatus missingDir = writeImage(rgb, dir / "no" / "such" / "dir.pfm");
        CHECK_FALSE(missingDir.ok());
        CHECK_THAT(missingDir.error, Catch::Contains("dir.pfm"));
        // Complete before it takes the name: a directory in the way fails the
        // rename, and the temporary file goes too.
        fs::create_directory(dir / "taken.pfm");
        fs::create_directory(dir / "taken.pfm" / "child");
        CHECK_FALSE(writeImage(rgb, dir / "taken.pfm").ok());
        CHECK(filesIn(dir) == 1);  // only the directory
        CHECK_FALSE(fs::exists(dir / "no"));
    }
}

TEST_CASE("Images crop to a rectangle", "[image]") {
    Image img(5, 4, {"a", "b"});
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 5; ++x) {
            img.at(x, y, 0) = float(10 * y + x);
            img.at(x, y, 1) = -float(10 * y + x);
        }
    const Image c = img.cropped(1, 2, 4, 4);
    REQUIRE(c.width() == 3);
    REQUIRE(c.height() == 2);
    CHECK(c.channelNames() == img.channelNames());
    CHECK(c.at(0, 0, 0) == 21.0f);
    CHECK(c.at(2, 1, 1) == -33.0f);
    CHECK_THROWS_AS(img.cropped(0, 0, 6, 1), std::invalid_argument);
    CHECK_THROWS_AS(img.cropped(2, 2, 2, 3), std::invalid_argument);
}
