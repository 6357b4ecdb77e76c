#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "asos/accel/cone_box.hpp"
#include "asos/geometry/beam_eye.hpp"
#include "asos/geometry/concentric_disc.hpp"
#include "asos/geometry/frame.hpp"
#include "asos/geometry/tangent_cone.hpp"
#include "asos/testing/direction_cone.hpp"
#include "asos/testing/quad_pyray.hpp"
#include "asos/testing/rect_shadow_pyray.hpp"
#include "asos/testing/segment_shadow_pyray.hpp"
#include "asos/testing/solid_angle.hpp"
#include "asos/testing/sphere_shadow_cone.hpp"
#include "random_direction.hpp"

using namespace asos;

namespace {

using asos::test::randomUnit;

// A ray of a beam lies in its cone: its direction within the half-angle of
// the axis (for a cone whose apex is the ray's origin).
bool directionInCone(const Cone& c, const Vec3& dir) {
    return angleBetween(c.axis, dir) <= c.halfAngle;
}

// A pinhole camera as the renderer will make one: unnormalised direction
// affine in (u, v).
struct Pinhole {
    Vec3 eye{1, 2, 3};
    Vec3 forward = glm::normalize(Vec3(0.2, -0.1, 1.0));
    Vec3 right = glm::normalize(glm::cross(Vec3(0, 1, 0), forward)) * 0.8;
    Vec3 up = glm::cross(forward, glm::normalize(right)) * 0.6;
    Ray operator()(double u, double v) const {
        return {eye, glm::normalize(forward + (2 * u - 1) * right + (2 * v - 1) * up)};
    }
};

struct Orthographic {
    Vec3 centre{1, 2, 3};
    Vec3 dir = glm::normalize(Vec3(0.3, -0.2, 1.0));
    Vec3 right = glm::normalize(glm::cross(Vec3(0, 1, 0), dir)) * 4.0;
    Vec3 up = glm::cross(dir, glm::normalize(right)) * 3.0;
    Ray operator()(double u, double v) const { return {centre + (2 * u - 1) * right + (2 * v - 1) * up, dir}; }
};

// A sphere and a point outside it, 10^lo to 10^(lo + span) radii beyond its
// surface (from just outside to far away).
struct SphereAndPoint {
    Vec3 centre;
    double radius, distance;
    Vec3 point;
};
SphereAndPoint randomSphereAndPoint(std::mt19937_64& rng, double lo, double span) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const Vec3 centre(u01(rng), 6, u01(rng));
    const double radius = 0.05 + 2 * u01(rng);
    const double distance = radius * (1.0 + std::pow(10.0, lo + span * u01(rng)));
    return {centre, radius, distance, centre + randomUnit(rng) * distance};
}

}  // namespace

TEST_CASE("Smallest enclosing cone holds its directions and cannot shrink", "[beam]") {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 2000; ++trial) {
        // 2..6 directions within a cap of random size about a random axis.
        const Vec3 centre = randomUnit(rng);
        const double spread = trial % 3 == 0 ? 1e-4 : 0.9 * u01(rng);  // within a hemisphere
        std::vector<Vec3> dirs;
        const int n = 2 + static_cast<int>(rng() % 5);
        for (int i = 0; i < n; ++i) dirs.push_back(glm::normalize(centre + spread * randomUnit(rng)));
        const DirectionCone cone = smallestEnclosingCone(dirs);
        REQUIRE(cone.halfAngle < 0.5 * kPi);
        double widest = 0.0;
        for (const Vec3& d : dirs) {
            CHECK(angleBetween(cone.axis, d) <= cone.halfAngle);
            widest = std::max(widest, angleBetween(cone.axis, d));
        }
        // The rim touches a direction, and no nearby axis does better.
        CHECK(cone.halfAngle - widest == Approx(kConeAnglePad).margin(1e-15));
        for (int k = 0; k < 50; ++k) {
            const Vec3 other = glm::normalize(cone.axis + 0.3 * widest * u01(rng) * randomUnit(rng));
            double otherWidest = 0.0;
            for (const Vec3& d : dirs) otherWidest = std::max(otherWidest, angleBetween(other, d));
            CHECK(otherWidest >= widest - 1e-12);
        }
    }
    // Not in an open hemisphere: the cone of everything.
    const std::vector<Vec3> opposite = {Vec3(1, 0, 0), Vec3(-1, 0, 0)};
    CHECK(smallestEnclosingCone(opposite).halfAngle == kPi);
}

TEST_CASE("Solid angles of triangles and rectangles are exact", "[beam]") {
    // An octant: pi/2.
    CHECK(solidAngle(Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)) == Approx(0.5 * kPi).epsilon(1e-14));
    // A rectangle a x b centred at distance d: 4 asin(ab / sqrt((a^2 + 4d^2)(b^2 + 4d^2))).
    const double a = 2.0, b = 3.0, d = 1.5;
    const std::vector<Vec3> corners = {Vec3(-a / 2, -b / 2, d), Vec3(a / 2, -b / 2, d), Vec3(a / 2, b / 2, d),
                                       Vec3(-a / 2, b / 2, d)};
    CHECK(solidAngleOfPolygon(Vec3(0.0), corners) ==
          Approx(4.0 * std::asin(a * b / std::sqrt((a * a + 4 * d * d) * (b * b + 4 * d * d)))).epsilon(1e-13));
}

TEST_CASE("Eye pyray: smallest cone about the central ray, exact quarters", "[beam]") {
    const Pinhole camera;
    std::mt19937_64 rng(22);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double pixel = 1.0 / 64.0;
    for (int trial = 0; trial < 300; ++trial) {
        const double u = std::floor(u01(rng) * 64) * pixel, v = std::floor(u01(rng) * 64) * pixel;
        const EyePyray pixelPyray = EyePyray::make(camera, ImageSquare{u, v, u + pixel, v + pixel});
        REQUIRE(pixelPyray.projection() == Projection::Perspective);
        // Descend to a random level up to 4 (MAX), checking every level.
        EyePyray p = pixelPyray;
        for (int level = 0; level <= 4; ++level) {
            const Cone& c = p.cone();
            CHECK(c.apex == camera.eye);
            CHECK(angleBetween(c.axis, p.centralRay().dir) <= 1e-15);
            CHECK(p.weight() == std::ldexp(1.0, -2 * level));
            // The rim touches a corner ray; every corner is inside.
            double widest = 0.0;
            for (const Ray& r : p.cornerRays()) widest = std::max(widest, angleBetween(c.axis, r.dir));
            CHECK(c.halfAngle - widest == Approx(kConeAnglePad).margin(1e-15));
            // Rays of the pyray (jittered) are inside its cone and its parent's.
            for (int k = 0; k < 20; ++k) {
                const Ray r = p.sampleRay(camera, u01(rng), u01(rng));
                CHECK(directionInCone(c, r.dir));
                CHECK(directionInCone(pixelPyray.cone(), r.dir));
            }
            const auto quarters = p.split(camera);
            // The quarters tile the square: shared midpoints, weights summing exactly.
            double total = 0.0;
            for (int q = 0; q < 4; ++q) {
                total += quarters[q].weight();
                CHECK(quarters[q].level() == level + 1);
            }
            CHECK(total == p.weight());
            CHECK(quarters[0].square().u1 == quarters[1].square().u0);
            CHECK(quarters[0].square().v1 == quarters[2].square().v0);
            CHECK(quarters[3].square().u1 == p.square().u1);
            CHECK(quarters[3].square().v1 == p.square().v1);
            CHECK(quarters[0].square().u0 == p.square().u0);
            // The quarter's corner at the parent's centre is the parent's central ray.
            CHECK(quarters[0].cornerRays()[2].dir == p.centralRay().dir);
            p = quarters[rng() % 4];
        }
    }
}

TEST_CASE("Eye pyray of an orthographic camera: a cone behind that holds the prism", "[beam]") {
    const Orthographic camera;
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (double tMax : {50.0, kInfinity}) {
        for (int trial = 0; trial < 100; ++trial) {
            const double size = std::ldexp(1.0, -static_cast<int>(rng() % 10));
            const double u = u01(rng) * (1 - size), v = u01(rng) * (1 - size);
            const EyePyray p = EyePyray::make(camera, ImageSquare{u, v, u + size, v + size}, 0, 0.5, tMax);
            REQUIRE(p.projection() == Projection::Orthographic);
            const ConeBoxTest cone(p.cone());
            for (int k = 0; k < 200; ++k) {
                const Ray r = p.sampleRay(camera, k % 10 == 0 ? 0.0 : u01(rng), k % 10 == 1 ? 1.0 : u01(rng));
                const double far = std::isfinite(tMax) ? tMax : 1e4;
                const double t = k % 7 == 0 ? 0.5 : (k % 7 == 1 ? far : 0.5 + u01(rng) * (far - 0.5));
                INFO("size " << size << " t " << t);
                CHECK(cone.contains(r.at(t)));
            }
            // Over a finite depth the cone stays within 1/16 of the prism's width.
            if (std::isfinite(tMax)) {
                const Cone& c = p.cone();
                const double rho = glm::length(p.cornerRays()[0].origin - p.centralRay().origin);
                CHECK(c.tMax * std::tan(c.halfAngle) <= rho * (1.0 + 1.0 / 16.0) * 1.001);
            } else {
                CHECK(std::tan(p.cone().halfAngle) == Approx(1.0 / 4096).epsilon(1e-9));
            }
        }
    }
    // Rays that share neither origin nor direction are rejected.
    const auto bad = [](double u, double v) { return Ray{Vec3(u, v, 0), glm::normalize(Vec3(u, v, 1))}; };
    CHECK_THROWS_AS(EyePyray::make(bad, ImageSquare{}), std::invalid_argument);
}

TEST_CASE("Rectangle shadow pyray: quarters tile the light, rays inside the cone", "[beam]") {
    std::mt19937_64 rng(24);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const RectangleLight light{Vec3(u01(rng), 5 + u01(rng), u01(rng)), randomUnit(rng) * (0.1 + 3 * u01(rng)),
                                   randomUnit(rng) * (0.1 + 3 * u01(rng))};
        // Points near and far, head-on and grazing.
        const Vec3 point = light.corner + randomUnit(rng) * std::pow(10.0, -1.0 + 3.0 * u01(rng));
        const auto made = RectShadowPyray::make(point, light, 1e-4);
        if (!made) continue;
        const Vec3 n = glm::normalize(glm::cross(light.edgeA, light.edgeB));
        RectShadowPyray p = *made;
        const double lightArea = glm::length(glm::cross(light.edgeA, light.edgeB));
        for (int level = 0; level <= 4; ++level) {
            const Cone& c = p.cone();
            CHECK(p.weight() == std::ldexp(1.0, -2 * level));
            CHECK(p.area() == Approx(lightArea * p.weight()).epsilon(1e-12));
            for (int k = 0; k < 30; ++k) {
                const BeamRay r = k == 0 ? p.central() : p.sample(k < 5 ? (k & 1) : u01(rng), k < 5 ? (k >> 1 & 1) : u01(rng));
                CHECK(directionInCone(c, r.ray.dir));
                // The ray ends on the light's plane, within the cone's t-range.
                CHECK(std::abs(glm::dot(r.ray.at(r.distance) - light.corner, n)) <= 1e-9 * (1 + r.distance));
                CHECK(r.distance <= c.tMax);
                CHECK(r.distance >= p.nearestLightDistance() * (1 - 1e-12));
            }
            CHECK(p.cosTheta() == Approx(std::abs(glm::dot(n, p.central().ray.dir))));
            const auto quarters = p.split();
            double weights = 0.0, solid = 0.0;
            for (const auto& q : quarters) {
                weights += q.weight();
                solid += q.solidAngle();
            }
            CHECK(weights == p.weight());
            CHECK(solid == Approx(p.solidAngle()).epsilon(1e-9));
            CHECK(quarters[0].region().s1 == quarters[1].region().s0);
            CHECK(quarters[0].region().t1 == quarters[2].region().t0);
            p = quarters[rng() % 4];
        }
    }
    // In the light's plane: no beam. Zero area: an error.
    const RectangleLight light{Vec3(0.0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    CHECK_FALSE(RectShadowPyray::make(Vec3(3, 3, 0), light).has_value());
    CHECK_THROWS_AS(RectShadowPyray::make(Vec3(0, 0, 1), RectangleLight{Vec3(0.0), Vec3(1, 0, 0), Vec3(2, 0, 0)}),
                    std::invalid_argument);
    // Head-on unit square at distance 1 (corner at the foot): cos theta of the
    // central ray and the nearest distance are known.
    const auto p = RectShadowPyray::make(Vec3(0, 0, 1), light);
    REQUIRE(p);
    CHECK(p->nearestLightDistance() == Approx(1.0));
    CHECK(p->cosTheta() == Approx(1.0 / std::sqrt(1.5)));
}

TEST_CASE("Segment shadow pyray: halves tile the light, rays inside the cone", "[beam]") {
    std::mt19937_64 rng(25);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        const Vec3 a(u01(rng), 4, u01(rng));
        const Vec3 b = a + randomUnit(rng) * (0.1 + 5 * u01(rng));
        const Vec3 point = a + randomUnit(rng) * std::pow(10.0, -1.0 + 2.5 * u01(rng));
        const auto made = SegmentShadowPyray::make(point, a, b);
        if (!made) continue;
        SegmentShadowPyray p = *made;
        for (int level = 0; level <= 6; ++level) {
            CHECK(p.weight() == std::ldexp(1.0, -level));
            for (int k = 0; k < 20; ++k) {
                const BeamRay r = k == 0 ? p.central() : p.sample(k == 1 ? 0.0 : (k == 2 ? 1.0 : u01(rng)));
                CHECK(directionInCone(p.cone(), r.ray.dir));
                CHECK(r.distance <= p.cone().tMax);
                CHECK(r.distance >= p.nearestLightDistance() * (1 - 1e-12));
                // It ends on the segment.
                const Vec3 end = r.ray.at(r.distance);
                CHECK(glm::length(glm::cross(end - a, b - a)) <= 1e-9 * glm::length(b - a) * (1 + glm::length(end - a)));
            }
            const auto halves = p.split();
            CHECK(halves[0].weight() + halves[1].weight() == p.weight());
            CHECK(halves[0].s1() == halves[1].s0());
            CHECK(halves[0].length() + halves[1].length() == Approx(p.length()).epsilon(1e-14));
            p = halves[rng() % 2];
        }
    }
    CHECK_FALSE(SegmentShadowPyray::make(Vec3(0.5, 0, 0), Vec3(0.0), Vec3(1, 0, 0)).has_value());
    CHECK(SegmentShadowPyray::make(Vec3(2, 0, 0), Vec3(0.0), Vec3(1, 0, 0)).has_value());  // end-on
    CHECK_THROWS_AS(SegmentShadowPyray::make(Vec3(0, 1, 0), Vec3(0.0), Vec3(0.0)), std::invalid_argument);
}

TEST_CASE("Concentric map: polar bounds of cells and the pieces' solid angles against a numerical sum", "[beam]") {
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    // Every cell of levels 1 to 4: its image's radii and angles, sampled
    // densely, lie in its polar bounds and reach them, under both maps.
    for (const DiscMap map : {DiscMap::Concentric, DiscMap::Povray})
    for (int level = 1; level <= 4; ++level) {
        const int n = 1 << level;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const DiscCell c{double(i) / n, double(i + 1) / n, double(j) / n, double(j + 1) / n};
                const PolarBounds b = polarBounds(c, map);
                CHECK(b.phi1 - b.phi0 <= 0.5 * kPi + 1e-15);
                CHECK(innerRadius(c) == b.r0);
                double r0 = 2.0, r1 = 0.0, phi0 = 10.0, phi1 = -10.0;
                for (int v = 0; v <= 16; ++v)
                    for (int u = 0; u <= 16; ++u) {
                        const Vec2 d = discPoint(map, c.s0 + u / 16.0 * (c.s1 - c.s0), c.t0 + v / 16.0 * (c.t1 - c.t0));
                        const double rho = glm::length(d);
                        r0 = std::min(r0, rho);
                        r1 = std::max(r1, rho);
                        if (rho < 1e-12) continue;
                        double phi = std::atan2(d.y, d.x);
                        if (phi < b.phi0 - 1e-9) phi += 2.0 * kPi;
                        phi0 = std::min(phi0, phi);
                        phi1 = std::max(phi1, phi);
                    }
                INFO((map == DiscMap::Povray ? "POV-Ray's map" : "concentric map") << " level " << level << " cell "
                                                                                 << i << "," << j);
                CHECK(r0 == Approx(b.r0).margin(1e-12));
                CHECK(r1 == Approx(b.r1).margin(1e-12));
                CHECK(phi0 == Approx(b.phi0).margin(1e-9));
                CHECK(phi1 == Approx(b.phi1).margin(1e-9));
            }
    }
    // The whole square: the whole disc.
    const PolarBounds whole = polarBounds(DiscCell{});
    CHECK(whole.r0 == 0.0);
    CHECK(whole.r1 == 1.0);
    CHECK(whole.phi1 - whole.phi0 == 2.0 * kPi);
    // Solid angles: the closed form against the midpoint rule over the cell
    // (the map has constant Jacobian pi, and the solid angle per unit disc
    // area at radius r is T^2 / (1 + r^2 T^2)^(3/2)), along random paths.
    for (int trial = 0; trial < 12; ++trial) {
        const double radius = 0.2 + u01(rng);
        const double distance = radius * (1.0 + std::pow(10.0, -2.0 + 3.0 * u01(rng)));
        const auto made = SphereShadowCone::make(Vec3(0.0), Vec3(0, 0, distance), radius);
        REQUIRE(made);
        const double T = std::tan(made->tangentHalfAngle());
        SphereShadowCone p = *made;
        for (int level = 0; level <= 3; ++level) {
            const DiscCell& c = p.region();
            constexpr int kSteps = 240;
            double sum = 0.0;
            for (int v = 0; v < kSteps; ++v)
                for (int u = 0; u < kSteps; ++u) {
                    const double s = c.s0 + (u + 0.5) / kSteps * (c.s1 - c.s0);
                    const double t = c.t0 + (v + 0.5) / kSteps * (c.t1 - c.t0);
                    const double r = std::max(std::abs(2 * s - 1), std::abs(2 * t - 1));
                    sum += kPi * T * T / std::pow(1.0 + r * r * T * T, 1.5);
                }
            sum *= (c.s1 - c.s0) * (c.t1 - c.t0) / (double(kSteps) * kSteps);
            INFO("trial " << trial << " level " << level);
            CHECK(p.solidAngle() == Approx(sum).epsilon(1e-4));
            p = p.split()[rng() % 4];
        }
    }
}

TEST_CASE("Tangent cone rays: unit directions, and distances to the sphere from far away to just outside",
          "[beam]") {
    std::mt19937_64 rng(28);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        const auto [centre, radius, distance, point] = randomSphereAndPoint(rng, -6.0, 8.0);
        const TangentCone cone = TangentCone::make(point, centre, radius);
        CHECK(cone.sinAlpha == Approx(radius / distance).epsilon(1e-12));
        CHECK(cone.cos2Alpha == Approx(1.0 - (radius / distance) * (radius / distance)).epsilon(1e-6));
        for (int k = 0; k < 12; ++k) {
            // The centre, the rim, and points between.
            const double rho = k == 0 ? 0.0 : (k < 4 ? 1.0 : u01(rng));
            const double phi = 2.0 * kPi * u01(rng);
            const BeamRay r = cone.ray(point, Vec2(rho * std::cos(phi), rho * std::sin(phi)));
            CHECK(glm::length(r.ray.dir) == Approx(1.0).epsilon(1e-15));
            // The hit is on the sphere, to the rounding of the point's own
            // coordinates (which the distance to the centre carries).
            CHECK(std::abs(glm::length(r.ray.at(r.distance) - centre) - radius) <= 1e-13 * (distance + 6.0));
            // The angle from the centre's direction is atan(rho tan alpha).
            CHECK(angleBetween(r.ray.dir, centre - point) ==
                  Approx(std::atan(rho * cone.tanAlpha)).margin(1e-12));
            // At the rim, the distance to the tangent point: a square root of
            // the direction's rounding (1e-16) moves it by about 1e-8.
            if (rho == 1.0)
                CHECK(std::abs(r.distance - std::sqrt((distance - radius) * (distance + radius))) <= 1e-7 * distance);
            if (rho == 0.0) CHECK(std::abs(r.distance - (distance - radius)) <= 1e-13 * distance);
        }
    }
}

TEST_CASE("Sphere shadow cone: the tangent cone, equal-area pieces, rays inside their cones", "[beam]") {
    std::mt19937_64 rng(26);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 150; ++trial) {
        const auto [centre, radius, distance, point] = randomSphereAndPoint(rng, -3.0, 5.0);
        const auto made = SphereShadowCone::make(point, centre, radius, 1e-4);
        REQUIRE(made);
        CHECK(made->cone().halfAngle == Approx(std::asin(radius / distance)).margin(1e-12));
        CHECK(made->central().ray.dir == made->cone().axis);
        CHECK(made->central().distance == Approx(distance - radius).epsilon(1e-9));
        CHECK(made->solidAngle() == Approx(2 * kPi * (1 - std::sqrt(1 - (radius / distance) * (radius / distance)))).epsilon(1e-9));
        // Walk down four levels along random pieces; at each level check all four pieces.
        SphereShadowCone p = *made;
        for (int level = 0; level < 4; ++level) {
            const auto pieces = p.split();
            double weights = 0.0, solid = 0.0;
            for (const auto& q : pieces) {
                weights += q.weight();
                solid += q.solidAngle();
                CHECK(q.weight() == std::ldexp(1.0, -2 * (level + 1)));
                const PolarBounds& bounds = q.bounds();
                const DiscCell& c = q.region();
                for (int k = 0; k < 60; ++k) {
                    // Corners of the piece first, then along its four edges
                    // (curves on the disc, where a cone of the corners alone
                    // could fall short), then inside.
                    double xi1 = u01(rng), xi2 = u01(rng);
                    if (k < 4) {
                        xi1 = k & 1;
                        xi2 = k >> 1 & 1;
                    } else if (k < 44) {
                        const double along = (k - 4) % 10 / 9.0;
                        const int edge = (k - 4) / 10;
                        xi1 = edge < 2 ? edge : along;
                        xi2 = edge < 2 ? along : edge - 2;
                    }
                    const BeamRay r = k == 4 ? q.central() : q.sample(xi1, xi2);
                    INFO("level " << level + 1 << " cell s [" << c.s0 << "," << c.s1 << "] t [" << c.t0 << ","
                                  << c.t1 << "]");
                    CHECK(directionInCone(q.cone(), r.ray.dir));
                    CHECK(directionInCone(made->cone(), r.ray.dir));
                    // It meets the sphere where the beam says, within the cone's t-range.
                    CHECK(glm::length(r.ray.at(r.distance) - centre) == Approx(radius).epsilon(1e-6));
                    CHECK(r.distance <= q.cone().tMax);
                    CHECK(r.distance >= q.nearestLightDistance() * (1 - 1e-9));
                    // Its disc point lies in the piece's polar rectangle.
                    const Vec2 d = concentricDisc(c.s0 + xi1 * (c.s1 - c.s0), c.t0 + xi2 * (c.t1 - c.t0));
                    const double rho = glm::length(d);
                    CHECK(rho >= bounds.r0 - 1e-12);
                    CHECK(rho <= bounds.r1 + 1e-12);
                    if (rho > 1e-9) {
                        double phi = std::atan2(d.y, d.x);
                        if (phi < bounds.phi0 - 1e-9) phi += 2.0 * kPi;
                        CHECK(phi >= bounds.phi0 - 1e-9);
                        CHECK(phi <= bounds.phi1 + 1e-9);
                    }
                }
            }
            CHECK(weights == p.weight());
            CHECK(solid == Approx(p.solidAngle()).epsilon(1e-9));
            // The pieces' cells are the parent's quarters.
            const DiscCell& e = p.region();
            for (const auto& q : pieces) {
                const DiscCell& d = q.region();
                CHECK((d.s1 - d.s0) == 0.5 * (e.s1 - e.s0));
                CHECK((d.t1 - d.t0) == 0.5 * (e.t1 - e.t0));
                CHECK(d.s0 >= e.s0);
                CHECK(d.s1 <= e.s1);
                CHECK(d.t0 >= e.t0);
                CHECK(d.t1 <= e.t1);
            }
            p = pieces[rng() % 4];
        }
    }
    CHECK_FALSE(SphereShadowCone::make(Vec3(0.5, 0, 0), Vec3(0.0), 1.0).has_value());
    CHECK_THROWS_AS(SphereShadowCone::make(Vec3(5, 0, 0), Vec3(0.0), 0.0), std::invalid_argument);
}

TEST_CASE("Point-light footprint pyray: bilinear quarters tile the quadrilateral", "[beam]") {
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        // A convex planar quadrilateral (a perspective footprint on a plane)
        // and a light above it.
        const Vec3 normal = randomUnit(rng);
        const Frame f = Frame::around(normal);
        const Vec3 origin(u01(rng), u01(rng), u01(rng));
        const double size = std::pow(10.0, -3.0 + 3.0 * u01(rng));
        std::array<Vec3, 4> corners;
        const double jitter = 0.3;
        const double xs[4] = {0, 1, 1, 0}, ys[4] = {0, 0, 1, 1};
        for (int i = 0; i < 4; ++i) {
            corners[i] = origin + size * (xs[i] + jitter * (u01(rng) - 0.5)) * f.u +
                         size * (ys[i] + jitter * (u01(rng) - 0.5)) * f.v;
        }
        const Vec3 light = origin + normal * (0.5 + 5 * u01(rng)) + randomUnit(rng) * 2.0 * u01(rng);
        const int startLevel = static_cast<int>(rng() % 3);
        QuadPyray p = QuadPyray::make(light, corners, startLevel, 0.0);
        const QuadPyray top = p;
        for (int level = startLevel; level < startLevel + 4; ++level) {
            CHECK(p.weight() == std::ldexp(1.0, -2 * level));
            const auto quarters = p.split();
            double weights = 0.0;
            for (int q = 0; q < 4; ++q) {
                weights += quarters[q].weight();
                CHECK(quarters[q].corners()[q] == p.corners()[q]);
                // A quarter's rays are the parent's rays at the mapped parameters.
                const double xi1 = u01(rng), xi2 = u01(rng);
                const BeamRay child = quarters[q].sample(xi1, xi2);
                const BeamRay parent = p.sample(0.5 * (xi1 + (q == 1 || q == 2)), 0.5 * (xi2 + (q >= 2)));
                CHECK(glm::length(child.ray.at(child.distance) - parent.ray.at(parent.distance)) <= 1e-12 * (1 + parent.distance));
                for (int k = 0; k < 20; ++k) {
                    const BeamRay r = k < 4 ? quarters[q].sample(k & 1, k >> 1 & 1) : quarters[q].sample(u01(rng), u01(rng));
                    CHECK(directionInCone(quarters[q].cone(), r.ray.dir));
                    CHECK(directionInCone(top.cone(), r.ray.dir));
                    CHECK(r.distance <= quarters[q].cone().tMax);
                    // It ends on the footprint's plane.
                    CHECK(std::abs(glm::dot(r.ray.at(r.distance) - origin, normal)) <= 1e-9 * (1 + r.distance));
                }
            }
            CHECK(weights == p.weight());
            p = quarters[rng() % 4];
        }
    }
    // The apex in the quadrilateral's plane: the cone of all directions.
    const QuadPyray flat = QuadPyray::make(Vec3(0.5, 0.5, 0), {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0)});
    CHECK(flat.cone().halfAngle == kPi);
}
