#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "asos/shapes/primitive.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {
// The torus { R, r } as POV-Ray's quartic: (|x|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2).
PolyShape torusQuartic(double major, double minor) {
    const double big = major * major, k = big - minor * minor;
    PolyShape p;
    p.order = 4;
    p.keyword = "quartic";
    p.coefficients = {1, 0, 0, 0, 2, 0, 0, 2, 0, 2 * k - 4 * big, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                      1, 0, 0, 2, 0, 2 * k, 0, 0, 0, 0, 1, 0, 2 * k - 4 * big, 0, k * k};
    return p;
}
// x^2 + y^2 + z^2 - r^2 as poly 2.
PolyShape spherePoly(double radius) {
    PolyShape p;
    p.order = 2;
    p.coefficients = {1, 0, 0, 0, 1, 0, 0, 1, 0, -radius * radius};
    return p;
}
// y - x^2 z^2 (shapesq.inc's Crossed_Trough, upside down): unbounded.
PolyShape crossedTrough() {
    PolyShape p;
    p.order = 4;
    p.coefficients.assign(35, 0.0);
    p.coefficients[7] = 4;    // x^2 z^2
    p.coefficients[29] = -1;  // y
    return p;
}
bool near(const Vec3& a, const Vec3& b, double tol = 1e-9) { return glm::length(a - b) <= tol; }
}  // namespace

TEST_CASE("Poly coefficients in POV-Ray's order", "[shapes][poly]") {
    // One term at a time: the coefficient's place names x^i y^j z^k, i from
    // N down, then j, then k.
    const int order = 3;
    int n = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k, ++n) {
                std::vector<double> c(static_cast<std::size_t>(PolyShape::termCount(order)), 0.0);
                c[static_cast<std::size_t>(n)] = 1.0;
                const Poly p(order, c);
                const Vec3 at(1.5, -0.7, 2.3);
                CHECK(p.value(at) == Approx(std::pow(1.5, i) * std::pow(-0.7, j) * std::pow(2.3, k)));
            }
    CHECK(n == 20);
    CHECK(PolyShape::termCount(4) == 35);
    CHECK(PolyShape::termCount(6) == 84);
}

TEST_CASE("A quartic torus hits where TorusShape does", "[shapes][poly]") {
    const Primitive q = Primitive::make(torusQuartic(2.0, 0.5), {});
    const Primitive t = Primitive::make(TorusShape{2.0, 0.5, false}, {});
    const Ray ray{{-10, 0, 0}, {1, 0, 0}};
    const Crossings all = q.crossings(ray, 0.0, kInfinity);
    REQUIRE(all.count == 4);
    CHECK(all.hits[0].t == Approx(7.5).margin(1e-12));
    CHECK(all.hits[1].t == Approx(8.5).margin(1e-12));
    CHECK(all.hits[2].t == Approx(11.5).margin(1e-12));
    CHECK(all.hits[3].t == Approx(12.5).margin(1e-12));
    CHECK(near(q.intersect(ray, 0.0, kInfinity)->normal, {-1, 0, 0}));
    // Rays in many directions: the same first hit and normal as the torus.
    int hits = 0;
    for (int i = 0; i < 400; ++i) {
        const double a = 0.37 * i, b = 0.11 * i;
        const Vec3 origin(6 * std::cos(a), 3 * std::sin(b), 6 * std::sin(a));
        const Vec3 target(2.2 * std::cos(1.7 * a), 0.6 * std::sin(2.3 * b), 2.2 * std::sin(1.3 * a));
        const Ray r{origin, glm::normalize(target - origin)};
        const auto hq = q.intersect(r, 0.0, kInfinity);
        const auto ht = t.intersect(r, 0.0, kInfinity);
        REQUIRE(hq.has_value() == ht.has_value());
        if (!hq) continue;
        ++hits;
        CHECK(hq->t == Approx(ht->t).margin(1e-9));
        CHECK(near(hq->normal, ht->normal, 1e-7));
    }
    CHECK(hits > 100);
    // Far away: the root search starts on the ball that bounds it.
    const Primitive far = Primitive::make(torusQuartic(1.0, 0.25), Transform::translate({0, 0, 1e4}));
    const auto hit = far.intersect({{0, 0, 0}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1e4 - 1.25).epsilon(1e-13));
}

TEST_CASE("A sphere as poly 2, tangent rays", "[shapes][poly]") {
    const Primitive s = Primitive::make(spherePoly(1.0), Transform::translate({0, 1, 0}));
    auto hit = s.intersect({{0, 1, -5}, {0, 0, 1}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(4.0).margin(1e-12));
    CHECK(near(hit->normal, {0, 0, -1}));
    // From inside: the exit.
    hit = s.intersect({{0, 1, 0}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(1.0).margin(1e-12));
    // Grazing: just inside hits, just outside misses.
    CHECK(s.intersect({{-5, 2.0 - 1e-7, 0}, {1, 0, 0}}, 0.0, kInfinity));
    CHECK_FALSE(s.intersect({{-5, 2.0 + 1e-7, 0}, {1, 0, 0}}, 0.0, kInfinity));
    // The bounds hold the sphere and are tight to a cell of the octree.
    const Bounds3 b = s.worldBounds();
    CHECK(b.lo.x <= -1.0);
    CHECK(b.hi.y >= 2.0);
    CHECK(b.hi.x < 1.5);
    // Inside is POV-Ray's: f < 1e-4.
    CHECK(s.inside({0, 1, 0}));
    CHECK(s.inside({0, 2.00001, 0}));  // within the tolerance
    CHECK_FALSE(s.inside({0, 2.1, 0}));
}

TEST_CASE("An unbounded quartic", "[shapes][poly]") {
    const Primitive p = Primitive::make(crossedTrough(), {});
    CHECK_FALSE(p.bounded());
    // Down onto y = 4 x^2 z^2 at x = z = 0.5: y = 0.25.
    auto hit = p.intersect({{0.5, 10, 0.5}, {0, -1, 0}}, 0.0, kInfinity);
    REQUIRE(hit);
    CHECK(hit->t == Approx(9.75).margin(1e-12));
    // Along x at y = 1, z = 1: 4 x^2 = 1, x = -0.5 then 0.5.
    const Crossings c = p.crossings({{-10, 1, 1}, {1, 0, 0}}, 0.0, kInfinity);
    REQUIRE(c.count == 2);
    CHECK(c.hits[0].t == Approx(9.5).margin(1e-12));
    CHECK(c.hits[1].t == Approx(10.5).margin(1e-12));
}

TEST_CASE("Poly cone classification: known answers", "[shapes][poly]") {
    const Primitive s = Primitive::make(spherePoly(1.0), {});
    Cone c;
    c.apex = {0, 0, -5};
    c.axis = {0, 0, 1};
    c.halfAngle = 0.01;  // well inside the sphere's outline
    ConeClass k = s.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear <= 4.0);
    CHECK(k.tFar >= 4.0);
    c.halfAngle = 0.3;  // its outline inside the cone
    CHECK(s.classify(c).coverage == Coverage::Marginal);
    c.axis = glm::normalize(Vec3(0.5, 0, 1));  // beside it
    c.halfAngle = 0.01;
    CHECK(s.classify(c).coverage == Coverage::Miss);
    c.axis = {0, 0, 1};
    c.tMax = 3.0;  // the range ends before it
    CHECK(s.classify(c).coverage == Coverage::Miss);
    // From inside, looking out: every ray leaves through the surface.
    c.apex = {0, 0, 0};
    c.tMax = kInfinity;
    k = s.classify(c);
    CHECK(k.coverage == Coverage::Full);
    CHECK(k.tNear <= 1.0);
    CHECK(k.tFar >= 1.0);

    const Primitive t = Primitive::make(torusQuartic(2.0, 0.5), {});
    c = Cone{};
    c.apex = {2, 10, 0};
    c.axis = {0, -1, 0};
    c.halfAngle = 0.01;  // inside the tube seen from above
    CHECK(t.classify(c).coverage == Coverage::Full);
    c.apex = {0, 10, 0};  // down the hole
    CHECK(t.classify(c).coverage == Coverage::Miss);
    c.halfAngle = 0.2;  // the tube's inner edge in it
    CHECK(t.classify(c).coverage == Coverage::Marginal);

    // Unbounded: a cone up the trough's empty side never meets it.
    const Primitive u = Primitive::make(crossedTrough(), {});
    c = Cone{};
    c.apex = {0.5, 10, 0.5};
    c.axis = {0, 1, 0};
    c.halfAngle = 0.01;
    CHECK(u.classify(c).coverage != Coverage::Full);
    c.axis = {0, -1, 0};  // down onto it: not a Miss
    CHECK(u.classify(c).coverage != Coverage::Miss);
}

TEST_CASE("Poly records POV-Ray refuses", "[shapes][poly]") {
    PolyShape p = spherePoly(1.0);
    p.order = 1;
    CHECK_THROWS_WITH(Primitive::make(p, {}), "the order of a poly must be 2 to 35, not 1");
    p = spherePoly(1.0);
    p.coefficients.pop_back();
    CHECK_THROWS_WITH(Primitive::make(p, {}), "a poly of order 2 takes 10 coefficients, not 9");
    p = torusQuartic(1.0, 0.5);
    p.coefficients.push_back(1.0);
    CHECK_THROWS_WITH(Primitive::make(p, {}), "a quartic takes 35 coefficients, not 36");
    p = spherePoly(1.0);
    p.coefficients.assign(10, 0.0);
    p.coefficients[9] = 1.0;
    CHECK_THROWS_WITH(Primitive::make(p, {}), "a poly without a term in x, y or z has no surface");
}

TEST_CASE("Poly cone classification is conservative (property)", "[shapes][poly][property]") {
    using namespace shapetest;
    const PropertyStats stats = runConeProperty("poly", 0x9017ull, 1500, [](Rng& rng) {
        ShapeCase sc;
        const double major = rng.uniform(0.5, 2.0);
        const double minor = major * rng.uniform(0.1, 0.9);
        sc.shape = torusQuartic(major, minor);
        sc.surfacePoint = [=](Rng& r) {
            const double u = r.uniform(0.0, 2.0 * kPi), v = r.uniform(0.0, 2.0 * kPi);
            const double rho = major + minor * std::cos(v);
            return Vec3(rho * std::cos(u), minor * std::sin(v), rho * std::sin(u));
        };
        sc.size = major + minor;
        sc.text = "quartic torus " + fmt(major) + ", " + fmt(minor);
        return sc;
    });
    CHECK(stats.failures == 0);
    CHECK(stats.full > 0);
    CHECK(stats.marginal > 0);
    CHECK(stats.miss > 0);
}
