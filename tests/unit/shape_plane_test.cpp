#include <catch2/catch.hpp>

#include <cmath>

#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive plane(Vec3 normal, double distance, const Transform& t = {}) {
    return Primitive::make(PlaneShape{normal, distance}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Plane ray hits follow POV-Ray's normal and distance", "[shapes][plane]") {
    // The distance is along the normalised normal: plane { <0,2,0>, 2 } is y = 2.
    const Primitive p = plane({0, 2, 0}, 2.0);
    CHECK_FALSE(p.bounded());
    auto hit = p.intersect({{0, 0, 0}, {0, 1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
    CHECK(near(hit->normal, {0, 1, 0}));
    // From above: the same (outward) normal.
    hit = p.intersect({{1, 5, 1}, {0, -1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(3.0));
    CHECK(near(hit->normal, {0, 1, 0}));
    CHECK(near(hit->objectPoint, {1, 2, 1}));
    CHECK_FALSE(p.intersect({{0, 0, 0}, {1, 0, 0}}, 0.0, kInfinity));   // parallel
    CHECK_FALSE(p.intersect({{0, 0, 0}, {0, -1, 0}}, 0.0, kInfinity));  // away
    CHECK_FALSE(p.intersectAny({{0, 0, 0}, {0, 1, 0}}, 0.0, 1.5));
    // Far away, grazing.
    const Vec3 d = glm::normalize(Vec3(1e5, 2.0, 0));
    hit = p.intersect({{0, 0, 0}, d}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.y == Approx(2.0).epsilon(1e-12));
    CHECK(hit->position.x == Approx(1e5).epsilon(1e-12));
    // rotate x*90 takes +y to +z: the plane becomes z = 2.
    const Primitive r = plane({0, 1, 0}, 2.0, Transform::rotateDegrees({90, 0, 0}));
    hit = r.intersect({{0, 0, 0}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
    CHECK(near(hit->normal, {0, 0, 1}));
}

TEST_CASE("Plane cone classification: known answers", "[shapes][plane]") {
    const Primitive p = plane({0, 1, 0}, 0.0);
    Cone c;
    c.apex = {0, 1, 0};
    c.axis = {0, -1, 0};
    c.halfAngle = 0.5;
    ConeClass k = p.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear == Approx(1.0).epsilon(1e-8));
    CHECK(k.tFar == Approx(1.0 / std::cos(0.5)).epsilon(1e-8));
    // Looking at the horizon: the boundary is one straight line.
    c.axis = {1, 0, 0};
    c.halfAngle = 0.1;
    k = p.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK(k.singleEdge);
    // ... unless a far end of the range cuts the footprint too.
    c.tMax = 100.0;
    k = p.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK_FALSE(k.singleEdge);
    c.tMax = kInfinity;
    c.axis = {0, 1, 0};
    CHECK(p.classify(c).coverage == Coverage::Miss);
    // All crossings beyond tMax: a miss; the footprint cut by tMax: marginal.
    c.axis = {0, -1, 0};
    c.tMax = 0.9;
    CHECK(p.classify(c).coverage == Coverage::Miss);
    c.tMax = 1.002;  // crossings lie in [1, 1/cos(0.1)]
    CHECK(p.classify(c).coverage == Coverage::Marginal);
    // A shadow cone from a point on the plane, leaving it: a miss.
    c = Cone{};
    c.apex = {3, 0, 4};
    c.axis = glm::normalize(Vec3(1, 1, 0));
    c.halfAngle = 0.3;
    c.tMin = 1e-6;
    CHECK(p.classify(c).coverage == Coverage::Miss);
    // Wider than a hemisphere from above the plane: every direction near -y
    // hits, those near +y do not.
    c.apex = {0, 1, 0};
    c.axis = {0, -1, 0};
    c.halfAngle = 2.0;
    c.tMin = 0.0;
    CHECK(p.classify(c).coverage == Coverage::Marginal);
}

TEST_CASE("Plane degenerate input", "[shapes][plane]") {
    CHECK_THROWS_WITH(plane({0, 0, 0}, 1.0), "the normal of a plane must not be zero");
    CHECK_THROWS_WITH(plane({0, 1, 0}, std::nan("")), "the distance of a plane must be finite, not nan");
}

TEST_CASE("Plane cone classification is conservative (property)", "[shapes][plane][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("plane", 0x91a7e000ull, 100000, [](Rng& rng) {
        ShapeCase sc;
        const Vec3 normal = rng.unitVector() * rng.uniform(0.5, 2.0);
        const double distance = rng.uniform(-3, 3);
        sc.shape = PlaneShape{normal, distance};
        sc.size = 1.0;
        const Vec3 n = glm::normalize(normal);
        const Mat3 frame = frameAroundAxis(n);
        sc.surfacePoint = [=](Rng& r) {
            return distance * n + r.uniform(-5, 5) * frame[0] + r.uniform(-5, 5) * frame[1];
        };
        sc.text = "plane { " + fmt(normal) + ", " + fmt(distance) + " }";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}
