#include <catch2/catch.hpp>

#include <cmath>

#include "asos/shapes/disc.hpp"
#include "asos/shapes/elliptic_disc.hpp"
#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive disc(Vec3 center, Vec3 normal, double radius, double hole = 0.0,
               const Transform& t = {}) {
    return Primitive::make(DiscShape{center, normal, radius, hole}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Disc ray hits: annulus, normal, far away", "[shapes][disc]") {
    const Primitive d = disc({0, 1, 0}, {0, 2, 0}, 2.0, 0.5);
    auto hit = d.intersect({{1, 5, 0}, {0, -1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(hit->normal, {0, 1, 0}));
    CHECK(near(hit->objectPoint, {1, 1, 0}));
    hit = d.intersect({{1, -5, 0}, {0, 1, 0}}, 0.0, kInfinity);  // from below: same normal
    REQUIRE(hit);
    CHECK(near(hit->normal, {0, 1, 0}));
    CHECK_FALSE(d.intersect({{0.2, 5, 0.2}, {0, -1, 0}}, 0.0, kInfinity));  // the hole
    CHECK_FALSE(d.intersect({{2.1, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));    // outside
    CHECK_FALSE(d.intersect({{0, 0, 0}, {1, 0, 0}}, 0.0, kInfinity));       // parallel
    const Primitive far = disc({0, 0, 1e5}, {0, 0, -1}, 1.0);
    hit = far.intersect({{0, 0, 0}, glm::normalize(Vec3(0.9e-5, 0, 1))}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.z == Approx(1e5).epsilon(1e-14));
    CHECK(near(hit->normal, {0, 0, -1}));
    // Non-uniform scale: an elliptic disc.
    const Primitive e = disc({0, 0, 0}, {0, 0, 1}, 1.0, 0.0, Transform::scale({3, 1, 1}));
    CHECK(e.intersect({{2.9, 0, -1}, {0, 0, 1}}, 0.0, kInfinity));
    CHECK_FALSE(e.intersect({{0, 1.1, -1}, {0, 0, 1}}, 0.0, kInfinity));
    CHECK(e.worldBounds().hi.x == Approx(3.0));
}

TEST_CASE("Disc cone classification: known answers", "[shapes][disc]") {
    const Primitive d = disc({0, 0, 0}, {0, 0, 1}, 1.0, 0.25);
    Cone c;
    c.apex = {0.5, 0, -10};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.01;  // footprint radius 0.1 around (0.5, 0)
    ConeClass k = d.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear == Approx(10.0).epsilon(1e-8));
    c.apex = {1.0, 0, -10};  // on the rim
    k = d.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK_FALSE(k.singleEdge);
    c.apex = {1.2, 0, -10};
    CHECK(d.classify(c).coverage == Coverage::Miss);
    c.apex = {0.0, 0, -10};  // inside the hole
    CHECK(d.classify(c).coverage == Coverage::Miss);
    c.apex = {0.3, 0, -10};  // across the hole's edge
    CHECK(d.classify(c).coverage == Coverage::Marginal);
    // Oblique: an elongated footprint near the rim.
    c.apex = {-9, 0, -3};
    c.axis = glm::normalize(Vec3(9.6, 0, 3));  // aims at (0.6, 0, 0), footprint ~0.3 long
    c.halfAngle = 0.005;
    CHECK(d.classify(c).coverage == Coverage::Full);
    c.axis = glm::normalize(Vec3(9.9, 0, 3));
    CHECK(d.classify(c).coverage == Coverage::Marginal);
}

TEST_CASE("Disc degenerate input", "[shapes][disc]") {
    CHECK_THROWS_WITH(disc({0, 0, 0}, {0, 0, 0}, 1.0), "the normal of a disc must not be zero");
    CHECK_THROWS_WITH(disc({0, 0, 0}, {0, 0, 1e-200}, 1.0), "the normal of a disc must not be zero");
    CHECK_THROWS_WITH(disc({0, 0, 0}, {0, 0, 1}, -1.0), "the radius of a disc must be positive, not -1");
    CHECK_THROWS_WITH(disc({0, 0, 0}, {0, 0, 1}, 1.0, 1.0),
                      "the hole radius of a disc must be at least 0 and less than its radius 1, not 1");
    CHECK_THROWS_WITH(disc({0, 0, 0}, {0, 0, 1}, 1.0, std::nan("")),
                      "the hole radius of a disc must be finite, not nan");
    // The empty discs, which Primitive::make refuses, still answer.
    const LocalCone c = shapetest::localCone({0, 0, -2}, {0, 0, 1}, 0.8);
    const Disc empty(1.0, 1.0);  // hole as large as the disc
    CHECK_FALSE(empty.intersect(Ray{{0.5, 0, -1}, {0, 0, 1}}, 0.0, kInfinity));
    CHECK(empty.classify(c).coverage == Coverage::Miss);
    CHECK(Disc(0.0, 0.0).classify(c).coverage == Coverage::Miss);
}

TEST_CASE("Disc cone classification is conservative (property)", "[shapes][disc][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("disc", 0xd15cull, 100000, [](Rng& rng) {
        ShapeCase sc;
        const Vec3 center(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
        const Vec3 normal = rng.unitVector() * rng.uniform(0.5, 2.0);
        const double radius = rng.logUniform(-1.0, 0.7);
        const double hole = rng.chance(0.5) ? 0.0 : radius * rng.uniform(0.05, 0.9);
        sc.shape = DiscShape{center, normal, radius, hole};
        sc.size = radius;
        const Mat3 frame = frameAroundAxis(glm::normalize(normal));
        sc.surfacePoint = [=](Rng& r) {
            const double a = r.uniform(0, 2 * kPi);
            const double pick = r.uniform();
            const double rr = pick < 0.35 ? radius : pick < 0.5 ? hole : r.uniform(hole, radius);
            return center + rr * (std::cos(a) * frame[0] + std::sin(a) * frame[1]);
        };
        sc.text = "disc { " + fmt(center) + ", " + fmt(normal) + ", " + fmt(radius) + ", " +
                  fmt(hole) + " }";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.leave > 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}

TEST_CASE("Disc classifyRanging answers as classify does", "[shapes][disc]") {
    shapetest::checkRangingAsClassify<Disc>(0xd15c4a6e, [](shapetest::Rng& rng, double radius) {
        return Disc(radius, rng.chance(0.4) ? radius * rng.uniform(0.1, 0.9) : 0.0);
    });
    shapetest::checkRangingAsClassify<EllipticDisc>(0xe111d15c, [](shapetest::Rng& rng, double radius) {
        return EllipticDisc(radius, radius * rng.uniform(0.25, 4.0),
                            rng.chance(0.4) ? rng.uniform(0.1, 0.9) : 0.0);
    });
}

TEST_CASE("Disc under a non-uniform frame: an elliptic disc with the same hits and object points",
          "[shapes][disc]") {
    // Primitive::make lays a disc under a non-uniform scale, a shear or a
    // matrix out again as an EllipticDisc in a rigid frame.
    shapetest::checkFlatUnderScale(0xe11d15cull, [](const Transform& t) {
        return Primitive::make(DiscShape{Vec3(0.0), Vec3(0, 0, 1), 1.0, 0.3}, t);
    }, [](shapetest::Rng& rng) {
        // A point of the annulus by a margin, or off it by one (beyond the
        // rim or in the hole).
        const double angle = rng.uniform(0.0, 2.0 * kPi);
        const double pick = rng.uniform();
        const double r = pick < 0.5 ? rng.uniform(0.32, 0.98) : pick < 0.8 ? rng.uniform(1.02, 2.0)
                                                                          : rng.uniform(0.0, 0.28);
        return std::pair{Vec3(r * std::cos(angle), r * std::sin(angle), 0.0), pick < 0.5};
    });
}
