// Creases in a Full cone (ConeClass::creaseParts): a box's edges between two
// faces turned to the apex, the rims of a capped cylinder's or cone's caps,
// a cone's tip. Property: random boxes, cylinders and cones under random
// transforms, against cones aimed at points on and beside their creases;
// every ray of a dense set inside a cone the classification calls Full and
// crease-free sees one part of the surface, and inside a creased one only
// the parts it names (probeCone checks both). And known answers: which
// parts, and when a crease is a single edge.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "asos/testing/cone_probe.hpp"
#include "shape_property.hpp"

using namespace asos;
using shapetest::fmt;

namespace {

struct CreasedShape {
    Shape shape;
    Vec3 creasePoint;  // object space, on a crease
    std::string text;
};

CreasedShape randomCreased(Rng& rng) {
    CreasedShape c;
    const double a = rng.uniform(0.3, 2.0), b = rng.uniform(0.3, 2.0), h = rng.uniform(0.3, 2.0);
    switch (rng.index(4)) {
        case 0: {
            c.shape = BoxShape{{-a, -b, -h}, {a, b, h}};
            const int k = rng.index(3);  // an edge along axis k
            const Vec3 half(a, b, h);
            Vec3 p;
            for (int i = 0; i < 3; ++i) p[i] = (rng.chance(0.5) ? 1.0 : -1.0) * half[i];
            p[k] = rng.uniform(-half[k], half[k]);
            c.creasePoint = p;
            c.text = "box " + fmt(half);
            break;
        }
        case 1: {
            c.shape = CylinderShape{{0, 0, 0}, {0, h, 0}, a, false};
            const double phi = rng.uniform(0.0, 2.0 * kPi);
            c.creasePoint = Vec3(a * std::cos(phi), rng.chance(0.5) ? 0.0 : h, a * std::sin(phi));
            c.text = "cylinder r " + fmt(a) + " h " + fmt(h);
            break;
        }
        case 2: {
            const double r1 = rng.chance(0.5) ? 0.0 : b;
            c.shape = ConeShape{{0, 0, 0}, a, {0, h, 0}, r1, false};
            const double phi = rng.uniform(0.0, 2.0 * kPi);
            const bool top = rng.chance(0.5);
            const double r = top ? r1 : a;
            c.creasePoint = Vec3(r * std::cos(phi), top ? h : 0.0, r * std::sin(phi));
            c.text = "cone r0 " + fmt(a) + " r1 " + fmt(r1) + " h " + fmt(h);
            break;
        }
        default: {
            // An open pointed cone: its tip alone.
            c.shape = ConeShape{{0, 0, 0}, a, {0, h, 0}, 0.0, true};
            c.creasePoint = Vec3(0.0, h, 0.0);
            c.text = "open cone r0 " + fmt(a) + " h " + fmt(h);
        }
    }
    return c;
}

}  // namespace

TEST_CASE("Creases: the rays of a Full cone see one part unless it names a crease, and then only its parts",
          "[crease][property]") {
    int cases = 0, full = 0, creased = 0, single = 0, failures = 0;
    shapetest::forEachCase(0xc4ea5e00ull, 60000, [&](int i, std::uint64_t seed, Rng& rng) {
        const CreasedShape s = randomCreased(rng);
        const shapetest::TransformCase tc = shapetest::randomTransform(rng, 5.0);
        const Primitive prim = Primitive::make(s.shape, tc.worldFromObject);
        Cone cone;
        const double half = rng.uniform() < 0.8 ? rng.logUniform(-4.0, -1.5) : rng.logUniform(-1.5, -0.4);
        const double distance = rng.logUniform(0.3, 1.5);
        // Aimed at the crease, or beside it by up to a few footprints.
        const Vec3 aim = s.creasePoint + rng.unitVector() * (distance * half * rng.uniform(0.0, 4.0));
        const Vec3 eye = rng.chance(0.9) ? aim + distance * rng.unitVector() : Vec3(0.0, 0.05, 0.0);
        cone.apex = tc.worldFromObject.point(eye);
        cone.axis = glm::normalize(tc.worldFromObject.point(aim) - cone.apex);
        cone.halfAngle = half;
        const ConeClass k = prim.classify(PreparedCone(cone, true));
        ++cases;
        if (k.coverage != Coverage::Full) return;
        ++full;
        creased += k.creaseParts != 0;
        single += k.creaseParts != 0 && k.singleEdge;
        const ProbeResult probe = probeCone(prim, cone, k, ProbeDensity{8, 8, 192}, true);
        if (probe.violations > 0 && failures++ < 5)
            FAIL_CHECK("case " << i << " (seed " << seed << "): " << s.text << " under " << tc.text << "\n  "
                               << shapetest::describe(cone) << "\n  creaseParts " << int(k.creaseParts)
                               << " singleEdge " << k.singleEdge << ": " << probe.firstViolation);
    });
    INFO(cases << " cases, " << full << " Full, " << creased << " with creases, " << single << " single");
    CHECK(failures == 0);
    CHECK(full > 10000);
    CHECK(creased > 3000);
    CHECK(single > 500);
    CHECK(full - creased > 3000);
}

namespace {

ConeClass look(const Primitive& p, const Vec3& eye, const Vec3& target, double half = 2e-3) {
    Cone c;
    c.apex = eye;
    c.axis = glm::normalize(target - eye);
    c.halfAngle = half;
    return p.classify(PreparedCone(c, true));
}

constexpr std::uint8_t bit(int part) { return static_cast<std::uint8_t>(1u << part); }

}  // namespace

TEST_CASE("Creases: known answers for a box, a cylinder and a cone", "[crease]") {
    const Transform id;
    SECTION("a box seen across its vertical edge") {
        // Faces x = 1 (part 1) and z = -1 (part 4) turned to the eye.
        const Primitive box = Primitive::make(BoxShape{{-1, -1, -1}, {1, 1, 1}}, id);
        const Vec3 eye(5.0, 0.3, -5.0);
        ConeClass k = look(box, eye, {1.0, 0.0, -1.0});
        CHECK(k.coverage == Coverage::Full);
        CHECK(k.creaseParts == (bit(1) | bit(4)));
        CHECK(k.singleEdge);
        // Inside one face: no crease.
        k = look(box, eye, {1.0, 0.0, 0.0});
        CHECK(k.coverage == Coverage::Full);
        CHECK(k.creaseParts == 0);
        // Over the corner where three faces turned to the eye meet.
        k = look(box, {5.0, 5.0, -5.0}, {1.0, 1.0, -1.0});
        CHECK(k.coverage == Coverage::Full);
        CHECK(k.creaseParts == (bit(1) | bit(3) | bit(4)));
        CHECK_FALSE(k.singleEdge);
    }
    SECTION("a box seen from inside: its edges are creases too") {
        const Primitive room = Primitive::make(BoxShape{{-3, 0, -3}, {3, 3, 3}}, id);
        const ConeClass k = look(room, {0.0, 1.5, 0.0}, {3.0, 1.5, 3.0}, 1e-2);
        CHECK(k.coverage == Coverage::Full);
        CHECK(k.creaseParts == (bit(1) | bit(5)));
    }
    SECTION("a capped cylinder's rim between its side and its top") {
        const Primitive can = Primitive::make(CylinderShape{{0, 0, 0}, {0, 1, 0}, 0.5, false}, id);
        const Vec3 eye(0.0, 3.0, -4.0);
        ConeClass k = look(can, eye, {0.0, 1.0, -0.5});
        CHECK(k.coverage == Coverage::Full);
        CHECK(k.creaseParts == (bit(0) | bit(2)));
        CHECK_FALSE(k.singleEdge);  // a circle
        CHECK(look(can, eye, {0.0, 1.0, 0.0}).creaseParts == 0);
        CHECK(look(can, eye, {0.0, 0.5, -0.5}).creaseParts == 0);
    }
    SECTION("a pointed cone seen from above its tip") {
        const Primitive cone = Primitive::make(ConeShape{{0, 0, 0}, 1.0, {0, 1, 0}, 0.0, false}, id);
        const ConeClass k = look(cone, {0.0, 5.0, -0.5}, {0.0, 1.0, 0.0});
        CHECK(k.coverage == Coverage::Full);
        CHECK((k.creaseParts & ConeClass::kTipCrease) != 0);
        CHECK(look(cone, {0.0, 5.0, -0.5}, {0.0, 0.5, -0.5}).creaseParts == 0);
    }
}
