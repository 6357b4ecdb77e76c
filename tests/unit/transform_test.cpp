#include <catch2/catch.hpp>

#include "asos/geometry/transform.hpp"

using namespace asos;

namespace {
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) {
    return glm::length(a - b) <= tol;
}
}  // namespace

TEST_CASE("POV-Ray rotations are left-handed and exact at right angles", "[transform]") {
    // rotate y*90 takes +x to -z in POV-Ray; rotate x*90 takes +y to +z; rotate z*90 takes +x to +y.
    CHECK(Transform::rotateDegrees({0, 90, 0}).point({1, 0, 0}) == Vec3(0, 0, -1));
    CHECK(Transform::rotateDegrees({90, 0, 0}).point({0, 1, 0}) == Vec3(0, 0, 1));
    CHECK(Transform::rotateDegrees({0, 0, 90}).point({1, 0, 0}) == Vec3(0, 1, 0));
    // x is applied before y: <1,0,0> -> (x 90) <1,0,0> -> (y 90) <0,0,-1>.
    CHECK(Transform::rotateDegrees({90, 90, 0}).point({1, 0, 0}) == Vec3(0, 0, -1));
    const Transform r = Transform::rotateDegrees({30, 40, 50});
    CHECK(near(r.inverse().point(r.point({1, 2, 3})), {1, 2, 3}));
}

TEST_CASE("POV-Ray matrix keyword round-trips and uses row vectors", "[transform]") {
    const double v[12] = {1, 2, 0, 0, 1, 0, 0, 0, 3, 4, 5, 6};
    const Transform t = Transform::fromPovMatrix(v);
    // p' = p * M: <1,1,1> -> <1+0+0+4, 2+1+0+5, 0+0+3+6>
    CHECK(t.point({1, 1, 1}) == Vec3(5, 8, 9));
    double back[12];
    t.toPovMatrix(back);
    for (int i = 0; i < 12; ++i) CHECK(back[i] == v[i]);
    CHECK(near(t.inverse().point(t.point({0.3, -2, 7})), {0.3, -2, 7}));
}

TEST_CASE("Composition applies the right operand first", "[transform]") {
    const Transform t = Transform::translate({1, 0, 0}) * Transform::scale({2, 2, 2});
    CHECK(t.point({1, 1, 1}) == Vec3(3, 2, 2));
    CHECK(near(t.inverse().point({3, 2, 2}), {1, 1, 1}));
    const Bounds3 b = Transform::rotateDegrees({0, 0, 90}).bounds({{0, 0, 0}, {1, 2, 3}});
    CHECK(near(b.lo, {-2, 0, 0}));
    CHECK(near(b.hi, {0, 1, 3}));
}
