// POV-Ray 3.7's brick pattern: known answers in a brick, in the mortar,
// across the courses (each shifted by half a brick) and at negative
// coordinates; POV-Ray's own answers at the edge of a joint (measured with
// povray); and the edges the tracer is told about, against the pattern.
#include <catch2/catch.hpp>

#include <random>

#include "asos/render/brick_pattern.hpp"
#include "asos/render/pattern_edges.hpp"
#include "asos/render/shading.hpp"

using namespace asos;

namespace {

// POV-Ray's defaults: brick_size <8, 3, 4.5>, mortar 0.5. The pattern is
// moved by 0.5 + 1e-10, so in course 0 (y in (0, 2.5)) the joints are
// x in [-0.5, 0] + 8k and z in [1.75, 2.25] + 4.5k; in course 1 (y in
// (3, 5.5)) x in [3.5, 4] + 8k and z in [-0.5, 0] + 4.5k; the bed joints
// y in [-0.5, 0] + 3k.
const BrickPattern kDefault({8.0, 3.0, 4.5}, 0.5);

}  // namespace

TEST_CASE("Brick is brick inside a brick and mortar in the joints", "[shading][brick]") {
    CHECK(kDefault.value({4.0, 1.0, 0.0}) == 1);
    CHECK(kDefault.value({4.0, 2.4, 1.0}) == 1);
    // A bed joint, under course 0 and under course 1.
    CHECK(kDefault.value({4.0, -0.25, 0.0}) == 0);
    CHECK(kDefault.value({4.0, 2.75, 0.0}) == 0);
    // Head joints of course 0, across x and across z.
    CHECK(kDefault.value({-0.25, 1.0, 1.0}) == 0);
    CHECK(kDefault.value({7.75, 1.0, 1.0}) == 0);
    CHECK(kDefault.value({2.0, 1.0, 2.0}) == 0);
}

TEST_CASE("Brick shifts alternate courses by half a brick", "[shading][brick]") {
    // Course 0's head joint along x is inside a brick of course 1, and the
    // other way round.
    CHECK(kDefault.value({-0.25, 1.0, 1.0}) == 0);
    CHECK(kDefault.value({-0.25, 4.0, 1.0}) == 1);
    CHECK(kDefault.value({3.75, 1.0, 1.0}) == 1);
    CHECK(kDefault.value({3.75, 4.0, 1.0}) == 0);
    // The same along z.
    CHECK(kDefault.value({2.0, 1.0, 2.0}) == 0);
    CHECK(kDefault.value({2.0, 4.0, 2.0}) == 1);
    CHECK(kDefault.value({2.0, 1.0, -0.25}) == 1);
    CHECK(kDefault.value({2.0, 4.0, -0.25}) == 0);
    // Course 2 repeats course 0.
    CHECK(kDefault.value({-0.25, 7.0, 1.0}) == 0);
    CHECK(kDefault.value({3.75, 7.0, 1.0}) == 1);
}

TEST_CASE("Brick continues below zero as above", "[shading][brick]") {
    // Course -1 (y in (-3, -0.5)) is odd: its joints are course 1's.
    CHECK(kDefault.value({-4.25, -2.0, 1.0}) == 0);
    CHECK(kDefault.value({-4.75, -2.0, 1.0}) == 1);
    CHECK(kDefault.value({-0.25, -2.0, 1.0}) == 1);
    // Course -2 (y in (-5.5, -3.5)) is even: course 0's joints.
    CHECK(kDefault.value({-0.25, -4.5, 1.0}) == 0);
    CHECK(kDefault.value({-8.25, -4.5, 1.0}) == 0);
    CHECK(kDefault.value({-4.25, -4.5, 1.0}) == 1);
    // The bed joint between them, and head joints along negative z.
    CHECK(kDefault.value({2.0, -3.25, 1.0}) == 0);
    CHECK(kDefault.value({2.0, 1.0, -2.5}) == 0);
    CHECK(kDefault.value({2.0, 4.0, -2.5}) == 1);
}

TEST_CASE("Brick's joints end where POV-Ray's do", "[shading][brick]") {
    // Measured with povray 3.7 (a one-pixel orthographic render of the plane
    // z = 2 at (2, y), brick rgb 0, rgb 1 brick_size <10, 1, 10> mortar 0.3):
    // the bed joint is y in [-m - 1e-10, -1e-10] with m the mortar as a
    // float, 0.30000001192...: a double 0.3 would call y = -0.300000005 brick.
    const BrickPattern p({10.0, 1.0, 10.0}, 0.3);
    CHECK(p.value({2.0, -0.300000005, 2.0}) == 0);
    CHECK(p.value({2.0, -0.30000001, 2.0}) == 0);
    CHECK(p.value({2.0, -0.300000015, 2.0}) == 1);
    CHECK(p.value({2.0, -1.5e-10, 2.0}) == 0);
    CHECK(p.value({2.0, -5e-11, 2.0}) == 1);
    CHECK(p.value({2.0, 0.5, 2.0}) == 1);
    CHECK(p.value({2.0, -0.7, 2.0}) == 1);
    // No mortar at all: POV-Ray's 0 - 2e-10 is below every fraction.
    const BrickPattern none({1.0, 1.0, 1.0}, 0.0);
    for (double t = -2.0; t < 2.0; t += 0.125) CHECK(none.value({t, t, t}) == 1);
}

TEST_CASE("A brick pigment is its second colour in the bricks, its first in the mortar", "[shading][brick]") {
    Pigment p;
    p.kind = Pigment::Kind::Brick;
    p.color1.rgb = {0.5, 0.5, 0.5};
    p.color2.rgb = {0.6, 0.15, 0.15};
    p.worldFromPattern = Transform::scale(Vec3(0.1));
    CHECK(evaluatePigment(p, {0.4, 0.1, 0.0}).rgb == p.color2.rgb);   // pattern point (4, 1, 0)
    CHECK(evaluatePigment(p, {0.4, -0.025, 0.0}).rgb == p.color1.rgb); // (4, -0.25, 0)
    CHECK(pigmentIndex(p, {0.4, 0.1, 0.0}) == 1);
    CHECK(pigmentIndex(p, {0.4, -0.025, 0.0}) == 0);
    CHECK(hasPattern(p));
    p.color2 = p.color1;
    CHECK_FALSE(hasPattern(p));
}

TEST_CASE("Brick counts the joint faces a box straddles", "[shading][brick]") {
    // Inside one brick; inside one bed joint, however far along x and z.
    CHECK(kDefault.edgesCrossed({3.0, 0.5, 0.5}, {5.0, 1.5, 1.0}) == 0.0);
    CHECK(kDefault.edgesCrossed({-1.0, -0.4, -1.0}, {10.0, -0.1, 5.0}) == 0.0);
    // One face: the top of a bed joint (clear of the head joints of the
    // courses on either side), or one side of a head joint.
    CHECK(kDefault.edgesCrossed({1.0, -0.1, 0.5}, {3.0, 0.2, 1.0}) == 1.0);
    CHECK(kDefault.edgesCrossed({-0.1, 1.0, 0.5}, {0.2, 2.0, 1.0}) == 1.0);
    // Both sides of a head joint; two courses.
    CHECK(kDefault.edgesCrossed({-0.6, 1.0, 0.5}, {0.2, 2.0, 1.0}) == 2.0);
    CHECK(kDefault.edgesCrossed({3.0, 1.0, 0.5}, {5.0, 4.0, 1.0}) >= 2.0);
}

TEST_CASE("Where brick changes inside a box, the box straddles an edge", "[shading][brick]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> corner(-20.0, 20.0), extent(0.0, 2.0), size(0.5, 6.0),
        mortar(0.0, 0.8);
    int changing = 0, still = 0;
    for (int i = 0; i < 2000; ++i) {
        const BrickPattern p({size(rng), size(rng), size(rng)}, mortar(rng));
        const Vec3 lo(corner(rng), corner(rng), corner(rng));
        const Vec3 hi = lo + Vec3(extent(rng), extent(rng), extent(rng));
        const double edges = p.edgesCrossed(lo, hi);
        const int first = p.value(lo);
        bool changes = false;
        for (int a = 0; a <= 6; ++a)
            for (int b = 0; b <= 6; ++b)
                for (int c = 0; c <= 6; ++c)
                    changes = changes || p.value(lo + (hi - lo) * Vec3(a, b, c) / 6.0) != first;
        INFO("box " << i);
        if (changes) CHECK(edges > 0.0);
        (changes ? changing : still) += 1;
    }
    // Both kinds of box were met.
    CHECK(changing > 200);
    CHECK(still > 200);
}

namespace {

// The share of brick over the box [lo, hi] by n^3 points at the centres of
// its cells (within about 1/n per joint face the box straddles).
double denseBrickShare(const BrickPattern& p, const Vec3& lo, const Vec3& hi, int n) {
    long ones = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                ones += p.value(lo + Vec3((i + 0.5) / n, (j + 0.5) / n, (k + 0.5) / n) * (hi - lo));
    return double(ones) / (double(n) * n * n);
}

}  // namespace

TEST_CASE("Brick's edge planes hold every change of its value", "[shading][brick]") {
    // Between two consecutive planes of an axis, along a line parallel to
    // it, the value does not change; sizes of both signs, thin and thick
    // mortar.
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> corner(-20.0, 20.0), size(0.5, 6.0), mortar(0.0, 1.2);
    for (int i = 0; i < 200; ++i) {
        const Vec3 s(size(rng) * (i % 2 ? -1.0 : 1.0), size(rng), size(rng) * (i % 3 ? 1.0 : -1.0));
        const BrickPattern p(s, mortar(rng));
        const Vec3 base(corner(rng), corner(rng), corner(rng));
        const int axis = i % 3;
        const double lo = base[axis], hi = lo + 15.0;
        std::vector<double> cuts{lo};
        p.planes(axis).forEachInside(lo, hi, [&](double plane) { cuts.push_back(plane); });
        cuts.push_back(hi);
        for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
            INFO("case " << i << ", axis " << axis << ", between " << cuts[c] << " and " << cuts[c + 1]);
            REQUIRE(cuts[c + 1] >= cuts[c]);  // two sides may meet (a joint of half a brick)
            if (cuts[c + 1] == cuts[c]) continue;
            Vec3 point = base;
            const double margin = 1e-7 * (cuts[c + 1] - cuts[c]);
            point[axis] = cuts[c] + margin;
            const int value = p.value(point);
            for (int k = 1; k <= 8; ++k) {
                point[axis] = cuts[c] + margin + (cuts[c + 1] - cuts[c] - 2.0 * margin) * k / 8.0;
                CHECK(p.value(point) == value);
            }
        }
    }
}

TEST_CASE("Brick's box share has its known answers", "[shading][brick]") {
    // kDefault, course 0: bricks over y in (0, 2.5), head joints at
    // x in [-0.5, 0] + 8k and z in [1.75, 2.25] + 4.5k.
    CHECK(kDefault.boxShare({1.0, 0.5, 0.0}, {6.0, 2.0, 1.5}) == 1.0);  // inside a brick
    CHECK(kDefault.boxShare({1.0, -0.4, 0.0}, {6.0, -0.1, 1.5}) == 0.0);  // inside a bed joint
    // Across the top of a bed joint: a quarter of the box in the joint.
    CHECK(kDefault.boxShare({1.0, -0.25, 0.0}, {6.0, 0.75, 1.5}) == Approx(0.75));
    // Across a head joint along x, [-0.5, 0] of [-1, 1]: a quarter mortar.
    CHECK(kDefault.boxShare({-1.0, 0.5, 0.0}, {1.0, 2.0, 1.5}) == Approx(0.75));
    // Across the corner of a bed and a head joint: y [-0.25, 0.75] (a
    // quarter in the bed joint), x [-0.25, 0.25] (half in the head joint).
    CHECK(kDefault.boxShare({-0.25, -0.25, 0.0}, {0.25, 0.75, 1.5}) == Approx(0.75 * 0.5));
    // Many bricks: the share of brick in a whole period of courses.
    const double mean = (1.0 - 0.5 / 3.0) * (1.0 - 0.5 / 8.0) * (1.0 - 0.5 / 4.5);
    CHECK(kDefault.boxShare({-0.5, -0.5, -0.5}, {-0.5 + 80.0, -0.5 + 60.0, -0.5 + 45.0}) == Approx(mean));
    CHECK(kDefault.boxShare({-3000.3, -2000.1, -4000.7}, {3000.9, 2000.6, 4000.2}) ==
          Approx(mean).margin(1e-4));
    // A box of no width along y, in course 0: the head joints' pattern.
    CHECK(kDefault.boxShare({-0.5, 1.0, -0.5}, {-0.5 + 80.0, 1.0, -0.5 + 45.0}) ==
          Approx((1.0 - 0.5 / 8.0) * (1.0 - 0.5 / 4.5)));
    // No width along z either: along x through course 1's head joints at
    // x in [3.5, 4] + 8k.
    CHECK(kDefault.boxShare({0.0, 4.0, 1.0}, {8.0, 4.0, 1.0}) == Approx(1.0 - 0.5 / 8.0));
    CHECK(kDefault.boxShare({3.0, 4.0, 1.0}, {4.0, 4.0, 1.0}) == Approx(0.5));
}

TEST_CASE("Brick's box share matches dense sampling of the box", "[shading][brick]") {
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> corner(-10.0, 10.0), width(0.1, 4.0), size(1.0, 5.0),
        mortar(0.1, 0.7);
    for (int i = 0; i < 20; ++i) {
        const BrickPattern p({size(rng), size(rng), size(rng)}, mortar(rng));
        const Vec3 lo(corner(rng), corner(rng), corner(rng));
        const Vec3 hi = lo + Vec3(width(rng), width(rng), width(rng));
        INFO("case " << i);
        CHECK(p.boxShare(lo, hi) == Approx(denseBrickShare(p, lo, hi, 96)).margin(0.015));
    }
}
