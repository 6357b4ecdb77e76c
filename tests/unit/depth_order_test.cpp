// The depth order of two objects over a cone (shapes/depth_order.hpp):
// objects in near contact (a disc or a polygon just above a plane, a box or
// a cylinder standing on one, a sphere resting on or sunk into one, two
// planes crossing) under random transforms, against random cones; wherever
// surelyInFront claims an order, every ray of a dense set inside the cone
// that meets both meets the claimed front one first. And known answers: the
// orders it must find (a rug above a floor, a box standing on it, two planes
// away from their line of intersection) and those it must not claim
// (coplanar shapes, a sphere sunk into a plane where it leaves the plane).
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "asos/shapes/depth_order.hpp"
#include "asos/testing/cone_probe.hpp"
#include "shape_property.hpp"

using namespace asos;
using shapetest::fmt;

namespace {

struct Pair {
    Shape front, back;  // in the canonical frame: back below y = 0, front above it (or sunk)
    std::string text;
};

// A gap between the two (the front object's lowest point above y = 0): in
// contact, just above (a decal), clearly above, or sunk into the back one.
double randomGap(Rng& rng) {
    const double gaps[] = {0.0, 0.0, 1e-4, 2e-3, 0.05, -1e-3, -0.2};
    return gaps[rng.index(7)];
}

Pair randomPair(Rng& rng) {
    Pair p;
    const double g = randomGap(rng);
    switch (rng.index(4)) {
        case 0: p.back = PlaneShape{{0, 1, 0}, 0.0}; p.text = "plane y = 0"; break;
        case 1: p.back = BoxShape{{-3, -1, -3}, {3, 0, 3}}; p.text = "box top y = 0"; break;
        case 2: p.back = DiscShape{{0, 0, 0}, {0, 1, 0}, 3.0, 0.0}; p.text = "disc y = 0"; break;
        default: p.back = PolygonShape{{{-3, 0, -3}, {3, 0, -3}, {3, 0, 3}, {-3, 0, 3}, {-3, 0, -3}}};
            p.text = "square y = 0";
    }
    const double r = rng.uniform(0.2, 1.0);
    switch (rng.index(9)) {
        case 0: p.front = DiscShape{{0, g, 0}, {0, 1, 0}, r, 0.0}; p.text += ", disc at " + fmt(g); break;
        case 1:
            p.front = PolygonShape{{{-r, g, -r}, {r, g, -0.5 * r}, {0.5 * r, g, r}, {-r, g, r}, {-r, g, -r}}};
            p.text += ", polygon at " + fmt(g);
            break;
        case 2: p.front = BoxShape{{-r, g, -0.5 * r}, {r, g + r, 0.5 * r}}; p.text += ", box on " + fmt(g); break;
        case 3: p.front = BoxShape{{-r, g, -r}, {r, g + 5e-4, r}}; p.text += ", paper box on " + fmt(g); break;
        case 4: p.front = SphereShape{{0, r + g, 0}, r}; p.text += ", sphere on " + fmt(g); break;
        case 5:
            p.front = CylinderShape{{0, g, 0}, {0, g + 2 * r, 0}, 0.5 * r, rng.chance(0.3)};
            p.text += ", cylinder standing on " + fmt(g);
            break;
        case 6:
            p.front = CylinderShape{{-r, g + 0.3 * r, 0}, {r, g + 0.3 * r, 0}, 0.3 * r, false};
            p.text += ", cylinder lying on " + fmt(g);
            break;
        case 7:
            p.front = ConeShape{{0, g, 0}, 0.6 * r, {0, g + 1.5 * r, 0}, rng.chance(0.5) ? 0.0 : 0.2 * r, rng.chance(0.3)};
            p.text += ", cone standing on " + fmt(g);
            break;
        default: {
            // A plane crossing y = 0 along a line (a wall on the floor).
            const double a = rng.uniform(-1.4, 1.4);
            p.front = PlaneShape{{std::sin(a), 0.0, -std::cos(a)}, rng.uniform(-1.0, 1.0)};
            p.text += ", a second plane at angle " + fmt(a);
        }
    }
    return p;
}

// Every ray of the probe that meets both objects meets `front` no later than
// `back`; returns the first that does not, or an empty string.
std::string contradiction(const Primitive& front, const Primitive& back, const Cone& cone) {
    const double tMin = std::max(cone.tMin, 0.0);
    for (const Vec3& d : probeDirections(cone, ProbeDensity{8, 8, 128})) {
        const auto a = front.intersect({cone.apex, d}, tMin, cone.tMax);
        const auto b = back.intersect({cone.apex, d}, tMin, cone.tMax);
        if (a && b && a->t > b->t + 1e-9 * (1.0 + b->t))
            return "the ray along " + fmt(d) + " meets the back object at " + fmt(b->t) +
                   ", the front one at " + fmt(a->t);
    }
    return {};
}

}  // namespace

TEST_CASE("Depth order: the object claimed in front is met first by every ray of the cone",
          "[depth_order][property]") {
    int cases = 0, claims = 0, failures = 0, fullPairs = 0, fullClaims = 0;
    shapetest::forEachCase(0xde9740d0ull, 40000, [&](int i, std::uint64_t seed, Rng& rng) {
        const Pair pair = randomPair(rng);
        const shapetest::TransformCase tc = shapetest::randomTransform(rng, 5.0);
        const Primitive front = Primitive::make(pair.front, tc.worldFromObject);
        const Primitive back = Primitive::make(pair.back, tc.worldFromObject);
        // A viewer above the plane, aimed near the contact.
        const Vec3 eye(rng.uniform(-4, 4), rng.logUniform(-1.5, 0.7), rng.uniform(-4, 4));
        const Vec3 target = rng.inBox({-1.5, -0.1, -1.5}, {1.5, 1.0, 1.5});
        Cone cone;
        cone.apex = tc.worldFromObject.point(eye);
        cone.axis = glm::normalize(tc.worldFromObject.point(target) - cone.apex);
        const double kind = rng.uniform();
        cone.halfAngle = kind < 0.7 ? rng.logUniform(-4.0, -1.5) : kind < 0.95 ? rng.logUniform(-1.5, -0.5)
                                                                                : rng.logUniform(-7.0, -4.0);
        if (rng.chance(0.2)) cone.tMin = rng.uniform(0.0, 0.5) * glm::length(cone.axis);
        const ConeClass kf = front.classify(cone), kb = back.classify(cone);
        if (kf.coverage == Coverage::Miss || kb.coverage == Coverage::Miss) return;
        ++cases;
        const PreparedCone prepared(cone);
        const bool bothFull = kf.coverage == Coverage::Full && kb.coverage == Coverage::Full;
        fullPairs += bothFull;
        for (int way = 0; way < 2; ++way) {
            const Primitive& a = way ? back : front;
            const Primitive& b = way ? front : back;
            if (!surelyInFront(a, way ? kb : kf, b, way ? kf : kb, prepared)) continue;
            ++claims;
            fullClaims += bothFull;
            const std::string wrong = contradiction(a, b, cone);
            if (!wrong.empty() && failures++ < 5)
                FAIL_CHECK("case " << i << " (seed " << seed << "): " << pair.text << " under " << tc.text
                                   << ", the " << (way ? "back" : "front") << " object claimed in front: "
                                   << wrong << "\n  " << shapetest::describe(cone));
        }
    });
    INFO(cases << " cases, " << claims << " claims; " << fullPairs << " with both Full, " << fullClaims
               << " of them ordered");
    CHECK(failures == 0);
    CHECK(cases > 5000);
    CHECK(claims > cases / 4);
    CHECK(fullClaims > fullPairs / 3);
}

namespace {

// A perspective pixel cone from `eye` toward `target`.
Cone pixelCone(const Vec3& eye, const Vec3& target, double halfAngle = 1e-3) {
    Cone c;
    c.apex = eye;
    c.axis = glm::normalize(target - eye);
    c.halfAngle = halfAngle;
    return c;
}

bool ordered(const Primitive& a, const Primitive& b, const Cone& cone) {
    const ConeClass ka = a.classify(cone), kb = b.classify(cone);
    REQUIRE(ka.coverage != Coverage::Miss);
    REQUIRE(kb.coverage != Coverage::Miss);
    return surelyInFront(a, ka, b, kb, PreparedCone(cone));
}

}  // namespace

TEST_CASE("Depth order: decals, objects standing on a floor, crossing planes", "[depth_order]") {
    const Transform id;
    const Primitive floor = Primitive::make(PlaneShape{{0, 1, 0}, 0.0}, id);
    const Vec3 eye(2.4, 1.65, -2.8);

    SECTION("a rug 2 mm above the floor, seen at any angle, grazing included") {
        const Primitive rug = Primitive::make(DiscShape{{0.4, 0.002, 0.6}, {0, 1, 0}, 1.3, 0.0}, id);
        for (int k = 0; k < 50; ++k) {
            const Vec3 target(0.4 + 1.2 * std::cos(k * 0.7) * (k % 5) / 5.0, 0.0,
                              0.6 + 1.2 * std::sin(k * 0.7) * (k % 5) / 5.0);
            const Vec3 from = k % 2 ? eye : Vec3(-3.0, 0.05, -2.0);  // the second nearly grazing
            const Cone cone = pixelCone(from, target);
            INFO("target " << fmt(target) << " from " << fmt(from));
            CHECK(ordered(rug, floor, cone));
            CHECK_FALSE(ordered(floor, rug, cone));
        }
    }
    SECTION("a disc lying on the floor itself is not ordered either way") {
        const Primitive disc = Primitive::make(DiscShape{{0, 0, 0}, {0, 1, 0}, 1.0, 0.0}, id);
        const Cone cone = pixelCone(eye, {0.2, 0.0, 0.1});
        CHECK_FALSE(ordered(disc, floor, cone));
        CHECK_FALSE(ordered(floor, disc, cone));
    }
    SECTION("a box standing on the floor, and a sphere resting on it, come first") {
        const Primitive box = Primitive::make(BoxShape{{-0.5, 0, -0.5}, {0.5, 0.7, 0.5}}, id);
        const Vec3 centre(1.5, 0.4, 0.0);
        const Primitive ball = Primitive::make(SphereShape{centre, 0.4}, id);
        const Vec3 toEye = glm::normalize(Vec3(eye.x - centre.x, 0.0, eye.z - centre.z));
        for (double y : {0.0005, 0.01, 0.3}) {
            INFO("height " << y);
            CHECK(ordered(box, floor, pixelCone(eye, {0.2, y, -0.5})));
            // The point of the ball at height y on the side toward the eye.
            const double across = std::sqrt(0.16 - (y - 0.4) * (y - 0.4));
            CHECK(ordered(ball, floor, pixelCone(eye, Vec3(centre.x, y, centre.z) + across * toEye)));
        }
    }
    SECTION("a sphere sunk into the floor: first where its cone part is above the floor, not across it") {
        const Primitive ball = Primitive::make(SphereShape{{0.0, 0.2, 0.0}, 0.5}, id);
        // The top of the ball, seen from above.
        CHECK(ordered(ball, floor, pixelCone({0.0, 3.0, -0.5}, {0.0, 0.7, 0.0})));
        // Where it leaves the floor (the circle of radius sqrt(0.21)).
        const Cone across = pixelCone({0.0, 3.0, -3.0}, {0.0, 0.0, -std::sqrt(0.21)});
        CHECK_FALSE(ordered(ball, floor, across));
        CHECK_FALSE(ordered(floor, ball, across));
    }
    SECTION("two planes, ordered where their line of intersection misses the cone") {
        const Primitive wall = Primitive::make(PlaneShape{{0, 0, -1}, -4.0}, id);  // z = 4, facing -z
        // The corner line y = 0, z = 4 seen from the eye: pixel cones above
        // and below it at growing angles from it.
        const Vec3 corner(0.0, 0.0, 4.0);
        const Vec3 toCorner = glm::normalize(corner - eye);
        const Vec3 up = glm::normalize(glm::cross(glm::cross(toCorner, Vec3(0, 1, 0)), toCorner));
        const double half = 1e-3;
        for (double angle : {-5e-3, -2.5e-3, 2.5e-3, 5e-3}) {
            Cone cone;
            cone.apex = eye;
            cone.axis = glm::normalize(toCorner + angle * up);
            cone.halfAngle = half;
            INFO("angle " << angle);
            // Above the corner line the wall is met first, below it the floor.
            CHECK(ordered(angle > 0 ? wall : floor, angle > 0 ? floor : wall, cone));
        }
        Cone on;
        on.apex = eye;
        on.axis = toCorner;
        on.halfAngle = half;
        CHECK_FALSE(ordered(wall, floor, on));
        CHECK_FALSE(ordered(floor, wall, on));
    }
}
