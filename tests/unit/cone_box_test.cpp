#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "asos/accel/cone_box.hpp"
#include "random_direction.hpp"

using namespace asos;

namespace {

// A unit vector orthogonal to w, and a third completing the frame.
void frame(const Vec3& w, Vec3& u, Vec3& v) {
    const Vec3 a = std::abs(w.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    u = glm::normalize(glm::cross(w, a));
    v = glm::cross(w, u);
}

using asos::test::randomUnit;

// Cones of every kind the tracer makes: pixel-sized, tiny, wide, wider than a
// hemisphere, single rays; finite and infinite t-ranges, some starting late.
Cone randomCone(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Cone c;
    c.apex = Vec3(u01(rng) - 0.5, u01(rng) - 0.5, u01(rng) - 0.5) * 4.0;
    c.axis = randomUnit(rng);
    switch (rng() % 6) {
        case 0: c.halfAngle = 0.0; break;
        case 1: c.halfAngle = 1e-4 * u01(rng); break;
        case 2: c.halfAngle = 0.01 * u01(rng); break;
        case 3: c.halfAngle = 0.6 * u01(rng); break;
        case 4: c.halfAngle = kPi / 2 * u01(rng); break;
        default: c.halfAngle = kPi / 2 + (kPi / 2 - 1e-3) * u01(rng); break;
    }
    if (rng() % 4 == 0) c.axis = Vec3(0, 0, (rng() % 2) ? 1.0 : -1.0);  // axis-aligned
    c.tMin = rng() % 2 ? 0.0 : 2.0 * u01(rng);
    c.tMax = rng() % 3 == 0 ? kInfinity : c.tMin + 3.0 * u01(rng) + 1e-3;
    return c;
}

// A point of the cone's solid for given fractions of the t-range, the
// half-angle and the azimuth.
Vec3 conePoint(const Cone& c, double tFraction, double angleFraction, double azimuth) {
    Vec3 u, v;
    frame(c.axis, u, v);
    const double far = std::isfinite(c.tMax) ? c.tMax : c.tMin + 20.0;
    const double t = c.tMin + tFraction * (far - c.tMin);
    const double psi = angleFraction * c.halfAngle;
    const Vec3 dir = std::cos(psi) * c.axis + std::sin(psi) * (std::cos(azimuth) * u + std::sin(azimuth) * v);
    return c.apex + t * dir;
}

// A box near the cone's boundary (where rejections are hardest to get right)
// or anywhere around it.
Bounds3 randomBox(std::mt19937_64& rng, const Cone& c) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    Vec3 centre;
    if (rng() % 4 == 0) {
        centre = c.apex + Vec3(u01(rng) - 0.5, u01(rng) - 0.5, u01(rng) - 0.5) * 8.0;
    } else {
        // Near the rim, the apex, or the ends of the t-range.
        const double tf = rng() % 3 == 0 ? (rng() % 2 ? 0.0 : 1.0) : u01(rng);
        centre = conePoint(c, tf, 1.0, 2 * kPi * u01(rng));
    }
    const double size = std::pow(10.0, -3.0 + 3.5 * u01(rng));
    Vec3 half(size * u01(rng), size * u01(rng), size * u01(rng));
    if (rng() % 5 == 0) half[static_cast<int>(rng() % 3)] = 0.0;  // flat boxes (axis-aligned polygons)
    const Vec3 offset = (Vec3(u01(rng), u01(rng), u01(rng)) - 0.5) * (2.0 * size);
    return {centre + offset - half, centre + offset + half};
}

std::string describe(const Cone& c, const Bounds3& b) {
    std::ostringstream s;
    s.precision(17);
    s << "cone apex (" << c.apex.x << "," << c.apex.y << "," << c.apex.z << ") axis (" << c.axis.x
      << "," << c.axis.y << "," << c.axis.z << ") halfAngle " << c.halfAngle << " t [" << c.tMin
      << "," << c.tMax << "] box (" << b.lo.x << "," << b.lo.y << "," << b.lo.z << ")-(" << b.hi.x
      << "," << b.hi.y << "," << b.hi.z << ")";
    return s.str();
}

// Dense evidence that the cone touches the box: a grid of the box's points
// inside the cone, or a point of the cone's rays (axis, rings, rim) in the box.
bool sampledTouch(const ConeBoxTest& test, const Bounds3& b) {
    const Cone& c = test.cone();
    constexpr int n = 6;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k) {
                const Vec3 f(i / double(n - 1), j / double(n - 1), k / double(n - 1));
                if (test.contains(b.lo + f * (b.hi - b.lo))) return true;
            }
    for (int ring = 0; ring <= 4; ++ring) {
        const int azimuths = ring == 0 ? 1 : 24;
        for (int a = 0; a < azimuths; ++a) {
            for (int s = 0; s <= 30; ++s) {
                if (b.contains(conePoint(c, s / 30.0, ring / 4.0, 2 * kPi * a / azimuths))) return true;
            }
        }
    }
    return false;
}

}  // namespace

TEST_CASE("Cone-box test never rejects a box the cone touches", "[accel][cone]") {
    std::mt19937_64 rng(12345);
    int touching = 0, rejected = 0;
    for (int trial = 0; trial < 20000; ++trial) {
        const Cone c = randomCone(rng);
        const ConeBoxTest test(c);
        const Bounds3 b = randomBox(rng, c);
        const bool touches = sampledTouch(test, b);
        const bool may = test.mayTouch(b);
        touching += touches;
        rejected += !may;
        if (touches && !may) FAIL("rejected a touching box: " << describe(c, b));
    }
    // The test must also do its job: many of these boxes are rejected.
    CHECK(touching > 2000);
    CHECK(rejected > 2000);
}

TEST_CASE("Cone distance is exact: never above a sampled distance, close to the minimum",
          "[accel][cone]") {
    std::mt19937_64 rng(777);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        Cone c = randomCone(rng);
        if (!std::isfinite(c.tMax)) c.tMax = c.tMin + 5.0;
        const ConeBoxTest test(c);
        const Vec3 x = c.apex + Vec3(u01(rng) - 0.5, u01(rng) - 0.5, u01(rng) - 0.5) * 10.0;
        const double d = test.distanceTo(x);
        double sampled = kInfinity;
        constexpr int nt = 40, na = 20, nz = 64;
        for (int i = 0; i <= nt; ++i)
            for (int j = 0; j <= na; ++j)
                for (int k = 0; k < nz; ++k)
                    sampled = std::min(sampled, glm::length(x - conePoint(c, i / double(nt), j / double(na),
                                                                           2 * kPi * k / nz)));
        INFO(describe(c, Bounds3::of(x)));
        CHECK(d <= sampled + 1e-9);
        // The samples are at most this far from any point of the cone.
        const double spacing = (c.tMax - c.tMin) / nt + c.tMax * (c.halfAngle / na + 2 * kPi / nz);
        CHECK(d >= sampled - spacing);
    }
}

TEST_CASE("Cone-box test rejects what lies behind, beside, before and beyond", "[accel][cone]") {
    Cone c;
    c.apex = Vec3(0.0);
    c.axis = Vec3(0, 0, 1);
    c.halfAngle = 0.1;
    c.tMin = 1.0;
    c.tMax = 10.0;
    const ConeBoxTest test(c);
    const Vec3 h(0.05);
    CHECK(test.mayTouch({Vec3(0, 0, 5) - h, Vec3(0, 0, 5) + h}));        // on the axis
    CHECK_FALSE(test.mayTouch({Vec3(0, 0, -5) - h, Vec3(0, 0, -5) + h}));  // behind
    CHECK_FALSE(test.mayTouch({Vec3(2, 0, 5) - h, Vec3(2, 0, 5) + h}));    // beside
    CHECK_FALSE(test.mayTouch({Vec3(0, 0, 0.5) - h, Vec3(0, 0, 0.5) + h}));  // before tMin
    CHECK_FALSE(test.mayTouch({Vec3(0, 0, 11) - h, Vec3(0, 0, 11) + h}));    // beyond tMax
    // Just outside the rim at t = 5 (rim radius 5 tan 0.1 = 0.5017), and just inside.
    CHECK_FALSE(test.mayTouch({Vec3(0.52, 0, 4.99), Vec3(0.6, 0.01, 5.0)}));
    CHECK(test.mayTouch({Vec3(0.49, 0, 4.99), Vec3(0.6, 0.01, 5.0)}));
    // A long thin box beside the cone, whose bounding sphere meets it: the
    // tangent plane rejects it.
    CHECK_FALSE(test.mayTouch({Vec3(0.8, -3, 4.9), Vec3(0.81, 3, 5.1)}));
    // Boxes centred on the axis, for axes in many directions (the centre's
    // offset from the axis is then rounding noise).
    std::mt19937_64 rng(5);
    for (int i = 0; i < 2000; ++i) {
        Cone d = c;
        d.axis = i < 8 ? glm::normalize(Vec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1)) : randomUnit(rng);
        d.halfAngle = i % 2 ? 1e-3 : 0.3;
        const Vec3 centre = d.apex + 1.7 * d.axis;
        INFO(describe(d, Bounds3::of(centre)));
        CHECK(ConeBoxTest(d).mayTouch({centre - 0.25, centre + 0.25}));
        CHECK_FALSE(ConeBoxTest(d).mayTouch({-centre - 0.25, -centre + 0.25}));
    }
    // A cone wider than a hemisphere reaches behind its apex.
    Cone wide = c;
    wide.halfAngle = 2.5;
    CHECK(ConeBoxTest(wide).mayTouch({Vec3(0, 2, -2) - h, Vec3(0, 2, -2) + h}));
    CHECK_FALSE(ConeBoxTest(wide).mayTouch({Vec3(0, 0, -5) - h, Vec3(0, 0, -5) + h}));
}

TEST_CASE("Cone-box test on degenerate input is defined", "[accel][cone]") {
    Cone c;
    c.axis = Vec3(0.0);  // no axis: accept everything (conservative)
    CHECK(ConeBoxTest(c).mayTouch({Vec3(5), Vec3(6)}));
    Cone empty;
    empty.tMin = 3.0;
    empty.tMax = 2.0;  // no point at all
    CHECK_FALSE(ConeBoxTest(empty).mayTouch({Vec3(-100), Vec3(100)}));
    Cone ray;  // halfAngle 0: a ray
    CHECK(ConeBoxTest(ray).mayTouch({Vec3(0, 0, 3), Vec3(0, 0, 3)}));  // a point on it
    CHECK_FALSE(ConeBoxTest(ray).mayTouch({Vec3(1e-6, 0, 3), Vec3(1e-6, 0, 3)}));
    CHECK_FALSE(ConeBoxTest(ray).mayTouch(Bounds3{}));  // an empty box
}
