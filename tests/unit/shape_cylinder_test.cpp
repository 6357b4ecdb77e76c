#include <catch2/catch.hpp>

#include <cmath>

#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive cylinder(Vec3 base, Vec3 cap, double radius, bool open = false, const Transform& t = {}) {
    return Primitive::make(CylinderShape{base, cap, radius, open}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Cylinder ray hits: side, caps, open, inside, tangent, far", "[shapes][cylinder]") {
    const Primitive c = cylinder({0, 0, 0}, {0, 2, 0}, 1.0);
    auto hit = c.intersect({{0, 1, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(hit->normal, {0, 0, -1}));
    CHECK(near(hit->objectPoint, {0, 1, -1}));
    hit = c.intersect({{0.5, 5, 0}, {0, -1, 0}}, 0.0, kInfinity);  // the cap
    REQUIRE(hit);
    CHECK(hit->t == Approx(3.0));
    CHECK(near(hit->normal, {0, 1, 0}));
    hit = c.intersect({{0.5, 1, 0}, {1, 0, 0}}, 0.0, kInfinity);  // from inside
    REQUIRE(hit);
    CHECK(hit->t == Approx(0.5));
    CHECK(near(hit->normal, {1, 0, 0}));
    hit = c.intersect({{1, 1, -5}, {0, 0, 1}}, 0.0, kInfinity);  // tangent
    REQUIRE(hit);
    CHECK(hit->t == Approx(5.0));
    CHECK_FALSE(c.intersect({{1.0 + 1e-9, 1, -5}, {0, 0, 1}}, 0.0, kInfinity));
    CHECK_FALSE(c.intersect({{0, 2.5, -5}, {0, 0, 1}}, 0.0, kInfinity));  // above
    // Open: straight down the axis passes through; a slanted ray meets the inside wall.
    const Primitive o = cylinder({0, 0, 0}, {0, 2, 0}, 1.0, true);
    CHECK_FALSE(o.intersect({{0, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));
    hit = o.intersect({{0, 3, 0}, glm::normalize(Vec3(1, -1, 0))}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->position, {1, 2, 0}, 1e-12));
    hit = o.intersect({{0, 2.5, 0}, glm::normalize(Vec3(1, -1, 0))}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->position, {1, 1.5, 0}, 1e-12));
    CHECK(near(hit->normal, {1, 0, 0}));  // outward, away from the viewer inside
    // Far away.
    const Primitive far = cylinder({0, -1, 1e5}, {0, 1, 1e5}, 1.0);
    const double b = 0.5e-5;
    hit = far.intersect({{0, 0, 0}, {std::sin(b), 0, std::cos(b)}}, 0.0, kInfinity);
    REQUIRE(hit);
    // x^2 + (z - 1e5)^2 = 1 along (sin b, 0, cos b): t = 1e5 cos b - sqrt(1 - 1e10 sin^2 b).
    CHECK(std::abs(hit->t - (1e5 * std::cos(b) - std::sqrt(1.0 - 1e10 * std::sin(b) * std::sin(b)))) <
          1e-9);
    // scale <2,1,1>: an elliptic cylinder, x-semi-axis 2.
    const Primitive e = cylinder({0, 0, 0}, {0, 2, 0}, 1.0, false, Transform::scale({2, 1, 1}));
    hit = e.intersect({{-5, 1, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(3.0));
    CHECK(e.worldBounds().hi.x == Approx(2.0));
}

TEST_CASE("Cylinder cone classification: known answers", "[shapes][cylinder]") {
    const Primitive c = cylinder({0, 0, 0}, {0, 2, 0}, 1.0);
    Cone k;
    k.apex = {0, 1, -10};
    k.axis = {0, 0, 1};
    k.halfAngle = 0.02;
    ConeClass a = c.classify(k);
    CHECK(a.coverage == Coverage::Full);
    CHECK(a.tNear >= 9.0 - 1e-7);
    CHECK(a.tFar <= 10.0 + 1e-7);  // the tangent points at the rims
    // The contour generator x = +-1: one straight edge.
    const double edge = std::asin(0.1);
    k.axis = {std::sin(edge), 0, std::cos(edge)};
    k.halfAngle = 0.005;
    a = c.classify(k);
    CHECK(a.coverage == Coverage::Marginal);
    CHECK(a.singleEdge);
    k.axis = {std::sin(edge + 0.02), 0, std::cos(edge + 0.02)};
    CHECK(c.classify(k).coverage == Coverage::Miss);
    // The top rim seen from the side: a curved boundary.
    k.axis = glm::normalize(Vec3(0, 1, 9));
    a = c.classify(k);
    CHECK(a.coverage == Coverage::Marginal);
    CHECK_FALSE(a.singleEdge);
    // The near rim seen from above is a crease between two visible faces;
    // open, rays just over it meet the inside of the far wall.
    const Primitive open = cylinder({0, 0, 0}, {0, 2, 0}, 1.0, true);
    k.apex = {0, 10, -10};
    k.axis = glm::normalize(Vec3(0, 2, -1) - k.apex);
    k.halfAngle = 0.01;
    CHECK(c.classify(k).coverage == Coverage::Full);
    CHECK(open.classify(k).coverage == Coverage::Full);
    // Looking down an open tube, the bottom rim bounds what is seen through
    // both openings; capped, the top cap covers it.
    k.apex = {0, 10, 0};
    k.axis = glm::normalize(Vec3(1, -10, 0));
    k.halfAngle = 0.005;
    CHECK(open.classify(k).coverage == Coverage::Marginal);
    CHECK(c.classify(k).coverage == Coverage::Full);
    // From inside: every ray leaves.
    k.apex = {0.2, 1, 0};
    k.halfAngle = 1.0;
    CHECK(c.classify(k).coverage == Coverage::Full);
    // A shadow cone leaving the side it starts on misses.
    k.apex = {0, 1, -1};
    k.axis = glm::normalize(Vec3(0.2, 0.3, -1));
    k.halfAngle = 0.3;
    k.tMin = 1e-6;
    CHECK(c.classify(k).coverage == Coverage::Miss);
}

TEST_CASE("Cylinder degenerate input", "[shapes][cylinder]") {
    CHECK_THROWS_WITH(cylinder({1, 2, 3}, {1, 2, 3}, 1.0), "the base and cap points of a cylinder are the same point");
    // Apart by less than the rounding of their coordinates: the same point.
    CHECK_THROWS_WITH(cylinder({1e6, 0, 0}, {1e6, 1e-8, 0}, 1.0),
                      "the base and cap points of a cylinder are the same point");
    CHECK_THROWS_WITH(cylinder({0, 0, 0}, {0, 1, 0}, -1.0), "the radius of a cylinder must be positive, not -1");
    CHECK_THROWS_WITH(cylinder({0, 0, 0}, {0, 1, 0}, 0.0), "the radius of a cylinder must be positive, not 0");
    CHECK_THROWS_WITH(cylinder({0, 0, 0}, {0, kInfinity, 0}, 1.0),
                      "the cap point of a cylinder must be finite, not <0, inf, 0>");
    // The cylinder of no radius, which Primitive::make refuses, still answers.
    const Cylinder thin(0.0, 1.0, false);
    CHECK_FALSE(thin.intersect(Ray{{0, -1, 0.5}, {0, 1, 0}}, 0.0, kInfinity));
    CHECK(thin.classify(shapetest::localCone({0, -3, 0.5}, {0, 1, 0}, 0.5)).coverage == Coverage::Miss);
}

TEST_CASE("Cylinder cone classification is conservative (property)",
          "[shapes][cylinder][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("cylinder", 0xc711ull, 100000, [](Rng& rng) {
        ShapeCase sc;
        const Vec3 base(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
        const Vec3 dir = rng.chance(0.3) ? Vec3(0, 1, 0) : rng.unitVector();
        const double length = rng.logUniform(-1.0, 0.7);
        const Vec3 cap = base + length * dir;
        const double radius = rng.logUniform(-1.3, 0.5);
        const bool open = rng.chance(0.3);
        sc.shape = CylinderShape{base, cap, radius, open};
        sc.size = std::max(length, radius);
        const Mat3 frame = frameAroundAxis(dir);
        sc.surfacePoint = [=](Rng& r) {
            const double a = r.uniform(0, 2 * kPi);
            const Vec3 radial = std::cos(a) * frame[0] + std::sin(a) * frame[1];
            const double pick = r.uniform();
            if (pick < 0.4) return base + r.uniform(0, length) * dir + radius * radial;
            if (pick < 0.7) return (r.chance(0.5) ? base : cap) + radius * radial;
            return (r.chance(0.5) ? base : cap) + radius * std::sqrt(r.uniform()) * radial;
        };
        sc.text = "cylinder { " + fmt(base) + ", " + fmt(cap) + ", " + fmt(radius) +
                  (open ? " open }" : " }");
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.leave > 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}
