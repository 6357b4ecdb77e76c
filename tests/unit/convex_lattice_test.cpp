#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <random>
#include <sstream>
#include <vector>

#include "asos/render/convex_lattice.hpp"

using namespace asos;

namespace {

// Convex sets over the lattice in exact integer arithmetic: a lattice point
// (i, j) is the point (kScale i, kScale j), and a set is an intersection of
// half-planes a x + b y <= c or a disc, all with integer coefficients, so
// that membership is exactly that of a convex set.
constexpr std::int64_t kScale = 1000;

struct HalfPlane {
    std::int64_t a, b, c;
    bool holds(std::int64_t x, std::int64_t y) const { return a * x + b * y <= c; }
};

struct ConvexSet {
    std::vector<HalfPlane> planes;
    bool disc = false;
    std::int64_t cx = 0, cy = 0, r = 0;
    std::string what;

    bool contains(int i, int j) const {
        const std::int64_t x = kScale * i, y = kScale * j;
        if (disc && (x - cx) * (x - cx) + (y - cy) * (y - cy) > r * r) return false;
        for (const HalfPlane& h : planes)
            if (!h.holds(x, y)) return false;
        return true;
    }
};

// Checks the lattice's answer against every point, and that no point was
// asked twice; returns how many tests it made.
int checkLattice(const ConvexSet& set, int columns, int rows) {
    std::array<int, ConvexLattice::kMaxSide * ConvexLattice::kMaxSide> asked{};
    int calls = 0;
    const ConvexLattice lattice(columns, rows, [&](int i, int j) {
        REQUIRE(i >= 0);
        REQUIRE(i < columns);
        REQUIRE(j >= 0);
        REQUIRE(j < rows);
        ++asked[j * ConvexLattice::kMaxSide + i];
        ++calls;
        return set.contains(i, j);
    });
    INFO(set.what << " on " << columns << " x " << rows);
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            INFO("point (" << i << ", " << j << ")");
            REQUIRE(lattice.member(i, j) == set.contains(i, j));
            REQUIRE(asked[j * ConvexLattice::kMaxSide + i] <= 1);
        }
    REQUIRE(lattice.tests() == calls);
    REQUIRE(calls <= columns * rows);
    return calls;
}

// A half-plane whose boundary passes through (x, y) with a random normal.
HalfPlane randomHalfPlane(std::mt19937_64& rng, std::int64_t x, std::int64_t y) {
    std::uniform_int_distribution<std::int64_t> coefficient(-1000, 1000);
    std::int64_t a = 0, b = 0;
    while (a == 0 && b == 0) {
        a = coefficient(rng);
        b = coefficient(rng);
    }
    return {a, b, a * x + b * y};
}

ConvexSet randomSet(std::mt19937_64& rng, int columns, int rows) {
    std::uniform_int_distribution<int> kind(0, 5);
    const std::int64_t w = kScale * (columns - 1), h = kScale * (rows - 1);
    std::uniform_int_distribution<std::int64_t> px(-2 * kScale, w + 2 * kScale), py(-2 * kScale, h + 2 * kScale);
    ConvexSet s;
    std::ostringstream what;
    switch (kind(rng)) {
        case 0: {  // one straight boundary
            s.planes.push_back(randomHalfPlane(rng, px(rng), py(rng)));
            what << "half-plane";
            break;
        }
        case 1: {  // a convex polygon: several half-planes
            const int n = std::uniform_int_distribution<int>(2, 6)(rng);
            for (int k = 0; k < n; ++k) s.planes.push_back(randomHalfPlane(rng, px(rng), py(rng)));
            what << n << " half-planes";
            break;
        }
        case 2: {  // a disc
            s.disc = true;
            s.cx = px(rng);
            s.cy = py(rng);
            s.r = std::uniform_int_distribution<std::int64_t>(0, 8 * kScale)(rng);
            what << "disc";
            break;
        }
        case 3: {  // a sliver: a strip narrower than the lattice's step, often between its points
            HalfPlane p = randomHalfPlane(rng, px(rng), py(rng));
            const std::int64_t width = std::uniform_int_distribution<std::int64_t>(0, 3000)(rng);
            s.planes.push_back(p);
            s.planes.push_back({-p.a, -p.b, -p.c + width});
            what << "strip";
            break;
        }
        case 4: {  // a small triangle or a single point
            const std::int64_t x = px(rng), y = py(rng);
            for (int k = 0; k < 3; ++k) {
                std::uniform_int_distribution<std::int64_t> offset(-800, 800);
                s.planes.push_back(randomHalfPlane(rng, x + offset(rng), y + offset(rng)));
            }
            what << "small triangle";
            break;
        }
        default: {  // a thin wedge: two half-planes through one point
            const std::int64_t x = px(rng), y = py(rng);
            s.planes.push_back(randomHalfPlane(rng, x, y));
            s.planes.push_back(randomHalfPlane(rng, x, y));
            what << "wedge";
            break;
        }
    }
    for (const HalfPlane& p : s.planes) what << " [" << p.a << " " << p.b << " " << p.c << "]";
    if (s.disc) what << " centre " << s.cx << " " << s.cy << " radius " << s.r;
    s.what = what.str();
    return s;
}

}  // namespace

TEST_CASE("Convex lattice: every point as a test of each would give it", "[convex_lattice]") {
    std::mt19937_64 rng(20261126);
    const int sides[] = {1, 2, 3, 4, 5, 8, 13, 16};
    for (const int columns : sides)
        for (const int rows : sides)
            for (int k = 0; k < 400; ++k) checkLattice(randomSet(rng, columns, rows), columns, rows);
}

TEST_CASE("Convex lattice: empty, full, one point, one row, one column", "[convex_lattice]") {
    ConvexSet none;
    none.planes.push_back({0, 1, -1});  // y <= -1
    ConvexSet all;
    all.planes.push_back({0, 0, 0});
    ConvexSet point;
    point.disc = true;
    point.cx = 3 * kScale;
    point.cy = 5 * kScale;
    point.r = 10;
    ConvexSet row;  // y = 4: a strip of zero width
    row.planes = {{0, 1, 4 * kScale}, {0, -1, -4 * kScale}};
    ConvexSet column;  // x = 7
    column.planes = {{1, 0, 7 * kScale}, {-1, 0, -7 * kScale}};
    for (const ConvexSet* s : {&none, &all, &point, &row, &column}) {
        CHECK(checkLattice(*s, 8, 8) <= 64);
        CHECK(checkLattice(*s, 16, 16) <= 256);
        CHECK(checkLattice(*s, 16, 1) <= 16);
    }
    // A full lattice is known from its boundary rows' ends and one column
    // beside each interpolated run: far fewer tests than points.
    CHECK(checkLattice(all, 8, 8) <= 16);
}

TEST_CASE("Convex lattice: a straight boundary costs about a quarter of the points", "[convex_lattice]") {
    // Lines through the middle of an 8 x 8 lattice (the shadow edge across a
    // light piece): the mean number of tests, against 64 points. The figure
    // is a property of the search, the same on every machine.
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<std::int64_t> inner(0, 7 * kScale);
    double total = 0.0;
    const int cases = 2000;
    for (int k = 0; k < cases; ++k) {
        ConvexSet s;
        s.planes.push_back(randomHalfPlane(rng, inner(rng), inner(rng)));
        s.what = "half-plane";
        total += checkLattice(s, 8, 8);
    }
    const double mean = total / cases;
    INFO("mean tests " << mean);
    CHECK(mean < 20.0);
}
