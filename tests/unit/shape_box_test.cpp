#include <catch2/catch.hpp>

#include <cmath>

#include "asos/testing/cone_probe.hpp"
#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive box(Vec3 a, Vec3 b, const Transform& t = {}) { return Primitive::make(BoxShape{a, b}, t); }
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Box ray hits: faces, inside, edges, corners in any order", "[shapes][box]") {
    const Primitive b = box({1, 1, 1}, {-1, -1, -1});  // corners in any order
    auto hit = b.intersect({{0, 0, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(hit->normal, {0, 0, -1}));
    hit = b.intersect({{0.5, 0.2, 0}, {1, 0, 0}}, 0.0, kInfinity);  // from inside
    REQUIRE(hit);
    CHECK(hit->t == Approx(0.5));
    CHECK(near(hit->normal, {1, 0, 0}));
    // Along an edge line and through a corner.
    hit = b.intersect({{1, 1, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    const Vec3 diag = glm::normalize(Vec3(1, 1, 1));
    hit = b.intersect({{-3, -3, -3}, diag}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->position, {-1, -1, -1}, 1e-12));
    CHECK_FALSE(b.intersect({{1.0 + 1e-12, 0, -5}, {0, 0, 1}}, 0.0, kInfinity));
    CHECK_FALSE(b.intersect({{0, 0, -5}, {0, 0, 1}}, 0.0, 3.9));
    CHECK(b.intersectAny({{0, 0, -5}, {0, 0, 1}}, 4.5, kInfinity));  // the exit at 6
    // Far away.
    const Primitive far = box({-1, -1, 1e5 - 1}, {1, 1, 1e5 + 1});
    hit = far.intersect({{0, 0, 0}, glm::normalize(Vec3(0.5e-5, 0, 1))}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.z == Approx(1e5 - 1).epsilon(1e-14));
    // Rotated: the normal turns with it; the object point stays put.
    const Primitive r = box({0, 0, 0}, {1, 2, 3}, Transform::rotateDegrees({0, 0, 90}));
    hit = r.intersect({{-1, 0.5, 5}, {0, 1, 0}}, 0.0, kInfinity);
    REQUIRE_FALSE(hit);  // the box now spans x in [-2, 0], y in [0, 1], z in [0, 3]
    hit = r.intersect({{-1, -4, 1}, {0, 1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(hit->normal, {0, -1, 0}));
    CHECK(near(hit->objectPoint, {0, 1, 1}));
    CHECK(near(r.worldBounds().lo, {-2, 0, 0}, 1e-9));
}

TEST_CASE("Box cone classification: known answers", "[shapes][box]") {
    const Primitive b = box({-1, -1, -1}, {1, 1, 1});
    Cone c;
    c.apex = {0, 0, -10};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.05;  // footprint radius ~0.45 on the face z = -1
    ConeClass k = b.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear >= 9.0 - 1e-7);
    c.axis = glm::normalize(Vec3(1, 0, 9));  // the edge x = 1 of the near face
    c.halfAngle = 0.01;
    k = b.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK(k.singleEdge);
    c.axis = glm::normalize(Vec3(1, 1, 9));  // the corner: two edges
    k = b.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK_FALSE(k.singleEdge);
    c.axis = glm::normalize(Vec3(0.2, 0, 1));
    CHECK(b.classify(c).coverage == Coverage::Miss);
    // Looking at an edge between two visible faces (a crease, not the
    // silhouette): every ray hits.
    c.apex = {-10, 0, -10};
    c.axis = glm::normalize(Vec3(9, 0, 9));
    c.halfAngle = 0.01;
    CHECK(b.classify(c).coverage == Coverage::Full);
    // From inside: every ray leaves.
    c.apex = {0.2, 0.3, 0.1};
    c.halfAngle = 2.0;
    k = b.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear >= 0.7 - 1e-7);
    // A shadow cone leaving the face it starts on misses.
    c.apex = {0.3, 1, 0.2};
    c.axis = glm::normalize(Vec3(0.3, 1, 0.2));
    c.halfAngle = 0.3;
    c.tMin = 1e-6;
    CHECK(b.classify(c).coverage == Coverage::Miss);
}

TEST_CASE("Box degenerate input", "[shapes][box]") {
    CHECK_THROWS_WITH(box({0, 0, 0}, {1, std::nan(""), 1}), Catch::Contains("corner"));
    // A flat box is a rectangle: hit where the ray crosses it.
    const Primitive flat = box({-1, -1, 0}, {1, 1, 0});
    auto hit = flat.intersect({{0.5, 0.5, -2}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
    Cone c;
    c.apex = {0, 0, -2};
    c.halfAngle = 0.1;
    CHECK(flat.classify(c).coverage == Coverage::Full);
    c.halfAngle = 0.5;
    CHECK(flat.classify(c).coverage == Coverage::Marginal);
}

TEST_CASE("Box silhouette edges near the cone's axis line", "[shapes][box]") {
    // The silhouette pass skips edges farther from the axis line than the
    // cone reaches (a quadratic along the edge, compared without division).
    // Edges parallel to the axis (no quadratic term), edges whose nearest
    // point is an end or lies between, and cones swept across the distance
    // at which they start to reach an edge: every answer agrees with rays.
    const Primitive b = box({-1, -1, -1}, {1, 1, 1});
    int marginal = 0, miss = 0;
    auto check = [&](const Cone& c) {
        const ConeClass k = b.classify(c);
        const ProbeResult p = probeCone(b, c, k, ProbeDensity{12, 8, 192});
        INFO("apex " << c.apex.x << " " << c.apex.y << " " << c.apex.z << " axis " << c.axis.x
                     << " " << c.axis.y << " " << c.axis.z << " half-angle " << c.halfAngle);
        CHECK(p.violations == 0);
        marginal += k.coverage == Coverage::Marginal;
        miss += k.coverage == Coverage::Miss;
    };
    for (int i = 0; i <= 40; ++i) {
        const double off = 0.02 + 0.1 * i / 40.0;  // the axis line from the edge x = y = 1
        Cone c;
        // Axis parallel to the z edges: the apex beside the box, past a corner.
        c.apex = {1.0 + off, 1.0 + off, -10.0};
        c.axis = {0, 0, 1};
        c.halfAngle = 0.005;
        check(c);
        // The same, axis tilted slightly, and wide enough for the far end.
        c.axis = glm::normalize(Vec3(-0.001, -0.001, 1.0));
        c.halfAngle = 0.008;
        check(c);
        // Looking at the near face's edge x = 1 from in front: the nearest
        // point of the x edges lies between their ends.
        c.apex = {1.0 + off, 0.3, -10.0};
        c.axis = {0, 0, 1};
        c.halfAngle = 0.004;
        check(c);
        // From the side, the axis across an edge's end (the nearest point an end).
        c.apex = {1.0 + off, 1.5, 0.2};
        c.axis = glm::normalize(Vec3(0.0, -1.0, 0.0));
        c.halfAngle = 0.02;
        check(c);
    }
    // The sweeps cross from Marginal to Miss.
    CHECK(marginal > 0);
    CHECK(miss > 0);
}

TEST_CASE("Box cone classification is conservative (property)", "[shapes][box][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("box", 0xb0c5ull, 100000, [](Rng& rng) {
        ShapeCase sc;
        const Vec3 a(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
        Vec3 size(rng.logUniform(-1, 0.5), rng.logUniform(-1, 0.5), rng.logUniform(-1, 0.5));
        if (rng.chance(0.03)) size[rng.index(3)] = 0.0;  // flat
        const Vec3 b = a + size * Vec3(rng.chance(0.5) ? 1 : -1, 1, rng.chance(0.5) ? 1 : -1);
        sc.shape = BoxShape{a, b};
        sc.size = glm::length(size);
        const Vec3 lo = glm::min(a, b), hi = glm::max(a, b);
        sc.surfacePoint = [=](Rng& r) {
            Vec3 x = r.inBox(lo, hi);
            const int pinned = r.chance(0.15) ? 2 : r.chance(0.1) ? 3 : 1;  // face, edge, corner
            for (int k = 0; k < pinned; ++k) {
                const int axis = (r.index(3) + k) % 3;
                x[axis] = r.chance(0.5) ? lo[axis] : hi[axis];
            }
            return x;
        };
        sc.text = "box { " + fmt(a) + ", " + fmt(b) + " }";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.leave > 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}

TEST_CASE("Box classifyRanging answers as classify does", "[shapes][box]") {
    // Boxes about the origin, some flat; apexes inside, outside and near them.
    shapetest::checkRangingAsClassify<Box>(0xb0c5a16e, [](shapetest::Rng& rng, double size) {
        const Vec3 half(size * rng.uniform(0.1, 1.0), size * rng.uniform(0.1, 1.0),
                        size * rng.uniform(0.1, 1.0));
        const Vec3 centre(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5));
        return Box(centre - half, centre + half);
    });
}
