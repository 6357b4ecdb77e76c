#include <catch2/catch.hpp>

#include <cmath>

#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive torus(double major, double minor, const Transform& t = {}) {
    return Primitive::make(TorusShape{major, minor, false}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-9) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Torus ray hits: all four crossings, POV-Ray's normal", "[shapes][torus]") {
    const Primitive t = torus(2.0, 0.5);
    // Along the x axis: crossings at -2.5, -1.5, 1.5, 2.5.
    const Ray ray{{-10, 0, 0}, {1, 0, 0}};
    const Crossings all = t.crossings(ray, 0.0, kInfinity);
    REQUIRE(all.count == 4);
    CHECK(all.hits[0].t == Approx(7.5).margin(1e-12));
    CHECK(all.hits[1].t == Approx(8.5).margin(1e-12));
    CHECK(all.hits[2].t == Approx(11.5).margin(1e-12));
    CHECK(all.hits[3].t == Approx(12.5).margin(1e-12));
    auto hit = t.intersect(ray, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->position, {-2.5, 0, 0}));
    CHECK(near(hit->normal, {-1, 0, 0}));
    // Past the first two: the hole's far wall, its normal facing the hole.
    hit = t.intersect(ray, 9.0, kInfinity);
    REQUIRE(hit);
    CHECK(near(hit->position, {1.5, 0, 0}));
    CHECK(near(hit->normal, {-1, 0, 0}));
    // Down the axis through the hole: no hit; down onto the tube: its top.
    CHECK_FALSE(t.intersect({{0, 5, 0}, {0, -1, 0}}, 0.0, kInfinity));
    hit = t.intersect({{0, 5, 2}, {0, -1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.5).margin(1e-12));
    CHECK(near(hit->normal, {0, 1, 0}));
    // Grazing the top of the tube from the side (tangent along y = 0.5): a
    // line at y = 0.5 + 1e-6 misses.
    CHECK_FALSE(t.intersect({{-10, 0.5 + 1e-6, 0}, {1, 0, 0}}, 0.0, kInfinity));
    CHECK(t.intersect({{-10, 0.5 - 1e-6, 0}, {1, 0, 0}}, 0.0, kInfinity));
    // From inside the tube: the first crossing is where the ray leaves.
    hit = t.intersect({{2, 0, 0}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1.5).epsilon(1e-12));  // where sqrt(4 + t^2) = 2.5
    // A diagonal ray, checked against the implicit surface.
    const Ray diag{{-4, 1.2, -3}, glm::normalize(Vec3(1.0, -0.3, 0.8))};
    const Crossings d = t.crossings(diag, 0.0, kInfinity);
    REQUIRE(d.count >= 2);
    for (int i = 0; i < d.count; ++i) {
        const Vec3 p = diag.at(d.hits[i].t);
        const double across = std::sqrt(p.x * p.x + p.z * p.z) - 2.0;
        CHECK(std::abs(across * across + p.y * p.y - 0.25) < 1e-12);
    }
}

TEST_CASE("Torus far away and transformed", "[shapes][torus]") {
    // A ray from far off keeps its precision (the root search starts on the
    // swept sphere).
    const Primitive t = torus(1.0, 0.25, Transform::translate({0, 0, 1e4}));
    const auto hit = t.intersect({{0, 0.0, 0}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1e4 - 1.25).epsilon(1e-14));
    // Scaled non-uniformly and rotated: bounds hold the surface.
    const Transform m = Transform::rotateDegrees({30, 10, 60}) * Transform::scale({1, 2, 0.5});
    const Primitive s = torus(1.5, 0.5, m);
    const Bounds3 b = s.worldBounds();
    for (int i = 0; i < 64; ++i) {
        const double u = 2 * kPi * i / 64, v = 2 * kPi * ((i * 7) % 64) / 64;
        const Vec3 p = m.point(Vec3((1.5 + 0.5 * std::cos(v)) * std::cos(u), 0.5 * std::sin(v),
                                    (1.5 + 0.5 * std::cos(v)) * std::sin(u)));
        CHECK(glm::all(glm::lessThanEqual(b.lo, p)));
        CHECK(glm::all(glm::lessThanEqual(p, b.hi)));
    }
}

TEST_CASE("Torus inside is POV-Ray's", "[shapes][torus]") {
    const Primitive t = torus(2.0, 0.5);
    CHECK(t.inside({2, 0, 0}));
    CHECK(t.inside({0, 0.3, -2.2}));
    CHECK(t.inside({2.5, 0, 0}));  // the surface counts as inside
    CHECK_FALSE(t.inside({0, 0, 0}));
    CHECK_FALSE(t.inside({2, 0.6, 0}));
    CHECK(t.selfOcclusion() == Primitive::SelfOcclusion::Any);
    CHECK_FALSE(t.convex());
    CHECK(t.canShadowItself());
}

TEST_CASE("Torus cone classification: known answers", "[shapes][torus]") {
    const Primitive t = torus(2.0, 0.5);
    Cone c;
    c.apex = {2, 10, 0};
    c.axis = {0, -1, 0};
    c.halfAngle = 0.01;  // well inside the tube seen from above
    ConeClass k = t.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear <= 9.5);
    CHECK(k.tFar >= 9.5);
    c.halfAngle = 0.2;  // wider than the tube: its edges show
    CHECK(t.classify(c).coverage == Coverage::Marginal);
    c.apex = {0, 10, 0};  // down through the hole
    c.halfAngle = 0.05;
    CHECK(t.classify(c).coverage != Coverage::Full);
    c.axis = {0, 1, 0};  // looking away
    CHECK(t.classify(c).coverage == Coverage::Miss);
    c.apex = {2, 0, 0};  // from inside the tube: never Full by the ball test
    c.axis = {0, 0, 1};
    c.halfAngle = 0.01;
    CHECK(t.classify(c).coverage == Coverage::Marginal);
    c.apex = {2, 10, 0};  // range before the torus
    c.axis = {0, -1, 0};
    c.tMax = 5.0;
    CHECK(t.classify(c).coverage == Coverage::Miss);
}

TEST_CASE("Torus records POV-Ray refuses or we do", "[shapes][torus]") {
    CHECK_THROWS_WITH(torus(1.0, 0.0), "the minor radius of a torus must be positive, not 0");
    CHECK_THROWS_WITH(torus(0.5, 1.0),
                      "a torus whose minor radius 1 exceeds its major radius 0.5 (POV-Ray's spindle torus) is "
                      "not supported");
}

TEST_CASE("Torus cone classification is conservative (property)", "[shapes][torus][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("torus", 0x70a05ull, 20000, [](Rng& rng) {
        ShapeCase sc;
        const double major = rng.uniform(0.5, 2.0);
        const double minor = major * rng.uniform(0.05, 1.0);
        sc.shape = TorusShape{major, minor, false};
        sc.surfacePoint = [=](Rng& r) {
            const double u = r.uniform(0.0, 2.0 * kPi), v = r.uniform(0.0, 2.0 * kPi);
            const double rho = major + minor * std::cos(v);
            return Vec3(rho * std::cos(u), minor * std::sin(v), rho * std::sin(u));
        };
        sc.size = major + minor;
        sc.text = "torus { " + fmt(major) + ", " + fmt(minor) + " }";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}
