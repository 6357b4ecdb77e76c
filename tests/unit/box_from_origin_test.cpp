#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "asos/shapes/box.hpp"
#include "asos/shapes/box_from_origin.hpp"
#include "asos/shapes/disc.hpp"
#include "asos/shapes/polygon.hpp"
#include "asos/shapes/primitive.hpp"
#include "any_test_from.hpp"

using namespace asos;

TEST_CASE("BoxFromOrigin answers as Box::intersectAny", "[shapes][box]") {
    const Box box(Vec3(-0.7, 0.0, -0.7), Vec3(0.7, 1.2, 0.7));
    std::mt19937 rng(4321);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    // Corners, edge midpoints and face points: the targets of rays that
    // graze an edge or end on the surface.
    std::vector<Vec3> targets;
    for (int i = 0; i < 27; ++i) {
        const double f[3] = {double(i % 3) * 0.5, double(i / 3 % 3) * 0.5, double(i / 9) * 0.5};
        targets.push_back(box.lo() + (box.hi() - box.lo()) * Vec3(f[0], f[1], f[2]));
    }
    long hits = 0, total = 0;
    // Outside on every side, far, inside, on a face, on an edge's line, in
    // a slab's plane.
    for (const Vec3 o : {Vec3(0.3, 4.0, -2.0), Vec3(-3.0, 0.5, 0.1), Vec3(40.0, -25.0, 17.0), Vec3(0.1, 0.6, -0.2),
                         Vec3(0.7, 0.6, 0.0), Vec3(0.7, 1.2, 3.0), Vec3(-0.7, 2.0, 0.3), Vec3(0.2, 0.0, -0.9)}) {
        const BoxFromOrigin fast(box.lo(), box.hi(), o);
        const auto compare = [&](const Vec3& d, double tMin, double tMax) {
            const bool exact = box.intersectAny(Ray{o, d}, tMin, tMax);
            INFO("origin " << o.x << " " << o.y << " " << o.z << " dir " << d.x << " " << d.y << " " << d.z << " t "
                           << tMin << " " << tMax);
            CHECK(fast.intersectAny(d, tMin, tMax) == exact);
            hits += exact;
            ++total;
        };
        for (int i = 0; i < 30; ++i)
            for (int j = 0; j < 30; ++j) {
                const Vec3 p(1.2 * (i / 14.5 - 1.0), 0.6 + 1.0 * (j / 14.5 - 1.0), 0.9 * u(rng));
                compare(glm::normalize(p - o), 1e-6, kInfinity);
                compare(p - o, 1e-6, 0.5 + 0.5 * u(rng));
            }
        for (const Vec3& p : targets) {
            const Vec3 d = p - o;
            const double dist = glm::length(d);
            if (!(dist > 0.0)) continue;
            for (const double nudge : {0.0, 1e-15, -1e-15, 1e-9}) {
                const Vec3 dn = glm::normalize(d / dist + nudge * Vec3(u(rng), u(rng), u(rng)));
                for (const double end : {dist, dist * (1.0 + 1e-15), dist * (1.0 - 1e-15), kInfinity}) {
                    compare(dn, 1e-6, end);
                    compare(dn, end, kInfinity);
                }
            }
        }
        // Along the axes and in the coordinate planes (zero components).
        for (const Vec3 d : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1),
                             Vec3(0.6, 0.8, 0), Vec3(0, -0.6, 0.8), Vec3(-0.8, 0, 0.6)})
            compare(d, 0.0, kInfinity);
    }
    // Both answers occur.
    CHECK(hits > total / 10);
    CHECK(hits < total * 9 / 10);
}

TEST_CASE("Disc and Polygon intersectAny answer as intersect", "[shapes][disc][polygon]") {
    const Disc disc(1.0, 0.35);
    std::vector<Vec2> hexagon;
    for (int i = 0; i < 6; ++i) hexagon.push_back({std::cos(i * kPi / 3.0), std::sin(i * kPi / 3.0)});
    const Polygon polygon(hexagon, {6});
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const Vec3 o : {Vec3(0.2, 0.1, 2.0), Vec3(-1.5, 0.4, -0.7), Vec3(0.3, 0.2, 0.0), Vec3(30.0, -10.0, 0.5)}) {
        const auto compare = [&](const Vec3& d, double tMin, double tMax) {
            const Ray ray{o, d};
            CHECK(disc.intersectAny(ray, tMin, tMax) == disc.intersect(ray, tMin, tMax).has_value());
            CHECK(polygon.intersectAny(ray, tMin, tMax) == polygon.intersect(ray, tMin, tMax).has_value());
        };
        for (int i = 0; i < 2000; ++i) {
            // Toward the rims and corners (radius 1, 0.35 and between) and
            // beyond, with ranges ending at the plane.
            const double phi = kPi * u(rng), r = i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.35 : 1.3 * std::abs(u(rng));
            const Vec3 p(r * std::cos(phi), r * std::sin(phi), 0.0);
            const Vec3 d = p - o;
            const double dist = glm::length(d);
            compare(d / dist, 1e-6, kInfinity);
            compare(d / dist, 1e-6, dist);
            compare(d / dist, dist, kInfinity);
            compare(Vec3(u(rng), u(rng), 0.0), 1e-6, kInfinity);  // parallel to the plane
        }
    }
}

TEST_CASE("Primitive::withAnyTestFrom answers as intersectAny: box, disc, polygon", "[shapes][box]") {
    const Transform placed = Transform::rotateDegrees({25.0, 40.0, -10.0}) * Transform::translate({0.3, -0.2, 1.1});
    const Transform stretched = Transform::scale({1.0, 2.5, 0.7}) * placed;
    const PolygonShape hexagon{{{1, 0, 0}, {0.5, 0.866, 0}, {-0.5, 0.866, 0}, {-1, 0, 0}, {-0.5, -0.866, 0},
                                {0.5, -0.866, 0}, {1, 0, 0}}};
    const std::vector<Primitive> prims = {
        Primitive::make(BoxShape{{-0.7, 0, -0.7}, {0.7, 1.2, 0.7}}, {}),
        Primitive::make(BoxShape{{-0.5, 0, -0.5}, {0.5, 1, 0.5}}, stretched),
        Primitive::make(DiscShape{{3, 1.5, 1.6}, {0.3, 1, -0.4}, 1.0, 0.35}, {}),
        Primitive::make(DiscShape{{0, 0, 0}, {0, 1, 0}, 1.0, 0.0}, stretched),
        Primitive::make(hexagon, placed),
        Primitive::make(hexagon, stretched),
    };
    test::checkAnyTestFromMatchesIntersectAny(prims, 98);
}
