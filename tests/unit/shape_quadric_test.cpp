#include <catch2/catch.hpp>

#include <cmath>

#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
Primitive quadric(Vec3 squares, Vec3 mixed, Vec3 linear, double constant, const Transform& t = {}) {
    return Primitive::make(QuadricShape{squares, mixed, linear, constant}, t);
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Quadric ray hits follow POV-Ray's coefficients", "[shapes][quadric]") {
    // shapes_old.inc's Sphere: x^2 + y^2 + z^2 - 1 = 0, bounded.
    const Primitive sphere = quadric({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
    CHECK(sphere.bounded());
    auto hit = sphere.intersect({{0, 0, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0));
    CHECK(near(hit->normal, {0, 0, -1}));
    // From inside: the far side, the normal still the gradient (outward).
    hit = sphere.intersect({{0, 0, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1.0));
    CHECK(near(hit->normal, {1, 0, 0}));
    CHECK_FALSE(sphere.intersect({{0, 2, -5}, {0, 0, 1}}, 0.0, kInfinity));
    // Its bounds: the unit box, a little padded.
    CHECK(sphere.worldBounds().lo.x == Approx(-1.0).epsilon(1e-6));
    CHECK(sphere.worldBounds().hi.z == Approx(1.0).epsilon(1e-6));

    // Cylinder_Y: x^2 + z^2 - 1 = 0, unbounded; the mixed terms split in two
    // (D xy: Q's xy and yx entries D/2 each).
    const Primitive cylinder = quadric({1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1);
    CHECK_FALSE(cylinder.bounded());
    hit = cylinder.intersect({{-3, 100, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(2.0));
    CHECK_FALSE(cylinder.intersect({{-3, 0, 0}, {0, 1, 0}}, 0.0, kInfinity));  // along, outside
    // xy - 1 = 0 (a hyperbolic cylinder): along x at y = 2 it is met at x = 1/2.
    hit = quadric({0, 0, 0}, {1, 0, 0}, {0, 0, 0}, -1).intersect({{-3, 2, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.x == Approx(0.5));
    // The paraboloid y = x^2 + z^2 (x^2 + z^2 - y = 0): a linear equation
    // along y, whose d.Q d is 0.
    hit = quadric({1, 0, 1}, {0, 0, 0}, {0, -1, 0}, 0).intersect({{2, -5, 0}, {0, 1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.y == Approx(4.0));
    CHECK(near(hit->normal, glm::normalize(Vec3(4, -1, 0))));
    // A grazing ray: x^2 + y^2 - 1 with a ray at y = 1 - 1e-8 along x from
    // x = -10 meets it near x = -1.4e-4, both roots kept apart.
    hit = quadric({1, 1, 0}, {0, 0, 0}, {0, 0, 0}, -1).intersect({{-10, 1 - 1e-8, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->position.x == Approx(-std::sqrt(1 - (1 - 1e-8) * (1 - 1e-8))).epsilon(1e-4));
    // Under a transform: the unit sphere scaled by 2 and moved up by 3.
    const Primitive moved = quadric({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1,
                                    Transform::translate({0, 3, 0}) * Transform::scale(Vec3(2)));
    hit = moved.intersect({{0, 3, -10}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(8.0));
}

TEST_CASE("Quadric cone classification: known answers", "[shapes][quadric]") {
    const Primitive sphere = quadric({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1);
    Cone c;
    c.apex = {0, 0, -5};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.01;
    ConeClass k = sphere.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear <= 4.0);
    CHECK(k.tFar >= 4.0);
    c.axis = glm::normalize(Vec3(0, 0.5, 1));  // well beside it
    CHECK(sphere.classify(c).coverage == Coverage::Miss);
    // The silhouette: marginal.
    c.axis = glm::normalize(Vec3(0, 1, std::sqrt(24.0)));
    CHECK(sphere.classify(c).coverage == Coverage::Marginal);

    // An unbounded cylinder seen from the side, away from it, and along it.
    const Primitive cylinder = quadric({1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1);
    c.apex = {0, 0, -6};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.02;
    k = cylinder.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear <= 5.0);
    CHECK(k.tFar >= 5.0);
    c.axis = {0, 0, -1};
    CHECK(cylinder.classify(c).coverage == Coverage::Miss);
    // Along its axis from outside: every ray grazes off to infinity; beyond
    // any distance d.Q d (~0 along y) leaves the sign open: marginal.
    c.apex = {3, 0, 0};
    c.axis = {0, 1, 0};
    CHECK(cylinder.classify(c).coverage == Coverage::Marginal);
    // A short range before the surface: a miss.
    c.apex = {0, 0, -6};
    c.axis = {0, 0, 1};
    c.tMax = 4.0;
    CHECK(cylinder.classify(c).coverage == Coverage::Miss);
}

TEST_CASE("Quadric degenerate input", "[shapes][quadric]") {
    CHECK_THROWS_WITH(quadric({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1),
                      "a quadric without a term in x, y or z has no surface");
    CHECK_THROWS_WITH(quadric({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, std::nan("")),
                      "the quadric's constant J must be finite, not nan");
}

TEST_CASE("Quadric cone classification is conservative (property)", "[shapes][quadric][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("quadric", 0x0adc1c00ull, 30000, [](Rng& rng) {
        ShapeCase sc;
        const double a = rng.uniform(0.4, 2.0), b = rng.uniform(0.4, 2.0), c = rng.uniform(0.4, 2.0);
        const int kind = static_cast<int>(rng.uniform(0.0, 6.0));
        auto angle = [](Rng& r) { return r.uniform(0.0, 2.0 * kPi); };
        switch (kind) {
            case 0:  // ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1
                sc.shape = QuadricShape{{1 / (a * a), 1 / (b * b), 1 / (c * c)}, {0, 0, 0}, {0, 0, 0}, -1};
                sc.surfacePoint = [=](Rng& r) {
                    const Vec3 u = r.unitVector();
                    return Vec3(a * u.x, b * u.y, c * u.z);
                };
                break;
            case 1:  // elliptic cylinder along z
                sc.shape = QuadricShape{{1 / (a * a), 1 / (b * b), 0}, {0, 0, 0}, {0, 0, 0}, -1};
                sc.surfacePoint = [=](Rng& r) {
                    const double p = angle(r);
                    return Vec3(a * std::cos(p), b * std::sin(p), r.uniform(-4, 4));
                };
                break;
            case 2:  // hyperboloid of one sheet
                sc.shape = QuadricShape{{1 / (a * a), 1 / (b * b), -1 / (c * c)}, {0, 0, 0}, {0, 0, 0}, -1};
                sc.surfacePoint = [=](Rng& r) {
                    const double p = angle(r), v = r.uniform(-1.5, 1.5);
                    return Vec3(a * std::cosh(v) * std::cos(p), b * std::cosh(v) * std::sin(p), c * std::sinh(v));
                };
                break;
            case 3:  // elliptic paraboloid z = x^2/a^2 + y^2/b^2
                sc.shape = QuadricShape{{1 / (a * a), 1 / (b * b), 0}, {0, 0, 0}, {0, 0, -1}, 0};
                sc.surfacePoint = [=](Rng& r) {
                    const double x = r.uniform(-2, 2), y = r.uniform(-2, 2);
                    return Vec3(x, y, x * x / (a * a) + y * y / (b * b));
                };
                break;
            case 4:  // cone x^2 + y^2 = z^2 / c^2, with its tip
                sc.shape = QuadricShape{{1, 1, -1 / (c * c)}, {0, 0, 0}, {0, 0, 0}, 0};
                sc.surfacePoint = [=](Rng& r) {
                    const double p = angle(r), s = r.uniform(-2, 2);
                    return Vec3(s * std::cos(p), s * std::sin(p), c * s);
                };
                break;
            default:  // hyperbolic paraboloid z = xy (mixed term) moved by linear terms
                sc.shape = QuadricShape{{0, 0, 0}, {1, 0, 0}, {0.3, 0, -1}, 0.2};
                sc.surfacePoint = [=](Rng& r) {
                    const double x = r.uniform(-2, 2), y = r.uniform(-2, 2);
                    return Vec3(x, y, x * y + 0.3 * x + 0.2);
                };
                break;
        }
        const auto& q = std::get<QuadricShape>(sc.shape);
        sc.size = 1.0;
        sc.text = "quadric { " + fmt(q.squares) + ", " + fmt(q.mixed) + ", " + fmt(q.linear) + ", " +
                  fmt(q.constant) + " }";
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}
