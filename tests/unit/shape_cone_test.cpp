#include <catch2/catch.hpp>

#include <cmath>

#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive cone(Vec3 base, double r0, Vec3 cap, double r1, bool open = false,
               const Transform& t = {}) {
    return Primitive::make(ConeShape{base, r0, cap, r1, open}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Cone ray hits: side, caps, tip, open, far", "[shapes][cone]") {
    const Primitive c = cone({0, 0, 0}, 1.0, {0, 2, 0}, 0.0);  // pointed, tip at y = 2
    CHECK(std::string(c.kindName()) == "cone");
    auto hit = c.intersect({{0, 1, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.5));  // radius 0.5 at y = 1
    CHECK(near(hit->normal, glm::normalize(Vec3(0, 0.25, -0.5))));
    hit = c.intersect({{0.3, -5, 0}, {0, 1, 0}}, 0.0, kInfinity);  // the base cap
    REQUIRE(hit);
    CHECK(hit->t == Approx(5.0));
    CHECK(near(hit->normal, {0, -1, 0}));
    hit = c.intersect({{0, 5, 0}, {0, -1, 0}}, 0.0, kInfinity);  // onto the tip
    REQUIRE(hit);
    CHECK(hit->t == Approx(3.0));
    CHECK_FALSE(c.intersect({{0.6, 1, -5}, {0, 0, 1}}, 0.0, kInfinity));
    hit = c.intersect({{0, 0.5, 0}, {1, 0, 0}}, 0.0, kInfinity);  // from inside
    REQUIRE(hit);
    CHECK(hit->t == Approx(0.75));
    // Truncated and open: looking down through the wide top into the inside.
    const Primitive o = cone({0, 0, 0}, 0.5, {0, 2, 0}, 1.0, true);
    CHECK_FALSE(o.intersect({{0, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));
    hit = o.intersect({{0, 5, 0}, glm::normalize(Vec3(0.3, -1, 0))}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(std::abs(hit->position.x - (0.5 + 0.25 * hit->position.y)) < 1e-12);
    // Equal radii: a cylinder, still called a cone.
    const Primitive cyl = cone({0, 0, 0}, 1.0, {0, 2, 0}, 1.0);
    CHECK(std::string(cyl.kindName()) == "cone");
    hit = cyl.intersect({{0, 1, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    // Far away.
    const Primitive far = cone({0, -1, 1e5}, 1.0, {0, 1, 1e5}, 0.5);
    hit = far.intersect({{0, 0, 0}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(std::abs(hit->t - (1e5 - 0.75)) < 1e-8);
}

TEST_CASE("Cone cone classification: known answers", "[shapes][cone]") {
    const Primitive c = cone({0, 0, 0}, 1.0, {0, 2, 0}, 0.5);
    Cone k;
    k.apex = {0, 1, -10};
    k.axis = {0, 0, 1};
    k.halfAngle = 0.02;
    ConeClass a = c.classify(k);
    CHECK(a.coverage == Coverage::Full);
    // The slanted side's nearest point (9.055 away) is below the axis ray's hit (9.25).
    CHECK(a.tNear >= 9.05);
    CHECK(a.tNear <= 9.25);
    // A contour generator: straight.
    k.apex = {0, 1, -100};
    k.axis = glm::normalize(Vec3(0.75, 0, 100));
    k.halfAngle = 0.001;
    a = c.classify(k);
    CHECK(a.coverage == Coverage::Marginal);
    CHECK(a.singleEdge);
    k.axis = glm::normalize(Vec3(1.5, 0, 100));
    CHECK(c.classify(k).coverage == Coverage::Miss);
    // From inside: every ray leaves.
    k.apex = {0.1, 0.5, 0};
    k.halfAngle = 2.0;
    CHECK(c.classify(k).coverage == Coverage::Full);
    // Looking at the tip of a pointed cone: two generators meet there.
    const Primitive p = cone({0, 0, 0}, 1.0, {0, 2, 0}, 0.0);
    k.apex = {0, 2, -10};
    k.axis = {0, 0, 1};
    k.halfAngle = 0.01;
    a = p.classify(k);
    CHECK(a.coverage == Coverage::Marginal);
    CHECK_FALSE(a.singleEdge);
}

TEST_CASE("Cone degenerate input", "[shapes][cone]") {
    CHECK_THROWS_WITH(cone({1, 1, 1}, 1.0, {1, 1, 1}, 0.5), "the base and cap points of a cone are the same point");
    CHECK_THROWS_WITH(cone({0, 0, 0}, -1.0, {0, 1, 0}, 0.5), "the base radius of a cone must not be negative, not -1");
    CHECK_THROWS_WITH(cone({0, 0, 0}, 1.0, {0, 1, 0}, std::nan("")), "the cap radius of a cone must be finite, not nan");
    CHECK_THROWS_WITH(cone({0, 0, 0}, 0.0, {0, 1, 0}, 0.0), "a cone needs a radius that is not zero");
    // The cone of no radius, which Primitive::make refuses, still answers.
    const TruncatedCone none(0.0, 0.0, 1.0, false);
    CHECK_FALSE(none.intersect(Ray{{0, -1, 0.5}, {0, 1, 0}}, 0.0, kInfinity));
    CHECK(none.classify(shapetest::localCone({0, -3, 0.5}, {0, 1, 0}, 0.5)).coverage == Coverage::Miss);
    Cone k;
    // Apex at the extended tip of the side: the contour is degenerate.
    const Primitive t = cone({0, 0, 0}, 1.0, {0, 1, 0}, 0.5);  // extended tip at y = 2
    k.apex = {0, 2, 0};
    k.axis = {0, -1, 0};
    k.halfAngle = 0.2;
    const ConeClass a = t.classify(k);
    CHECK(a.coverage != Coverage::Miss);
    CHECK_FALSE(std::isnan(a.tNear + a.tFar));
}

TEST_CASE("Cone cone classification is conservative (property)", "[shapes][cone][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("cone", 0xc0e5ull, 100000, [](Rng& rng) {
        ShapeCase sc;
        const Vec3 base(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
        const Vec3 dir = rng.chance(0.3) ? Vec3(0, 1, 0) : rng.unitVector();
        const double length = rng.logUniform(-1.0, 0.7);
        const Vec3 cap = base + length * dir;
        double r0 = rng.logUniform(-1.3, 0.5);
        double r1 = rng.chance(0.25) ? 0.0 : rng.logUniform(-1.3, 0.5);
        if (rng.chance(0.2)) std::swap(r0, r1);
        const bool open = rng.chance(0.3);
        sc.shape = ConeShape{base, r0, cap, r1, open};
        sc.size = std::max({length, r0, r1});
        const Mat3 frame = frameAroundAxis(dir);
        sc.surfacePoint = [=](Rng& r) {
            const double a = r.uniform(0, 2 * kPi);
            const Vec3 radial = std::cos(a) * frame[0] + std::sin(a) * frame[1];
            const double pick = r.uniform();
            if (pick < 0.4) {
                const double f = r.uniform();
                return base + f * length * dir + (r0 + f * (r1 - r0)) * radial;
            }
            const bool top = r.chance(0.5);
            const double radius = top ? r1 : r0;
            if (pick < 0.7) return (top ? cap : base) + radius * radial;
            return (top ? cap : base) + radius * std::sqrt(r.uniform()) * radial;
        };
        sc.text = "cone { " + fmt(base) + ", " + fmt(r0) + ", " + fmt(cap) + ", " + fmt(r1) +
                  (open ? " open }" : " }");
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.leave > 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}
