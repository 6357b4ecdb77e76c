#include <catch2/catch.hpp>

#include <cmath>

#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive sphere(Vec3 center, double radius, const Transform& t = {}) {
    return Primitive::make(SphereShape{center, radius}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Sphere ray hits from outside, inside, tangent and far away", "[shapes][sphere]") {
    const Primitive s = sphere({0, 0, 0}, 1.0);
    auto hit = s.intersect({{0, 0, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(hit->position, {0, 0, -1}));
    CHECK(near(hit->normal, {0, 0, -1}));
    CHECK(hit->objectIndex == -1);

    // From inside, the exit, with the outward normal.
    hit = s.intersect({{0, 0, 0}, {0, 1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1.0));
    CHECK(near(hit->normal, {0, 1, 0}));

    // Tangent: exactly grazing hits, a hair outside misses.
    hit = s.intersect({{1, 0, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(5.0));
    CHECK_FALSE(s.intersect({{1.0 + 1e-9, 0, -5}, {0, 0, 1}}, 0.0, kInfinity));

    // The t-interval picks the hit inside it.
    CHECK_FALSE(s.intersect({{0, 0, -5}, {0, 0, 1}}, 0.0, 3.9));
    hit = s.intersect({{0, 0, -5}, {0, 0, 1}}, 4.5, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(6.0));
    CHECK(s.intersectAny({{0, 0, -5}, {0, 0, 1}}, 4.5, kInfinity));
    CHECK_FALSE(s.intersectAny({{0, 0, -5}, {0, 0, 1}}, 6.5, kInfinity));

    // 1e5 units away, off-axis: t = d cos(b) - sqrt(r^2 - d^2 sin^2(b)).
    const Primitive far = sphere({0, 0, 1e5}, 1.0);
    const double b = 0.5e-5;
    const Vec3 dir(std::sin(b), 0, std::cos(b));
    hit = far.intersect({{0, 0, 0}, dir}, 0.0, kInfinity);
    REQUIRE(hit);
    const double expected = 1e5 * std::cos(b) - std::sqrt(1.0 - 1e10 * std::sin(b) * std::sin(b));
    CHECK(std::abs(hit->t - expected) < 1e-9);
    CHECK(std::abs(glm::length(hit->position - Vec3(0, 0, 1e5)) - 1.0) < 1e-9);
}

TEST_CASE("Sphere under transforms: ellipsoid normals and object points", "[shapes][sphere]") {
    // scale <2,1,1>: an ellipsoid with semi-axes 2, 1, 1.
    const Primitive e = sphere({0, 0, 0}, 1.0, Transform::scale({2, 1, 1}));
    auto hit = e.intersect({{-5, 0, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(3.0));
    CHECK(near(hit->normal, {-1, 0, 0}));
    CHECK(near(hit->objectPoint, {-1, 0, 0}));
    // At (sqrt(2), sqrt(0.5), 0) the normal is along (x/4, y, 0).
    const Vec3 p(std::sqrt(2.0), std::sqrt(0.5), 0);
    hit = e.intersect({{p.x, 5, 0}, {0, -1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->position, p, 1e-12));
    CHECK(near(hit->normal, glm::normalize(Vec3(p.x / 4, p.y, 0)), 1e-12));
    // Translated and rotated: the object point stays in object space.
    const Primitive t = sphere({1, 0, 0}, 0.5, Transform::translate({0, 3, 0}) *
                                                   Transform::rotateDegrees({0, 0, 90}));
    hit = t.intersect({{0, 1, 0}, {0, 1, 0}}, 0.0, kInfinity);  // centre at (0, 4, 0)
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.5));
    CHECK(near(hit->objectPoint, {0.5, 0, 0}));
    CHECK(t.worldBounds().contains({0, 4.4999, 0}));
    CHECK(near(t.worldBounds().lo, {-0.5, 3.5, -0.5}, 1e-9));
}

TEST_CASE("Sphere cone classification: known answers", "[shapes][sphere]") {
    const Primitive s = sphere({0, 0, 0}, 1.0);
    const double tangent = std::asin(0.1);  // seen from 10 units away
    Cone c;
    c.apex = {0, 0, -10};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.5 * tangent;
    ConeClass k = s.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear == Approx(9.0).epsilon(1e-6));
    CHECK(k.tFar <= std::sqrt(99.0));
    c.halfAngle = 1.5 * tangent;
    CHECK(s.classify(c).coverage == Coverage::Marginal);
    CHECK_FALSE(s.classify(c).singleEdge);
    c.axis = {std::sin(0.3), 0, std::cos(0.3)};
    c.halfAngle = 0.1;
    CHECK(s.classify(c).coverage == Coverage::Miss);
    // A Full cone whose hits all lie beyond tMax misses; one cut by tMax is marginal.
    c.axis = {0, 0, 1};
    c.halfAngle = 0.01;
    c.tMax = 8.9;
    CHECK(s.classify(c).coverage == Coverage::Miss);
    c.tMax = 9.0005;
    CHECK(s.classify(c).coverage == Coverage::Marginal);
    // From inside every ray leaves between r - d and r + d.
    c = Cone{};
    c.apex = {0, 0, 0.5};
    c.axis = {1, 0, 0};
    c.halfAngle = 1.0;
    k = s.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear >= 0.5 - 1e-9);
    CHECK(k.tFar <= 1.5 + 1e-9);
    // A shadow cone leaving the lit side of the surface it starts on misses.
    c.apex = {0, 0, 1};
    c.axis = glm::normalize(Vec3(0.3, 0, 1));
    c.halfAngle = 0.2;
    c.tMin = 1e-6;
    CHECK(s.classify(c).coverage == Coverage::Miss);
    c.axis = glm::normalize(Vec3(1, 0, 0.01));  // straddles the tangent plane
    CHECK(s.classify(c).coverage == Coverage::Marginal);
}

TEST_CASE("Sphere degenerate input has defined answers", "[shapes][sphere]") {
    CHECK_THROWS_WITH(sphere({0, 0, 0}, -1.0), "the radius of a sphere must be positive, not -1");
    CHECK_THROWS_WITH(sphere({0, 0, 0}, 0.0), "the radius of a sphere must be positive, not 0");
    CHECK_THROWS_WITH(sphere({0, 0, 0}, kInfinity), "the radius of a sphere must be finite, not inf");
    CHECK_THROWS_WITH(sphere({0, std::nan(""), 0}, 1.0), "the centre of a sphere must be finite, not <0, nan, 0>");
    CHECK_THROWS_WITH(sphere({0, 0, 0}, 1.0, Transform::scale({1, 0, 1})),
                      Catch::Contains("singular"));
    // The empty sphere, which Primitive::make refuses, still answers.
    const Sphere empty(0.0);
    CHECK_FALSE(empty.intersect(Ray{{0, 0, -5}, {0, 0, 1}}, 0.0, kInfinity));
    CHECK(empty.classify(shapetest::localCone({0, 0, -5}, {0, 0, 1}, 0.5)).coverage == Coverage::Miss);
    Cone c;
    c.apex = {0, 0, -5};
    const Primitive s = sphere({0, 0, 0}, 1.0);
    // A ray-thin cone along a hitting ray is Full.
    c.halfAngle = 0.0;
    CHECK(s.classify(c).coverage == Coverage::Full);
    // Wider than a hemisphere: marginal, never NaN.
    c.halfAngle = 2.5;
    const ConeClass wide = s.classify(c);
    CHECK(wide.coverage == Coverage::Marginal);
    CHECK_FALSE(std::isnan(wide.tNear + wide.tFar));
    // Not a cone at all.
    c.apex = {std::nan(""), 0, 0};
    const ConeClass bad = s.classify(c);
    CHECK(bad.coverage == Coverage::Marginal);
    CHECK_FALSE(std::isnan(bad.tNear + bad.tFar));
}

namespace {
shapetest::ShapeCase randomSphere(shapetest::Rng& rng) {
    using namespace shapetest;
    ShapeCase sc;
    const Vec3 center(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
    const double radius = rng.logUniform(-1.0, 1.0);
    sc.shape = SphereShape{center, radius};
    sc.size = radius;
    sc.surfacePoint = [=](Rng& r) { return center + radius * r.unitVector(); };
    sc.text = "sphere { " + fmt(center) + ", " + fmt(radius) + " }";
    return sc;
}
}  // namespace

TEST_CASE("Sphere cone classification is conservative (property)", "[shapes][sphere][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("sphere", 0x5b11e7e5ull, 100000, randomSphere);
    CHECK(stats.failures == 0);
    CHECK(stats.leave > 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}

// Ellipsoids alone (non-uniform scales and general matrices), where
// Sphere::classifyAcrossScale answers in world terms before the bounding-cone
// path: its Miss and Full must stay conservative too.
TEST_CASE("Sphere cone classification under non-uniform scales is conservative (property)",
          "[shapes][sphere][property]") {
    using namespace shapetest;
    const PropertyStats stats =
        runConeProperty("ellipsoid", 0xe111b501ull, 100000, randomSphere, ProbeDensity{}, 4);
    CHECK(stats.failures == 0);
    CHECK(stats.leave > 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}

TEST_CASE("Sphere classification across a scale: known answers", "[shapes][sphere]") {
    // The ellipsoid x^2/4 + y^2 + 4 z^2 = 1 (a unit sphere scaled <2, 1, 0.5>),
    // rotated about z by 30 degrees and moved to <1, 2, 3>.
    const Transform t = Transform::translate({1, 2, 3}) * Transform::rotateDegrees({0, 0, 30}) *
                        Transform::scale({2, 1, 0.5});
    const LocalFrame frame = LocalFrame::make(t, Mat3(1.0), Vec3(0.0));
    REQUIRE(frame.kind == LocalFrame::Kind::General);
    const Sphere sphere(1.0);
    const Vec3 centre(1, 2, 3);
    // Head-on along -z onto the pole at z = 3.5: Full, with depth bounds
    // around the exact 6.5 within the pixel cone's spread.
    Cone cone{centre + Vec3(0, 0, 10), {0, 0, -1}, 1e-3};
    auto out = sphere.classifyAcrossScale(PreparedCone(cone), frame);
    REQUIRE(out);
    CHECK(out->coverage == Coverage::Full);
    CHECK(out->tNear <= 9.5);
    CHECK(out->tFar >= 9.5);
    CHECK(out->tFar - out->tNear < 1e-3);
    // The same cone ending before the pole: Miss; ending inside it: undecided.
    cone.tMax = 9.0;
    out = sphere.classifyAcrossScale(PreparedCone(cone), frame);
    REQUIRE(out);
    CHECK(out->coverage == Coverage::Miss);
    cone.tMax = 9.5;
    CHECK_FALSE(sphere.classifyAcrossScale(PreparedCone(cone), frame));
    // Beside the ellipsoid: the long axis reaches 2 along the rotated x, so a
    // cone 2.2 away along it misses and one 1.8 away is Full; at 2 it is on
    // the silhouette: Marginal, its bounds holding the grazing hit at t = 10.
    const Vec3 longAxis(std::cos(kPi / 6), std::sin(kPi / 6), 0.0);
    for (const double along : {2.2, 1.8, 2.0}) {
        const Cone beside{centre + along * longAxis + Vec3(0, 0, 10), {0, 0, -1}, 1e-3};
        const auto answer = sphere.classifyAcrossScale(PreparedCone(beside), frame);
        if (along == 2.2) {
            REQUIRE(answer);
            CHECK(answer->coverage == Coverage::Miss);
        } else if (along == 1.8) {
            REQUIRE(answer);
            CHECK(answer->coverage == Coverage::Full);
        } else {
            REQUIRE(answer);
            CHECK(answer->coverage == Coverage::Marginal);
            CHECK(answer->tNear <= 10.0);
            CHECK(answer->tFar >= 10.0);
            CHECK(answer->tFar - answer->tNear < 0.1);
        }
    }
    // A wide cone holding the whole ellipsoid: Marginal (its axis hits, and
    // it is wider than the ellipsoid's bounding ball seen from the apex).
    const auto wide = sphere.classifyAcrossScale(PreparedCone(Cone{centre + Vec3(0, 0, 10), {0, 0, -1}, 0.5}), frame);
    REQUIRE(wide);
    CHECK(wide->coverage == Coverage::Marginal);
    // The apex inside: left to the local path.
    CHECK_FALSE(sphere.classifyAcrossScale(PreparedCone(Cone{centre, {0, 0, 1}, 1e-3}), frame));
}
