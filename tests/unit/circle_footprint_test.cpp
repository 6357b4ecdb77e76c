// The footprint ellipse against circles (conegeom::CircleFootprint, the
// disc's fast path): every decided answer agrees with the ellipse traced by
// the cone's rim rays, and the undecided ones are rare.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "asos/geometry/margins.hpp"
#include "asos/shapes/cone_geometry.hpp"

using namespace asos;
using namespace asos::conegeom;

namespace {

struct Extent {
    double nearest;   // of the ellipse (0 when it holds the origin)
    double farthest;
};

// The footprint on z = 0 of the cone's rim rays, sampled densely, and
// whether the origin's direction is in the cone.
Extent tracedExtent(const LocalCone& cone) {
    const Vec3 a = cone.axis;
    const Vec3 u = glm::normalize(std::abs(a.x) < 0.9 ? glm::cross(a, Vec3(1, 0, 0))
                                                      : glm::cross(a, Vec3(0, 1, 0)));
    const Vec3 v = glm::cross(a, u);
    Extent e{kInfinity, 0.0};
    for (int i = 0; i < 20000; ++i) {
        const double phi = 2.0 * kPi * i / 20000.0;
        const Vec3 d = cone.cosHalf * a + cone.sinHalf * (std::cos(phi) * u + std::sin(phi) * v);
        const double t = -cone.apex.z / d.z;
        const Vec3 x = cone.apex + t * d;
        const double r = std::sqrt(x.x * x.x + x.y * x.y);
        e.nearest = std::min(e.nearest, r);
        e.farthest = std::max(e.farthest, r);
    }
    const Vec3 w = glm::normalize(-cone.apex);
    if (glm::dot(w, a) >= cone.cosHalf) e.nearest = 0.0;
    return e;
}

LocalCone makeCone(const Vec3& apex, const Vec3& axis, double halfAngle) {
    LocalCone cone;
    cone.apex = apex;
    cone.axis = glm::normalize(axis);
    cone.cosHalf = std::cos(halfAngle);
    cone.sinHalf = std::sin(halfAngle);
    cone.setRange(0.0, kInfinity, kPositionTolerance * (std::abs(apex.x) + std::abs(apex.y) + apex.z + 1.0));
    return cone;
}

CircleFootprint footprint(const LocalCone& cone) {
    const double depth = cone.apex.z, an = -cone.axis.z;
    const double k = cone.cosHalf * cone.cosHalf - (1.0 - an * an);
    return CircleFootprint(cone, depth, an, k);
}

}  // namespace

TEST_CASE("The footprint ellipse against circles agrees with the traced ellipse",
          "[shapes][cone_geometry]") {
    std::mt19937_64 rng(77);
    auto uniform = [&](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    int decided = 0, unsure = 0, crossing = 0, inside = 0, outside = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 apex(uniform(-3, 3), uniform(-3, 3), uniform(0.5, 20.0));
        const double halfAngle = std::pow(10.0, uniform(-4.0, -0.5));
        // Aimed at a point near the unit circle.
        const double phi = uniform(0.0, 2.0 * kPi), r = uniform(0.0, 2.0);
        const Vec3 target(r * std::cos(phi), r * std::sin(phi), 0.0);
        const LocalCone cone = makeCone(apex, target - apex, halfAngle);
        const double an = -cone.axis.z;
        const double k = cone.cosHalf * cone.cosHalf - (1.0 - an * an);
        if (!(k > 1e-6)) continue;
        const Extent e = tracedExtent(cone);
        const CircleFootprint f = footprint(cone);
        for (const double rho : {0.3, 1.0, r, r * (1.0 + 1e-3), e.farthest * 1.001, e.nearest * 0.999}) {
            if (!(rho > 0.0)) continue;
            const double slack = 1e-6 * (rho + e.farthest);
            switch (f.relation(rho)) {
                case CircleRelation::EllipseInside:
                    ++inside;
                    CHECK(e.farthest < rho + slack);
                    break;
                case CircleRelation::EllipseOutside:
                    ++outside;
                    CHECK(e.nearest > rho - slack);
                    break;
                case CircleRelation::Crossing:
                    ++crossing;
                    CHECK(e.nearest < rho + slack);
                    CHECK(e.farthest > rho - slack);
                    break;
                case CircleRelation::Unsure: {
                    ++unsure;
                    // Undecided only near tangency, relative to the
                    // footprint's size where that is small next to the circle.
                    const double size = e.farthest - e.nearest;
                    const double gap = std::min(std::abs(rho - e.nearest), std::abs(rho - e.farthest));
                    CHECK_FALSE((size < 0.1 * rho && gap > 0.1 * size));
                    continue;
                }
            }
            ++decided;
        }
    }
    CHECK(inside > 100);
    CHECK(outside > 100);
    CHECK(crossing > 100);
    CHECK(unsure < decided);
}

TEST_CASE("The footprint ellipse centred on the circles' centre is not misjudged",
          "[shapes][cone_geometry]") {
    // Head-on: the ellipse is a circle about the origin (d = 0), where the
    // direction of its centre is undefined; the answer is Unsure, or right.
    const LocalCone cone = makeCone({0, 0, 5}, {0, 0, -1}, 0.01);
    const CircleFootprint f = footprint(cone);
    const double footprintRadius = 5.0 * std::tan(0.01);
    for (const double rho : {0.5 * footprintRadius, 2.0 * footprintRadius}) {
        const CircleRelation rel = f.relation(rho);
        if (rho < footprintRadius) CHECK((rel == CircleRelation::Crossing || rel == CircleRelation::Unsure));
        else CHECK((rel == CircleRelation::EllipseInside || rel == CircleRelation::Unsure));
    }
    // A tiny cone straight above a point of the circle: surely crossing.
    const LocalCone onRim = makeCone({1, 0, 5}, {0, 0, -1}, 1e-6);
    CHECK(footprint(onRim).relation(1.0) != CircleRelation::EllipseInside);
    CHECK(footprint(onRim).relation(1.0) != CircleRelation::EllipseOutside);
}
