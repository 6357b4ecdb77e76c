// The golden tests' image comparison (asos_testing): OpenImageIO's
// test-suite thresholds on the product's Image.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "asos/testing/image_comparison.hpp"

using namespace asos;

TEST_CASE("Image comparison follows OpenImageIO's test-suite thresholds", "[image]") {
    Image a = Image::rgb(100, 100);
    for (float& v : a.data()) v = 0.5f;
    Image b = a;
    ImageComparison same = compareImages(a, b);
    CHECK(same.passed);
    CHECK(same.maxError == 0.0);
    CHECK(same.pixels == 10000);

    // 0.02% of 10000 pixels is 2: two failing pixels pass, three fail.
    b.at(10, 20, 1) = 0.506f;
    b.at(11, 20, 1) = 0.506f;
    ImageComparison two = compareImages(a, b);
    CHECK(two.failPixels == 2);
    CHECK(two.passed);
    b.at(12, 20, 1) = 0.506f;
    CHECK_FALSE(compareImages(a, b).passed);

    // Any single value over 0.012 fails; the worst pixel is reported.
    Image c = a;
    c.at(42, 7, 2) = 0.52f;
    const ImageComparison hard = compareImages(a, c);
    CHECK_FALSE(hard.passed);
    CHECK(hard.maxX == 42);
    CHECK(hard.maxY == 7);
    CHECK(hard.maxChannel == 2);
    CHECK(hard.maxError == Approx(0.02).margin(1e-6));
    CHECK_THAT(hard.summary(), Catch::Contains("FAIL") && Catch::Contains("(42, 7)"));
    CHECK(absoluteDifference(a, c).at(42, 7, 2) == Approx(0.02f).margin(1e-6));

    Image nan = a;
    nan.at(0, 0, 0) = std::nanf("");
    CHECK_FALSE(compareImages(a, nan).passed);
    // NaN matches NaN, an infinity the same infinity; other non-finite
    // differences are infinite.
    CHECK(compareImages(nan, nan).passed);
    Image inf = a;
    inf.at(1, 1, 1) = std::numeric_limits<float>::infinity();
    CHECK(compareImages(inf, inf).passed);
    const ImageComparison finiteAndInf = compareImages(a, inf);
    CHECK_FALSE(finiteAndInf.passed);
    CHECK(std::isinf(finiteAndInf.maxError));

    const ImageComparison mismatch = compareImages(a, Image::rgb(10, 10));
    CHECK_FALSE(mismatch.passed);
    CHECK_FALSE(mismatch.error.empty());
}
