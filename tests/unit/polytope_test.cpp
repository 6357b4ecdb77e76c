#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "asos/geometry/polytope.hpp"

using namespace asos;

namespace {

const Bounds3 kBig{Vec3(-100.0), Vec3(100.0)};

bool near(const Vec3& a, const Vec3& b) { return glm::length(a - b) < 1e-9; }

bool holds(const std::vector<Vec3>& points, const Vec3& p) {
    for (const Vec3& q : points)
        if (near(p, q)) return true;
    return false;
}

}  // namespace

TEST_CASE("polytopeVertices finds the corners of a cube of six planes", "[geometry][polytope]") {
    const std::vector<HalfSpace> cube{{{1, 0, 0}, 1}, {{-1, 0, 0}, 1}, {{0, 2, 0}, 2},
                                      {{0, -1, 0}, 1}, {{0, 0, 1}, 1}, {{0, 0, -1}, 1}};
    const auto vertices = polytopeVertices(cube, kBig);
    REQUIRE(vertices);
    for (int i = 0; i < 8; ++i)
        CHECK(holds(*vertices, Vec3((i & 1) ? 1 : -1, (i & 2) ? 1 : -1, (i & 4) ? 1 : -1)));
    // None beyond the cube (each corner is met by three triples of planes
    // at most, all at the same point).
    for (const Vec3& v : *vertices) CHECK(glm::all(glm::lessThanEqual(glm::abs(v), Vec3(1.0 + 1e-12))));
}

TEST_CASE("polytopeVertices cuts the box by the half-spaces", "[geometry][polytope]") {
    // The half-space x + y + z <= 0 cuts the cube [-1, 1]^3 through its
    // centre: the corner (-1, -1, -1) stays, (1, 1, 1) goes, and the cut's
    // corners lie on the plane.
    const std::vector<HalfSpace> cut{{{1, 1, 1}, 0}};
    const auto vertices = polytopeVertices(cut, Bounds3{Vec3(-1.0), Vec3(1.0)});
    REQUIRE(vertices);
    CHECK(holds(*vertices, Vec3(-1, -1, -1)));
    CHECK_FALSE(holds(*vertices, Vec3(1, 1, 1)));
    CHECK(holds(*vertices, Vec3(1, -1, 0)));
    for (const Vec3& v : *vertices) CHECK(v.x + v.y + v.z <= 1e-9);
}

TEST_CASE("polytopeVertices: an unbounded polytope reaches the box, an empty one has none", "[geometry][polytope]") {
    const std::vector<HalfSpace> slab{{{1, 0, 0}, 1}, {{-1, 0, 0}, 1}};
    const auto open = polytopeVertices(slab, kBig);
    REQUIRE(open);
    bool reaches = false;
    for (const Vec3& v : *open) reaches |= std::abs(v.y) == 100.0;
    CHECK(reaches);
    const std::vector<HalfSpace> none{{{1, 0, 0}, -1}, {{-1, 0, 0}, -1}};
    const auto empty = polytopeVertices(none, kBig);
    REQUIRE(empty);
    CHECK(empty->empty());
    CHECK_FALSE(polytopeVertices(slab, Bounds3{Vec3(-1.0), Vec3(kInfinity)}));
}
