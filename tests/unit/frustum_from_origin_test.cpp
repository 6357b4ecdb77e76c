#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "asos/shapes/cylinder.hpp"
#include "asos/shapes/frustum.hpp"
#include "asos/shapes/frustum_from_origin.hpp"
#include "asos/shapes/primitive.hpp"
#include "any_test_from.hpp"
#include "asos/shapes/truncated_cone.hpp"

using namespace asos;

namespace {

// Points on the solid's surface (side, rims and caps), the targets of
// grazing rays and of rays whose hit lies at an end of their t-range.
std::vector<Vec3> surfacePoints(const Frustum& f, std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<Vec3> out;
    for (int i = 0; i < 300; ++i) {
        const double phi = 2.0 * kPi * u(rng);
        const double z = i % 3 == 0 ? 0.0 : i % 3 == 1 ? f.length() : f.length() * u(rng);
        const double r = f.radiusAt(z) * (i % 5 == 0 ? u(rng) : 1.0);  // some on the caps
        out.push_back({r * std::cos(phi), r * std::sin(phi), z});
    }
    return out;
}

// Origins about the solid: beside it, above and below it, far, inside.
std::vector<Vec3> origins(const Frustum& f) {
    const double l = f.length(), r = std::max(f.r0(), f.r1());
    return {{3.0 * r, 0.2, -0.5 * l}, {-2.0 * r, 1.5 * r, 0.3 * l}, {0.1, 0.2, 3.0 * l},
            {0.05, -0.1, -2.0 * l}, {40.0 * r, -25.0 * r, 17.0 * l}, {0.1 * f.radiusAt(0.5 * l), 0.0, 0.5 * l},
            {1.2 * r, 0.0, l}, {f.r0(), 0.0, -1e-9}};
}

// Every decided answer equals the exact test's: rays toward a lattice
// about the solid, toward its surface points exactly (grazing the side and
// the rims) and nudged by a few ulps and by 1e-9, with t-ranges ending just
// before, at and just after the hit.
template <class Exact>
void checkAgainstExact(const Frustum& f, const Exact& exact) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::vector<Vec3> targets = surfacePoints(f, rng);
    const double l = f.length(), r = std::max(f.r0(), f.r1());
    long decided = 0, total = 0;  // of the lattice's rays
    for (const Vec3& o : origins(f)) {
        const FrustumFromOrigin fast(f, o);
        REQUIRE(fast.usable());
        const auto compare = [&](const Vec3& d, double tMin, double tMax, bool lattice = false) {
            const int answer = fast.decide(d, tMin, tMax);
            total += lattice;
            if (answer == FrustumFromOrigin::kUndecided) return;
            decided += lattice;
            INFO("origin " << o.x << " " << o.y << " " << o.z << " dir " << d.x << " " << d.y << " " << d.z
                           << " t " << tMin << " " << tMax);
            CHECK((answer != 0) == exact(Ray{o, d}, tMin, tMax));
        };
        // A lattice of directions through a box about the solid.
        for (int i = 0; i < 40; ++i)
            for (int j = 0; j < 40; ++j) {
                const Vec3 p(1.5 * r * (i / 19.5 - 1.0), 1.5 * r * (j / 19.5 - 1.0), l * (0.5 + 0.7 * u(rng)));
                const Vec3 d = p - o;
                compare(glm::normalize(d), 1e-6, kInfinity, true);
                compare(d, 1e-6, 0.5 + 0.5 * u(rng), true);
            }
        for (const Vec3& p : targets) {
            const Vec3 d = p - o;
            const double dist = glm::length(d);
            const Vec3 unit = d / dist;
            for (const double nudge : {0.0, 1e-15, -1e-15, 1e-9, -1e-9}) {
                const Vec3 dn = glm::normalize(unit + nudge * Vec3(u(rng), u(rng), u(rng)));
                compare(dn, 1e-6, kInfinity);
                for (const double end : {dist, dist * (1.0 + 1e-15), dist * (1.0 - 1e-15), dist * (1.0 + 1e-9)}) {
                    compare(dn, 1e-6, end);
                    compare(dn, end, kInfinity);
                }
            }
        }
    }
    // Away from the surface most rays are decided here: the exact
    // test is the exception.
    CHECK(decided > total * 3 / 4);
}

}  // namespace

TEST_CASE("FrustumFromOrigin decides as the exact ray test: cones", "[shapes][frustum]") {
    for (const Frustum& f : {Frustum(0.9, 0.0, 1.8, true), Frustum(1.0, 0.4, 2.0, true), Frustum(0.2, 1.5, 0.7, true)}) {
        checkAgainstExact(f, [&](const Ray& ray, double lo, double hi) { return f.intersectAny(ray, lo, hi); });
    }
}

TEST_CASE("FrustumFromOrigin decides as the exact ray test: cylinders", "[shapes][frustum]") {
    for (const double radius : {0.35, 2.0}) {
        const Cylinder c(radius, 1.7, false);
        checkAgainstExact(c.frustum(), [&](const Ray& ray, double lo, double hi) { return c.intersectAny(ray, lo, hi); });
    }
}

TEST_CASE("FrustumFromOrigin leaves open and empty frustums to the exact test", "[shapes][frustum]") {
    CHECK_FALSE(FrustumFromOrigin(Frustum(1.0, 0.5, 1.0, false), Vec3(3.0, 0.0, 0.0)).usable());
    CHECK_FALSE(FrustumFromOrigin(Frustum(0.0, 0.0, 1.0, true), Vec3(3.0, 0.0, 0.0)).usable());
}

TEST_CASE("Primitive::withAnyTestFrom answers as intersectAny", "[shapes][frustum]") {
    const Transform placed = Transform::rotateDegrees({25.0, 40.0, -10.0}) * Transform::translate({0.3, -0.2, 1.1});
    const Transform stretched = Transform::scale({1.0, 2.5, 0.7}) * placed;
    const std::vector<Primitive> prims = {
        Primitive::make(ConeShape{{0, 0, -1.6}, 0.9, {0, 1.8, -1.6}, 0.0, false}, {}),
        Primitive::make(CylinderShape{{2.2, 1.0, -1.9}, {3.8, 1.4, -1.3}, 0.35, false}, {}),
        Primitive::make(ConeShape{{0, 0, 0}, 0.5, {0, 1, 0}, 1.0, false}, placed),
        Primitive::make(CylinderShape{{0, 0, 0}, {1, 1, 0}, 0.5, false}, stretched),
        Primitive::make(CylinderShape{{0, 0, 0}, {0, 1, 0}, 0.5, true}, placed),
        Primitive::make(SphereShape{{0.5, 0.5, 0.2}, 0.7}, stretched),
        Primitive::make(BoxShape{{-0.5, 0, -0.5}, {0.5, 1, 0.5}}, placed),
    };
    test::checkAnyTestFromMatchesIntersectAny(prims, 99);
}
