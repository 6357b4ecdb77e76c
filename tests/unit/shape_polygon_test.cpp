#include <catch2/catch.hpp>

#include <cmath>

#include "asos/testing/cone_probe.hpp"
#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive polygon(std::vector<Vec3> points, const Transform& t = {}) {
    return Primitive::make(PolygonShape{std::move(points)}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
bool hits(const Primitive& p, double x, double y) {
    return p.intersect({{x, y, -1}, {0, 0, 1}}, 0.0, kInfinity).has_value();
}
}  // namespace

TEST_CASE("Polygon ray hits: POV-Ray normal, sub-polygons, even-odd", "[shapes][polygon]") {
    // The normal is u x v of the first two independent edges: here +z.
    const Primitive tri = polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}});
    auto hit = tri.intersect({{0.2, 0.2, -1}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1.0));
    CHECK(near(hit->normal, {0, 0, 1}));
    CHECK(near(hit->objectPoint, {0.2, 0.2, 0}));
    CHECK_FALSE(hits(tri, 0.6, 0.6));
    // Clockwise: the normal flips.
    const Primitive cw = polygon({{0, 0, 0}, {0, 1, 0}, {1, 0, 0}});  // closed for us
    hit = cw.intersect({{0.2, 0.2, -1}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->normal, {0, 0, -1}));
    // A square with a square hole: two sub-polygons.
    const Primitive frame = polygon({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 0},
                                     {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}, {1, 1, 0}});
    CHECK(hits(frame, 0.5, 0.5));
    CHECK(hits(frame, 3.5, 2.0));
    CHECK_FALSE(hits(frame, 2.0, 2.0));
    CHECK_FALSE(hits(frame, 5.0, 2.0));
    // Non-convex: an L.
    const Primitive ell = polygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}});
    CHECK(hits(ell, 0.5, 1.5));
    CHECK(hits(ell, 1.5, 0.5));
    CHECK_FALSE(hits(ell, 1.5, 1.5));
    // Self-intersecting bow tie: even-odd.
    const Primitive bow = polygon({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}});
    CHECK(hits(bow, 0.3, 1.0));
    CHECK(hits(bow, 1.7, 1.0));
    CHECK_FALSE(hits(bow, 1.0, 1.7));
    // Far away, rotated into the plane x = 1e5.
    const Primitive far = polygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}},
                                  Transform::translate({1e5, 0, 0}) *
                                      Transform::rotateDegrees({0, 90, 0}));
    hit = far.intersect({{0, 0, 0}, glm::normalize(Vec3(1e5, 0.5, 0.5))}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.x == Approx(1e5).epsilon(1e-14));
    CHECK(std::abs(hit->position.y - 0.5) < 1e-9);
}

TEST_CASE("Polygon under a non-uniform frame: relaid rigidly, the same hits and object points",
          "[shapes][polygon]") {
    // An affine image of a planar polygon is a planar polygon, which
    // Primitive::make lays out again in a rigid frame.
    shapetest::checkFlatUnderScale(0x5ca1eull, [](const Transform& t) {
        return polygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, t);
    }, [](shapetest::Rng& rng) {
        // A point of the square by a margin, or off it by one.
        const bool inside = rng.chance(0.5);
        Vec3 target(rng.uniform(-0.95, 0.95), rng.uniform(-0.95, 0.95), 0.0);
        if (!inside) target[rng.index(2)] = (rng.chance(0.5) ? 1.0 : -1.0) * rng.uniform(1.05, 2.0);
        return std::pair{target, inside};
    });
}

TEST_CASE("Polygon cone classification: known answers", "[shapes][polygon]") {
    const Primitive sq = polygon({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    Cone c;
    c.apex = {0, 0, -10};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.05;
    ConeClass k = sq.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear == Approx(10.0).epsilon(1e-8));
    c.axis = glm::normalize(Vec3(1, 0, 10));  // the edge x = 1
    c.halfAngle = 0.01;
    k = sq.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK(k.singleEdge);
    c.axis = glm::normalize(Vec3(1, 1, 10));  // a corner
    k = sq.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK_FALSE(k.singleEdge);
    c.axis = glm::normalize(Vec3(2, 0, 10));
    CHECK(sq.classify(c).coverage == Coverage::Miss);
    // Through the hole of a frame: a miss.
    const Primitive frame = polygon({{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 0},
                                     {1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}, {1, 1, 0}});
    c.apex = {2, 2, -5};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.1;
    CHECK(frame.classify(c).coverage == Coverage::Miss);
    c.halfAngle = 0.3;
    CHECK(frame.classify(c).coverage == Coverage::Marginal);
    // Grazing, wider than the plane's horizon: never Full.
    c.apex = {0, 0, -0.01};
    c.axis = {1, 0, 0};
    c.halfAngle = 0.2;
    CHECK(sq.classify(c).coverage == Coverage::Marginal);
}

TEST_CASE("Polygon degenerate input", "[shapes][polygon]") {
    CHECK_THROWS_WITH(polygon({{0, 0, 0}, {1, 0, 0}}), "a polygon needs at least 3 points, not 2");
    CHECK_THROWS_WITH(polygon({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}),
                      "the points of the polygon are not in one plane: point 4 is 1 away from the plane of the first ones");
    CHECK_THROWS_WITH(polygon({{0, 0, 0}, {1, 0, 0}, {0, kInfinity, 0}}),
                      "point 3 of the polygon must be finite, not <0, inf, 0>");
    // Collinear and repeated points: all on one line.
    CHECK_THROWS_WITH(polygon({{0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {2, 2, 2}}),
                      "the points of the polygon are all on one line");
    // A polygon of no loop, which Primitive::make never lays out, answers as empty.
    const Polygon none({Vec2(0.0), Vec2(1.0)}, {});
    CHECK_FALSE(none.intersect(Ray{{0.5, 0.5, -1}, {0, 0, 1}}, 0.0, kInfinity));
    CHECK(none.classify(shapetest::localCone({0.5, 0.5, -3}, {0, 0, 1}, 0.5)).coverage == Coverage::Miss);
    Cone c;
    // Repeated vertices inside a valid polygon are harmless.
    const Primitive rep = polygon({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    CHECK(hits(rep, 0.5, 0.5));
    c.apex = {0.5, 0.5, -3};
    c.halfAngle = 0.01;
    CHECK(rep.classify(c).coverage == Coverage::Full);
}

TEST_CASE("Polygon near edges: zero-length edges and clamped nearest points",
          "[shapes][polygon]") {
    // The near edges' test clamps the nearest point of each segment to its
    // ends by masks: a zero-length edge (a repeated vertex: the clamp sees
    // 0/0 or an infinity) and nearest points before, between and past the
    // ends, with cones swept across the corner at the repeated vertex.
    const Primitive rep = polygon({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}});
    int counts[3] = {0, 0, 0};
    for (int i = 0; i <= 30; ++i) {
        for (int j = 0; j <= 4; ++j) {
            Cone c;
            const double x = 0.96 + 0.08 * i / 30.0, y = -0.04 + 0.08 * j / 4.0;
            c.apex = {x, y, -10.0};
            c.axis = {0, 0, 1};
            c.halfAngle = 0.002;
            if (j % 2) c.axis = glm::normalize(Vec3(0.0005, -0.0005, 1.0));
            const ConeClass k = rep.classify(c);
            const ProbeResult p = probeCone(rep, c, k, ProbeDensity{12, 8, 192});
            INFO("apex " << x << " " << y << " coverage " << int(k.coverage));
            CHECK(p.violations == 0);
            ++counts[static_cast<int>(k.coverage)];
        }
    }
    CHECK(counts[static_cast<int>(Coverage::Miss)] > 0);
    CHECK(counts[static_cast<int>(Coverage::Full)] > 0);
    CHECK(counts[static_cast<int>(Coverage::Marginal)] > 0);
}

TEST_CASE("Polygon near edges: more than the near list holds", "[shapes][polygon]") {
    // The edge pass counts near edges without a clamp, its 16 slots
    // wrapping: 16 or more take the exact path, fewer keep their indices
    // (here up to 39). A 40-gon, with cones from its centre (every edge's
    // line near q) out past its rim, narrow and wide.
    std::vector<Vec3> points;
    for (int i = 0; i < 40; ++i) {
        const double a = 2.0 * kPi * i / 40.0;
        points.emplace_back(std::cos(a), std::sin(a), 0.0);
    }
    const Primitive gon = polygon(points);
    int counts[3] = {0, 0, 0};
    for (int i = 0; i <= 24; ++i) {
        for (const double halfAngle : {0.002, 0.02, 0.2}) {
            Cone c;
            const double a = 0.3 * i;
            const double r = 1.2 * i / 24.0;
            c.apex = {r * std::cos(a), r * std::sin(a), -5.0};
            c.axis = glm::normalize(Vec3(0.01 * i, -0.005 * i, 1.0));
            c.halfAngle = halfAngle;
            const ConeClass k = gon.classify(c);
            const ProbeResult p = probeCone(gon, c, k, ProbeDensity{12, 8, 192});
            INFO("i " << i << " half-angle " << halfAngle << " coverage " << int(k.coverage));
            CHECK(p.violations == 0);
            ++counts[static_cast<int>(k.coverage)];
        }
    }
    CHECK(counts[static_cast<int>(Coverage::Miss)] > 0);
    CHECK(counts[static_cast<int>(Coverage::Full)] > 0);
    CHECK(counts[static_cast<int>(Coverage::Marginal)] > 0);
    // Footprint over the whole 40-gon (all 40 edges near): Marginal.
    Cone c;
    c.apex = {0.0, 0.0, -5.0};
    c.axis = {0.0, 0.0, 1.0};
    c.halfAngle = 0.3;
    CHECK(gon.classify(c).coverage == Coverage::Marginal);
    // Near edge 39 alone (the last slot index, past the 16 slots).
    c.apex = {std::cos(2.0 * kPi * 39.5 / 40.0) * 0.999, std::sin(2.0 * kPi * 39.5 / 40.0) * 0.999, -5.0};
    c.halfAngle = 0.001;
    const ConeClass k = gon.classify(c);
    CHECK(k.coverage == Coverage::Marginal);
    CHECK(k.singleEdge);
}

TEST_CASE("Polygon cone classification is conservative (property)", "[shapes][polygon][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("polygon", 0x9017ull, 100000, [](Rng& rng) {
        // A 2D outline, then placed in a random plane.
        std::vector<Vec2> outline;
        const int kind = rng.index(4);
        if (kind == 0) {
            for (int i = 0; i < 3; ++i) outline.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1));
        } else if (kind == 1 || kind == 2) {
            // Star-shaped, possibly non-convex; kind 2 adds a square hole.
            const int n = 3 + rng.index(10);
            for (int i = 0; i < n; ++i) {
                const double a = 2.0 * kPi * (i + rng.uniform(0.0, 0.8)) / n;
                const double r = rng.uniform(0.3, 1.0);
                outline.emplace_back(r * std::cos(a), r * std::sin(a));
            }
        } else {
            const int n = 4 + rng.index(6);  // self-intersecting: random points
            for (int i = 0; i < n; ++i) outline.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1));
        }
        const double scale = rng.logUniform(-1.0, 0.7);
        const Mat3 frame = frameAroundAxis(rng.unitVector());
        const Vec3 origin(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
        auto place = [=](Vec2 v) { return origin + scale * (v.x * frame[0] + v.y * frame[1]); };
        std::vector<Vec3> points;
        for (const Vec2& v : outline) points.push_back(place(v));
        if (kind == 2) {
            points.push_back(points[0]);
            const double s = rng.uniform(0.05, 0.2);
            const Vec2 sq[] = {{-s, -s}, {s, -s}, {s, s}, {-s, s}, {-s, -s}};
            for (const Vec2& v : sq) points.push_back(place(v));
        }
        ShapeCase sc;
        sc.shape = PolygonShape{points};
        sc.size = scale;
        const std::vector<Vec3> pts = points;
        sc.surfacePoint = [=](Rng& r) {
            const std::size_t i = static_cast<std::size_t>(r.index(static_cast<int>(pts.size())));
            const Vec3 a = pts[i], b = pts[(i + 1) % pts.size()];
            const double pick = r.uniform();
            if (pick < 0.2) return a;
            if (pick < 0.6) return a + r.uniform() * (b - a);
            return place(Vec2(r.uniform(-1, 1), r.uniform(-1, 1)));
        };
        std::string text = "polygon { " + std::to_string(points.size());
        for (const Vec3& p : points) text += ", " + fmt(p);
        sc.text = text + " }";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.leave > 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}

TEST_CASE("Which primitives are convex sets", "[shapes][polygon]") {
    const Transform none{};
    CHECK(Primitive::make(SphereShape{{1, 2, 3}, 0.5}, none).convex());
    CHECK(Primitive::make(BoxShape{{0, 0, 0}, {1, 2, 3}}, none).convex());
    CHECK(Primitive::make(CylinderShape{{0, 0, 0}, {0, 1, 0}, 0.5, false}, none).convex());
    CHECK_FALSE(Primitive::make(CylinderShape{{0, 0, 0}, {0, 1, 0}, 0.5, true}, none).convex());
    CHECK(Primitive::make(ConeShape{{0, 0, 0}, 1.0, {0, 1, 0}, 0.0, false}, none).convex());
    CHECK_FALSE(Primitive::make(ConeShape{{0, 0, 0}, 1.0, {0, 1, 0}, 0.5, true}, none).convex());
    CHECK(Primitive::make(DiscShape{{0, 0, 0}, {0, 1, 0}, 1.0, 0.0}, none).convex());
    CHECK_FALSE(Primitive::make(DiscShape{{0, 0, 0}, {0, 1, 0}, 1.0, 0.3}, none).convex());
    CHECK_FALSE(Primitive::make(PlaneShape{{0, 1, 0}, 0.0}, none).convex());
    // Polygons: one convex loop, in either turning sense, with repeated and
    // collinear points; not a concave loop, a star, a loop that turns back
    // along itself, or two loops.
    CHECK(polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}}).convex());
    CHECK(polygon({{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, {0, 0, 0}}).convex());
    CHECK(polygon({{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}}).convex());
    CHECK_FALSE(polygon({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}, {0, 0, 0}}).convex());
    std::vector<Vec3> star;
    for (int k = 0; k <= 5; ++k) {
        const double a = 2.0 * kPi * (2 * k % 5) / 5.0;
        star.push_back({std::cos(a), std::sin(a), 0.0});
    }
    CHECK_FALSE(polygon(star).convex());
    CHECK_FALSE(polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0.5, 0}, {0, 0.75, 0}, {0, 0, 0}}).convex());
    CHECK_FALSE(polygon({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {2, 2, 0}, {3, 2, 0}, {3, 3, 0}, {2, 2, 0}})
                    .convex());
}

TEST_CASE("Open cylinders and cones may shadow themselves, other shapes not", "[shapes][shadow]") {
    const Transform none{};
    const Transform stretched = Transform::scale({2, 1, 0.5});
    const auto can = [](const Shape& shape, const Transform& t) { return Primitive::make(shape, t).canShadowItself(); };
    CHECK(can(CylinderShape{{0, 0, 0}, {0, 1, 0}, 1.0, true}, none));
    CHECK_FALSE(can(CylinderShape{{0, 0, 0}, {0, 1, 0}, 1.0, false}, none));
    ConeShape cone;
    cone.open = true;
    CHECK(can(cone, none));
    CHECK_FALSE(can(ConeShape{}, none));
    // A cone of equal radii is placed as a cylinder.
    CHECK(can(ConeShape{{0, 0, 0}, 0.5, {0, 1, 0}, 0.5, true}, none));
    CHECK_FALSE(can(ConeShape{{0, 0, 0}, 0.5, {0, 1, 0}, 0.5, false}, none));
    CHECK_FALSE(can(SphereShape{}, none));
    CHECK_FALSE(can(BoxShape{}, none));
    CHECK_FALSE(can(PlaneShape{}, none));
    CHECK_FALSE(can(DiscShape{}, none));
    CHECK_FALSE(can(DiscShape{}, stretched));  // an elliptic disc
    CHECK_FALSE(can(PolygonShape{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 0.2, 0}}}, none));
}

TEST_CASE("Polygon classifyRanging answers as classify does", "[shapes][polygon]") {
    // One loop of 3 to 8 vertices about the origin, the longer ones star-like
    // (concave): the edge pass's answers, which go through RigidBounds before
    // the range is set, and the near-edge and exact answers after it. The
    // vertices reach 2 size, so that the random cones meet about as many
    // polygons as they meet discs of radius size (a polygon inscribed in a
    // circle covers less of it).
    shapetest::checkRangingAsClassify<Polygon>(0x9017a6e5, [](shapetest::Rng& rng, double size) {
        const int n = 3 + static_cast<int>(rng.uniform(0.0, 6.0));
        std::vector<Vec2> vertices;
        for (int i = 0; i < n; ++i) {
            const double a = 2.0 * kPi * (i + rng.uniform(0.0, 0.5)) / n;
            const double r = 2.0 * size * (n > 4 && i % 2 ? rng.uniform(0.4, 0.8) : 1.0);
            vertices.emplace_back(r * std::cos(a), r * std::sin(a));
        }
        return Polygon(std::move(vertices), {static_cast<std::uint32_t>(n)});
    });
}
