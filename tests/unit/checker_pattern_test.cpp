// POV-Ray 3.7's checker pattern: its cell rule with POV-Ray's tolerance
// (measured with povray), its edge planes against its values, and the
// closed-form share of a box (pbrt-v3's box-filtered checkerboard, in three
// dimensions) against known answers and dense sampling of the box.
#include <catch2/catch.hpp>

#include <random>

#include "asos/render/checker_pattern.hpp"

using namespace asos;

namespace {

const CheckerPattern kChecker;

// The share of value 1 over the box [lo, hi] by n^3 points at the centres
// of its cells (within about 1/n per edge plane the box straddles).
double denseBoxShare(const Vec3& lo, const Vec3& hi, int n) {
    long ones = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const Vec3 f((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n);
                ones += kChecker.value(lo + f * (hi - lo));
            }
    return double(ones) / (double(n) * n * n);
}

}  // namespace

TEST_CASE("Checker follows POV-Ray's cell rule in pattern space", "[shading][checker]") {
    CHECK(kChecker.value({0.5, 0.5, 0.5}) == 0);
    CHECK(kChecker.value({1.5, 0.5, 0.5}) == 1);
    CHECK(kChecker.value({1.5, 1.5, 0.5}) == 0);
    CHECK(kChecker.value({-0.5, 0.5, 0.5}) == 1);
    CHECK(kChecker.value({-0.5, -0.5, 0.5}) == 0);
    // POV-Ray 3.7's tolerance (measured): a point 1e-10 below a cell
    // boundary is in the upper cell, 1.1e-10 below is not.
    CHECK(kChecker.value({0.5, -1e-16, 0.5}) == 0);
    CHECK(kChecker.value({0.5, -1e-10, 0.5}) == 0);
    CHECK(kChecker.value({0.5, -1.1e-10, 0.5}) == 1);
    CHECK(kChecker.value({0.5, -0.0005, 0.5}) == 1);
    CHECK(kChecker.value({0.9995, 0.5, 0.5}) == 0);
    CHECK(kChecker.value({1e12 + 1.5, 0.5, 0.5}) == 1);

}

TEST_CASE("Checker's edge planes are where its value changes", "[shading][checker]") {
    // Along each axis the value flips across each plane and nowhere between.
    for (int axis = 0; axis < 3; ++axis) {
        const PatternPlanes planes = kChecker.planes(axis);
        std::vector<double> found;
        planes.forEachInside(-2.3, 1.7, [&](double p) { found.push_back(p); });
        REQUIRE(found.size() == 4);
        CHECK(planes.countInside(-2.3, 1.7, 100) >= 4);
        double previous = -2.3;
        Vec3 point(0.5);
        point[axis] = previous;
        int value = kChecker.value(point);
        for (double p : found) {
            CHECK(p > previous);
            point[axis] = 0.5 * (previous + p);
            CHECK(kChecker.value(point) == value);  // no change between planes
            point[axis] = p + 1e-9;
            CHECK(kChecker.value(point) != value);  // a change across each
            value = 1 - value;
            previous = p;
        }
    }
}

TEST_CASE("Checker's box share has its known answers", "[shading][checker]") {
    // Inside one cell: its value.
    CHECK(kChecker.boxShare({0.1, 0.2, 0.3}, {0.9, 0.8, 0.7}) == Approx(0.0).margin(1e-12));
    CHECK(kChecker.boxShare({1.1, 0.2, 0.3}, {1.9, 0.8, 0.7}) == Approx(1.0));
    // Across one plane at x = 1, 30 % beyond it.
    CHECK(kChecker.boxShare({0.3, 0.2, 0.3}, {1.3, 0.8, 0.7}) == Approx(0.3));
    // Across an edge of two planes, a quarter of the box in each cell.
    CHECK(kChecker.boxShare({0.5, 0.5, 0.2}, {1.5, 1.5, 0.7}) == Approx(0.5));
    // Across a corner, off centre: x 2/3 in cell 0, y 3/4 in cell 0.
    CHECK(kChecker.boxShare({0.6, 0.25, 0.2}, {1.2, 1.25, 0.7}) ==
          Approx(2.0 / 3.0 * 0.25 + 1.0 / 3.0 * 0.75));
    // A box of whole cells pairs them off; a huge one tends to the mean.
    CHECK(kChecker.boxShare({0.0, 0.0, 0.0}, {2.0, 3.0, 1.0}) == Approx(0.5));
    CHECK(kChecker.boxShare({-1000.3, 5.1, -77.7}, {1000.9, 900.6, 3000.2}) == Approx(0.5).margin(1e-6));
    // A box of no width along y (a floor in the plane y = 0, as POV-Ray's
    // epsilon puts it in cell 0) is the checker of x and z.
    CHECK(kChecker.boxShare({0.5, -1e-16, 0.2}, {1.5, -1e-16, 0.7}) == Approx(0.5));
    CHECK(kChecker.boxShare({1.2, -1e-16, 0.2}, {1.8, -1e-16, 0.7}) == 1.0);
    CHECK(kChecker.boxShare({1.2, -0.5, 0.2}, {1.8, -0.5, 0.7}) == 0.0);
}

TEST_CASE("Checker's box share matches dense sampling of the box", "[shading][checker]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> corner(-4.0, 4.0), width(0.05, 2.5);
    for (int i = 0; i < 24; ++i) {
        const Vec3 lo(corner(rng), corner(rng), corner(rng));
        const Vec3 hi = lo + Vec3(width(rng), width(rng), width(rng));
        INFO("box " << lo.x << " " << lo.y << " " << lo.z << " to " << hi.x << " " << hi.y << " " << hi.z);
        CHECK(kChecker.boxShare(lo, hi) == Approx(denseBoxShare(lo, hi, 96)).margin(0.01));
    }
}
