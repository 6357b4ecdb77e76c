#pragma once
// The property test shared by the primitives (tests/unit/shape_*_test.cpp):
// random shapes under random transforms (identity, translate, rotate, uniform
// and non-uniform scale, general matrix) against random cones (tiny,
// pixel-sized and wide; head-on and grazing; apexes far away, near the
// surface and inside; open, cut and short t-ranges). Every answer is checked
// against a dense set of rays of the cone traced exactly; any contradiction
// of the conservative rule fails the test and prints the case. Each case has
// its own seed: ASOS_SHAPE_REPLAY=<name>:<seed> runs that case alone and
// prints it.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <sstream>
#include <string>

#include "asos/geometry/frame.hpp"
#include "asos/geometry/margins.hpp"
#include "asos/shapes/primitive.hpp"
#include "asos/testing/cone_probe.hpp"
#include "asos/testing/rng.hpp"

namespace shapetest {

using namespace asos;

// A cone in a shape's local frame over [0, inf), for tests that ask a local
// shape directly (the degenerate shapes Primitive::make refuses).
inline LocalCone localCone(const Vec3& apex, const Vec3& axis, double halfAngle) {
    LocalCone cone;
    cone.apex = apex;
    cone.axis = glm::normalize(axis);
    cone.cosHalf = std::cos(halfAngle);
    cone.sinHalf = std::sin(halfAngle);
    cone.setRange(0.0, kInfinity, kPositionTolerance * (std::abs(apex.x) + std::abs(apex.y) + std::abs(apex.z)));
    return cone;
}

inline std::uint64_t splitmix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

// Runs f(i, seed, rng) for `count` cases of a property test, each with its
// own seed (splitmix(base + i)) and random numbers, so that a failing case
// can be named and replayed alone.
template <class F>
void forEachCase(std::uint64_t base, int count, F&& f) {
    for (int i = 0; i < count; ++i) {
        const std::uint64_t seed = splitmix(base + static_cast<std::uint64_t>(i));
        Rng rng(seed);
        f(i, seed, rng);
    }
}

inline std::string fmt(const Vec3& v) {
    std::ostringstream s;
    s.precision(17);
    s << "<" << v.x << ", " << v.y << ", " << v.z << ">";
    return s.str();
}

inline std::string fmt(double v) {
    std::ostringstream s;
    s.precision(17);
    s << v;
    return s.str();
}

struct ShapeCase {
    Shape shape;
    std::function<Vec3(Rng&)> surfacePoint;  // object space, on the surface
    double size = 1.0;                       // object-space scale
    std::string text;                        // the parameters, for a failure message
};

struct TransformCase {
    Transform worldFromObject;
    std::string text;
};

// kinds: 0 identity, 1 translate, 2 rotate, 3 uniform scale, 4 non-uniform
// scale, 5 matrix; `firstKind` limits the draw to kinds firstKind..5.
inline TransformCase randomTransform(Rng& rng, double spread, int firstKind = 0) {
    const int kind = firstKind + rng.index(6 - firstKind);
    const Vec3 offset = spread * Vec3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    auto rotation = [&] {
        if (rng.chance(0.3))
            return Transform::rotateDegrees(
                90.0 * Vec3(rng.index(4), rng.index(4), rng.index(4)));
        return Transform::rotateDegrees(
            Vec3(rng.uniform(-180, 180), rng.uniform(-180, 180), rng.uniform(-180, 180)));
    };
    Transform t;
    const char* name = "identity";
    switch (kind) {
        case 0: break;
        case 1: t = Transform::translate(offset); name = "translate"; break;
        case 2: t = Transform::translate(offset) * rotation(); name = "rotate"; break;
        case 3:
            t = Transform::translate(offset) * rotation() *
                Transform::scale(Vec3(rng.logUniform(-1.0, 1.0)));
            name = "uniform scale";
            break;
        case 4:
            t = Transform::translate(offset) * rotation() *
                Transform::scale(Vec3(rng.logUniform(-0.7, 0.7), rng.logUniform(-0.7, 0.7),
                                      rng.logUniform(-0.7, 0.7)));
            name = "non-uniform scale";
            break;
        default: {
            double v[12];
            for (int i = 0; i < 9; ++i) v[i] = (i % 4 == 0 ? 1.0 : 0.0) + rng.uniform(-0.6, 0.6);
            for (int i = 9; i < 12; ++i) v[i] = offset[i - 9];
            t = Transform::fromPovMatrix(v);
            name = "matrix";
        }
    }
    std::ostringstream s;
    s.precision(17);
    s << name << " matrix <";
    double v[12];
    t.toPovMatrix(v);
    for (int i = 0; i < 12; ++i) s << v[i] << (i < 11 ? ", " : ">");
    return {t, s.str()};
}

// A flat shape in the object's plane z = 0 under non-uniform scales and
// matrices (some mirrored), which Primitive::make lays out again in a rigid
// frame: rays aimed at points of the plane (target(rng) gives the object
// point and whether the shape holds it, by a margin) must hit exactly the
// held ones, at the point's distance, with the plane's world normal (the
// inverse transpose of +z) and the object point itself.
template <class Make, class Target>
void checkFlatUnderScale(std::uint64_t seed, Make&& make, Target&& target) {
    Rng rng(seed);
    int hitsSeen = 0, missesSeen = 0;
    for (int trial = 0; trial < 200; ++trial) {
        TransformCase tc = randomTransform(rng, 5.0, 4);
        if (rng.chance(0.3)) tc.worldFromObject = tc.worldFromObject * Transform::scale({-1.0, 1.0, 1.0});
        const Primitive shape = make(tc.worldFromObject);
        const Mat4& m = tc.worldFromObject.matrix();
        const Vec3 normal = glm::normalize(glm::transpose(glm::inverse(Mat3(m))) * Vec3(0, 0, 1));
        INFO(tc.text);
        for (int k = 0; k < 20; ++k) {
            const auto [point, held] = target(rng);
            const Vec3 world = Vec3(m * Vec4(point, 1.0));
            const Vec3 origin = world + rng.uniform(1.0, 10.0) * rng.unitVector();
            const double distance = glm::length(world - origin);
            const auto hit = shape.intersect(Ray{origin, (world - origin) / distance}, 0.0, kInfinity);
            INFO("object point " << fmt(point));
            REQUIRE(hit.has_value() == held);
            if (!hit) {
                ++missesSeen;
                continue;
            }
            ++hitsSeen;
            CHECK(std::abs(hit->t - distance) <= 1e-9 * (1.0 + distance));
            CHECK(glm::length(hit->normal - normal) <= 1e-9);
            CHECK(glm::length(hit->objectPoint - point) <= 1e-9);
        }
    }
    CHECK(hitsSeen > 1000);
    CHECK(missesSeen > 1000);
}

// A cone aimed at (or near) a target point of the object.
inline Cone randomCone(Rng& rng, const Vec3& target, const Vec3& surfacePoint,
                       const Bounds3& bounds, double size) {
    Cone cone;
    const double pick = rng.uniform();
    if (pick < 0.55) {
        cone.apex = target + rng.unitVector() * size * rng.logUniform(-0.5, 5.0);
    } else if (pick < 0.8) {
        // Near (or on) the surface, on either side.
        cone.apex = surfacePoint + rng.unitVector() * size * rng.logUniform(-14.0, -1.0);
        if (rng.chance(0.2)) cone.apex = surfacePoint;
    } else {
        cone.apex = bounds.empty() ? target : rng.inBox(bounds.lo, bounds.hi);
    }
    const double kind = rng.uniform();
    if (kind < 0.02) cone.halfAngle = 0.0;
    else if (kind < 0.12) cone.halfAngle = rng.logUniform(-9.0, -6.0);
    else if (kind < 0.62) cone.halfAngle = rng.logUniform(-5.0, -2.5);
    else if (kind < 0.87) cone.halfAngle = rng.logUniform(-2.5, -0.5);
    else if (kind < 0.95) cone.halfAngle = rng.uniform(0.3, 1.55);
    else cone.halfAngle = rng.uniform(1.55, 3.1);
    Vec3 toTarget = target - cone.apex;
    const double dist = glm::length(toTarget);
    if (dist > 0.0 && rng.chance(0.9)) {
        toTarget /= dist;
        // Tilt the axis by up to a few half-angles (or a little when tiny).
        const double tilt = rng.uniform(0.0, 3.0) * std::max(cone.halfAngle, 1e-7 * rng.uniform());
        const Vec3 side = glm::normalize(glm::cross(toTarget, rng.unitVector()));
        cone.axis = glm::normalize(std::cos(tilt) * toTarget + std::sin(tilt) * side);
    } else {
        cone.axis = rng.unitVector();
    }
    const double range = rng.uniform();
    const double scale = std::max(dist, size);
    if (range < 0.55) {
        cone.tMin = 0.0;
    } else if (range < 0.7) {
        cone.tMin = size * rng.logUniform(-9.0, -3.0);
    } else if (range < 0.85) {
        cone.tMin = size * rng.logUniform(-9.0, -3.0);
        cone.tMax = scale * rng.uniform(0.5, 1.5);
    } else {
        cone.tMin = dist * rng.uniform(0.8, 1.0);
        cone.tMax = dist * rng.uniform(1.0, 1.2) + size * 1e-3 * rng.uniform();
    }
    return cone;
}

inline std::string describe(const Cone& c) {
    return "cone apex " + fmt(c.apex) + " axis " + fmt(c.axis) + " halfAngle " + fmt(c.halfAngle) +
           " t [" + fmt(c.tMin) + ", " + fmt(c.tMax) + "]";
}

struct PropertyStats {
    int cases = 0;
    int miss = 0, full = 0, marginal = 0;
    int leave = 0;  // cases where Primitive::raysLeave held
    int failures = 0;
};

// Runs `count` random cases of one primitive; returns the statistics.
inline PropertyStats runConeProperty(const char* name, std::uint64_t baseSeed, int count,
                                     const std::function<ShapeCase(Rng&)>& makeShape,
                                     const ProbeDensity& density = {}, int firstTransformKind = 0) {
    std::uint64_t only = 0;
    bool replay = false;
    if (const char* env = std::getenv("ASOS_SHAPE_REPLAY")) {
        const std::string s(env), prefix = std::string(name) + ":";
        if (s.rfind(prefix, 0) == 0) {
            only = std::stoull(s.substr(prefix.size()));
            replay = true;
        } else {
            count = 0;
        }
    }
    PropertyStats stats;
    for (int i = 0; i < (replay ? 1 : count); ++i) {
        const std::uint64_t seed = replay ? only : splitmix(baseSeed + static_cast<std::uint64_t>(i));
        Rng rng(seed);
        const ShapeCase shape = makeShape(rng);
        const TransformCase transform = randomTransform(rng, 5.0 * shape.size, firstTransformKind);
        const Primitive prim = Primitive::make(shape.shape, transform.worldFromObject);
        const Vec3 surface = transform.worldFromObject.point(shape.surfacePoint(rng));
        const Bounds3 bounds = prim.bounded() ? prim.worldBounds() : Bounds3{};
        const Vec3 target = rng.chance(0.8) ? surface
                                            : transform.worldFromObject.point(shape.surfacePoint(rng)) +
                                                  rng.unitVector() * shape.size * rng.uniform(0.0, 0.3);
        const Cone cone = randomCone(rng, target, surface, bounds, shape.size);
        // Every other case asks for the creases too (from the seed: the
        // draws stay those of the cases before).
        const bool creases = (seed & 1) != 0;
        const ConeClass answer = prim.classify(PreparedCone(cone, creases));
        ProbeResult probe = probeCone(prim, cone, answer, density, creases);
        const bool nan = std::isnan(answer.tNear) || std::isnan(answer.tFar);
        // The ray hits themselves: any-hit agrees, the point is on the ray,
        // in the bounds and back at objectPoint, the normal is unit.
        for (int r = 0; r < 4; ++r) {
            const Vec3 dir = r == 0 ? cone.axis : rng.unitVector();
            const Ray ray{cone.apex, glm::normalize(dir)};
            const auto hit = prim.intersect(ray, 0.0, kInfinity);
            std::string wrong;
            if (hit.has_value() != prim.intersectAny(ray, 0.0, kInfinity))
                wrong = "intersect and intersectAny disagree";
            if (hit) {
                const double scale = glm::length(ray.origin) + glm::length(hit->position) + shape.size;
                const Vec3 pad(1e-9 * scale);
                const Vec3 back = transform.worldFromObject.point(hit->objectPoint);
                if (std::abs(glm::length(hit->normal) - 1.0) > 1e-9) wrong = "normal not unit";
                if (glm::length(hit->position - ray.at(hit->t)) > 1e-9 * scale)
                    wrong = "position off the ray";
                if (prim.bounded() &&
                    !Bounds3{bounds.lo - pad, bounds.hi + pad}.contains(hit->position))
                    wrong = "hit outside worldBounds";
                if (glm::length(back - hit->position) > 1e-7 * scale) wrong = "objectPoint does not map back";
            }
            if (!wrong.empty() && stats.failures++ < 5)
                FAIL_CHECK(name << " case " << i << " (replay: ASOS_SHAPE_REPLAY=" << name << ":"
                                << seed << "): " << wrong << " for the ray from " << fmt(ray.origin)
                                << " along " << fmt(ray.dir));
        }
        // Primitive::raysLeave for four directions about the cone's axis (at
        // its half-angle, at most 0.3): where it holds, no ray along a
        // non-negative combination of them may meet the shape beyond the apex.
        {
            const double spread = std::min(cone.halfAngle, 0.3);
            const Mat3 basis = frameAroundAxis(cone.axis);
            const Vec3 along = std::cos(spread) * cone.axis;
            const Vec3 dirs[4] = {along + std::sin(spread) * basis[0], along - std::sin(spread) * basis[0],
                                  along + std::sin(spread) * basis[1], along - std::sin(spread) * basis[1]};
            if (prim.raysLeave(cone.apex, dirs, 4)) {
                ++stats.leave;
                const double start = 1e-9 * (glm::length(cone.apex) + shape.size);
                for (int k = 0; k < 68; ++k) {
                    Vec3 dir(0.0);
                    if (k < 4) {
                        dir = dirs[k];
                    } else {
                        for (const Vec3& d : dirs) dir += (rng.chance(0.3) ? 0.0 : rng.uniform()) * d;
                        if (!(glm::length(dir) > 0.0)) continue;
                    }
                    const Ray ray{cone.apex, glm::normalize(dir)};
                    if (prim.intersectAny(ray, start, kInfinity) && stats.failures++ < 5)
                        FAIL_CHECK(name << " case " << i << " (replay: ASOS_SHAPE_REPLAY=" << name << ":" << seed
                                        << "): raysLeave, yet the ray from " << fmt(ray.origin) << " along "
                                        << fmt(ray.dir) << " meets the shape\n  shape " << shape.text
                                        << "\n  transform " << transform.text);
                }
            }
        }
        ++stats.cases;
        if (answer.coverage == Coverage::Miss) ++stats.miss;
        else if (answer.coverage == Coverage::Full) ++stats.full;
        else ++stats.marginal;
        if (probe.violations > 0 || nan || replay) {
            std::ostringstream msg;
            msg << name << " case " << i << " (replay: ASOS_SHAPE_REPLAY=" << name << ":" << seed
                << ")\n  shape " << shape.text << "\n  transform " << transform.text << "\n  "
                << describe(cone) << "\n  answer "
                << (answer.coverage == Coverage::Miss   ? "Miss"
                    : answer.coverage == Coverage::Full ? "Full"
                                                        : "Marginal")
                << " [" << fmt(answer.tNear) << ", " << fmt(answer.tFar) << "] singleEdge "
                << answer.singleEdge << " creaseParts " << int(answer.creaseParts) << "\n  probe " << probe.hits << "/" << probe.rays
                << " rays hit; " << probe.violations << " contradict"
                << (probe.firstViolation.empty() ? "" : ": " + probe.firstViolation)
                << (nan ? "\n  NaN depth bound" : "");
            if (replay && probe.violations == 0 && !nan) {
                WARN(msg.str());
            } else {
                ++stats.failures;
                if (stats.failures <= 5) FAIL_CHECK(msg.str());
            }
        }
    }
    return stats;
}

// Primitive::classifyRigid hands a rigid frame's shape (a disc, circular or
// elliptic; a box; a polygon) its cone before the range is set (classifyRanging): the
// answers must be those of classify on the ranged cone, brought back by the
// same RigidBounds (whose world range is the local one scaled, as
// classifyRigid's). The fast paths' answers hold their depths against the
// world range with one padding rather than two (rangedClass on RigidBounds,
// its full and marginal), so their bounds may differ by the tolerances, and
// nothing more.
// `make` builds a shape about `size` across, about the origin.
template <class Shape>
void checkRangingAsClassify(std::uint64_t seed, Shape (*make)(Rng&, double)) {
    Rng rng(seed);
    int misses = 0, others = 0;
    for (int i = 0; i < 20000; ++i) {
        const double size = rng.uniform(0.2, 2.0);
        const Shape d = make(rng, size);
        LocalCone cone;
        cone.apex = Vec3(rng.uniform(-4, 4), rng.uniform(-4, 4), rng.uniform(-4, 4));
        cone.axis = rng.unitVector();
        const double half = rng.uniform(0.0, 0.4);
        cone.cosHalf = std::cos(half);
        cone.sinHalf = std::sin(half);
        const double t0 = rng.chance(0.5) ? 0.0 : rng.uniform(0.0, 4.0);
        const double t1 = rng.chance(0.5) ? kInfinity : t0 + rng.uniform(0.0, 6.0);
        const double absTol = kPositionTolerance * (std::abs(cone.apex.x) + std::abs(cone.apex.y) +
                                                    std::abs(cone.apex.z) + size);
        const double worldPerLocal = rng.uniform(0.5, 2.0);
        const RigidBounds back{absTol, worldPerLocal, t0 * worldPerLocal, t1 * worldPerLocal};
        LocalCone ranged = cone;
        ranged.setRange(t0, t1, absTol);
        const ConeClass want = back(d.classify(ranged));
        LocalCone unranged = cone;
        unranged.absTol = absTol;
        const ConeClass got = d.classifyRanging(unranged, t0, t1, back);
        INFO("cone " << i);
        REQUIRE(static_cast<int>(got.coverage) == static_cast<int>(want.coverage));
        REQUIRE(got.singleEdge == want.singleEdge);
        if (got.coverage != Coverage::Miss) {
            const double slack = 1e-8 * (std::abs(want.tNear) + std::abs(want.tFar)) + 4.0 * absTol;
            REQUIRE(std::abs(got.tNear - want.tNear) <= slack);
            REQUIRE(std::abs(got.tFar - want.tFar) <= slack);
        }
        (got.coverage == Coverage::Miss ? misses : others) += 1;
    }
    CHECK(misses > 1000);
    CHECK(others > 1000);
}

}  // namespace shapetest
