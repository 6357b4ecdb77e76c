// Where a shadow beam's rays run (geometry/beam_hull.hpp): known answers at
// the light's plane and beside the beam, every light form's hull holding the
// rays of its beam, and the proofs that an object lies outside checked
// against dense rays of the beam, for every kind of primitive
// (Primitive::outside).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "asos/accel/cone_box.hpp"
#include "asos/lights/light_form.hpp"
#include "asos/scene/pov_tolerances.hpp"
#include "asos/shapes/primitive.hpp"
#include "random_direction.hpp"
#include "shape_property.hpp"

using namespace asos;

namespace {

using asos::test::randomUnit;

// A box of half-size h about p.
Bounds3 boxAbout(const Vec3& p, double h) { return {p - Vec3(h), p + Vec3(h)}; }

// The pyramid from the origin over the square z = 1, |x|, |y| <= 1; rays stop
// `gap` before it.
BeamHull unitPyramid(double gap) {
    const Vec3 base[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    return *BeamHull::over(Vec3(0.0), base, 4, std::sqrt(3.0), gap);
}

}  // namespace

TEST_CASE("Beam hulls: known answers at the light, beside the beam and behind the apex", "[lights][hull]") {
    const BeamHull hull = unitPyramid(0.0);
    // Beyond the light's plane; touching it; just in front of it.
    CHECK(hull.missesBox({{-5, -5, 1.0001}, {5, 5, 2}}));
    CHECK_FALSE(hull.missesBox({{-5, -5, 1.0}, {5, 5, 2}}));
    CHECK_FALSE(hull.missesBox({{-5, -5, 0.999}, {5, 5, 0.9995}}));
    CHECK(hull.missesPlane({0, 0, 1}, {0, 0, 1.0001}));
    CHECK_FALSE(hull.missesPlane({0, 0, 1}, {0, 0, 0.9999}));
    // Beside the beam, inside the cone about it (a corner ray is 54.7
    // degrees off the axis, a side's middle 45): outside a side face.
    CHECK(hull.missesBox(boxAbout({0, 1.1, 0.9}, 0.05)));
    CHECK_FALSE(hull.missesBox(boxAbout({0, 0.85, 0.9}, 0.1)));
    // Behind the apex: outside the hull's box.
    CHECK(hull.missesBox(boxAbout({0, 0, -0.2}, 0.1)));
    CHECK(hull.missesPlane(glm::normalize(Vec3(0.2, 0.1, 1.0)), {0, 0, -0.01}));
    CHECK_FALSE(hull.missesPlane(glm::normalize(Vec3(0.2, 0.1, 1.0)), {0, 0, 0.01}));

    // Rays stopping 0.01 before the light: the ray toward a corner (length
    // sqrt 3) stops at z = 1 - 0.01 / sqrt 3, the deepest of all.
    const BeamHull gapped = unitPyramid(0.01);
    const double deepest = 1.0 - 0.01 / std::sqrt(3.0);
    CHECK(gapped.missesBox({{-5, -5, deepest + 1e-9}, {5, 5, 2}}));
    CHECK_FALSE(gapped.missesBox({{-5, -5, deepest - 1e-9}, {5, 5, 2}}));
    CHECK(gapped.missesPlane({0, 0, 1}, {0, 0, 1.0}));

    // Beyond the light alone, within a box holding the cone: the box beside
    // the beam is not proved outside, nor is the part of a tilted plane
    // in front of the light; a plane beyond the light within the box is.
    const Bounds3 reach{{-2, -2, 0}, {2, 2, 1.8}};
    const BeamHull beyond = hull.beyondLight(reach);
    CHECK(beyond.missesBox({{-5, -5, 1.0001}, {5, 5, 2}}));
    CHECK_FALSE(beyond.missesBox(boxAbout({0, 1.1, 0.9}, 0.05)));
    CHECK(beyond.missesBox(boxAbout({0, 0, 5}, 0.1)));  // outside the reach
    // A box from in front of the light to beyond it, whose part within the
    // reach lies beyond the light.
    CHECK(beyond.missesBox({{-1, -1, 1.5}, {1, 1, 3}}));
    CHECK_FALSE(beyond.missesBox({{-1, -1, 0.5}, {1, 1, 3}}));
    // Tilted planes: beyond the light across the whole reach, or not.
    CHECK(beyond.missesPlane(glm::normalize(Vec3(0.1, 0, 1)), {0, 0, 1.25}));
    CHECK_FALSE(beyond.missesPlane(glm::normalize(Vec3(0.5, 0, 1)), {0, 0, 1.25}));
    CHECK_FALSE(beyond.missesPlane({0, 0, 1}, {0, 0, 0.9}));

    // A triangle (a segment's beam): beyond its far edge, or out of its plane.
    const Vec3 ends[2] = {{-1, 0, 1}, {1, 0, 1}};
    const BeamHull triangle = *BeamHull::over(Vec3(0.0), ends, 2, std::sqrt(2.0), 0.0);
    CHECK(triangle.missesBox(boxAbout({0, 0, 1.2}, 0.1)));
    CHECK(triangle.missesBox(boxAbout({0, 0.2, 0.5}, 0.1)));
    CHECK_FALSE(triangle.missesBox(boxAbout({0, 0.05, 0.5}, 0.1)));
    CHECK(triangle.missesPlane({0, 0, 1}, {0, 0, 1.001}));
    CHECK_FALSE(triangle.missesPlane({0, 1, 0}, {0, 0, 0}));
    // A linear light under a ceiling, seen from the side (34 degrees from
    // square to the triangle): the ceiling lies beyond a plane through the
    // light, though not beyond the one square to the triangle; flush with
    // the light, it lies beyond the gap the rays stop short by. So does a
    // wall behind the light; a box beside the triangle, or past the light's
    // end, lies beyond no plane through the light near square to it.
    const Vec3 tube[2] = {{-1, 3, 0}, {1, 3, 0}};
    const Vec3 side(0, 0, -2);
    const Bounds3 room{{-2, -1, -3}, {2, 4, 1}};
    const BeamHull under = BeamHull::over(side, tube, 2, std::sqrt(14.0), 0.0)->beyondLight(room);
    CHECK(under.missesPlane({0, 1, 0}, {0, 3.0001, 0}));
    CHECK(under.missesBox({{-5, 3.0001, -5}, {5, 3.2, 5}}));
    CHECK_FALSE(under.missesPlane({0, 1, 0}, {0, 2.999, 0}));
    CHECK_FALSE(under.missesPlane({0, 1, 0}, {0, 3.0, 0}));
    const BeamHull gappedTube = BeamHull::over(side, tube, 2, std::sqrt(14.0), 1e-3)->beyondLight(room);
    CHECK(gappedTube.missesPlane({0, 1, 0}, {0, 3.0, 0}));
    CHECK(gappedTube.missesBox({{-5, 3.0, -5}, {5, 3.2, 5}}));
    CHECK(under.missesBox({{-5, 0, 0.5}, {5, 4, 0.6}}));
    CHECK_FALSE(under.missesBox(boxAbout({0, 1.78, -1.42}, 0.05)));
    CHECK_FALSE(under.missesBox({{1.2, 0, -3}, {1.3, 4, 1}}));

    // None from an apex in the base's plane or on the segment's line.
    CHECK_FALSE(BeamHull::over({0, 0, 1}, ends, 2, 2.0, 0.0));
    const Vec3 square[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    CHECK_FALSE(BeamHull::over({3, 0, 1}, square, 4, 5.0, 0.0));
    // None where the gap reaches the apex.
    CHECK_FALSE(BeamHull::over(Vec3(0.0), square, 4, std::sqrt(3.0), 2.0));
}

namespace {

// The stretch of the ray from the apex toward y that the tracer tests:
// from the shadow tolerance to `gap` before y.
template <class F>
void forEachStretchPoint(const BeamRay& r, double tMin, double gap, int steps, F&& f) {
    const double t1 = r.distance - gap;
    if (!(tMin < t1)) return;
    for (int k = 0; k <= steps; ++k) f(r.ray.at(tMin + (t1 - tMin) * k / steps));
}

// Random beams of every form, from points near and far.
struct FormCase {
    LightForm form;
    Vec3 apex;
};
FormCase randomForm(std::mt19937_64& rng, int kind) {
    std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
    const Vec3 centre(u(rng), 3.0 + u(rng), u(rng));
    const double size = 0.1 + 2.0 * u01(rng);
    const Vec3 apex = centre + randomUnit(rng) * (size * (0.6 + 5.0 * u01(rng)));
    if (kind == 0) {
        RectangleLight r;
        r.edgeA = randomUnit(rng) * size;
        r.edgeB = glm::normalize(glm::cross(r.edgeA, randomUnit(rng))) * (size * (0.2 + u01(rng)));
        r.corner = centre - 0.5 * (r.edgeA + r.edgeB);
        return {r, apex};
    }
    if (kind == 1) {
        SegmentLight s;
        const Vec3 axis = randomUnit(rng) * size;
        s.start = centre - 0.5 * axis;
        s.end = centre + 0.5 * axis;
        s.length = size;
        return {s, apex};
    }
    if (kind == 2) {
        SphereLight sphere;
        sphere.centre = centre;
        sphere.radius = 0.5 * size;
        return {sphere, apex};
    }
    OrientedDiscLight disc;
    disc.centre = centre;
    disc.radius = 0.5 * size;
    return {disc, apex};
}

// Runs f(i, seed, c, light, beam, hull) for `count` random beams, every form in
// turn, each case with its own seed (so that a failing one can be replayed)
// and random numbers in `rng`.
template <class F>
void forEachBeam(std::uint64_t base, int count, std::mt19937_64& rng, F&& f) {
    for (int i = 0; i < count; ++i) {
        const std::uint64_t seed = shapetest::splitmix(base + std::uint64_t(i));
        rng.seed(seed);
        const FormCase c = randomForm(rng, i % 4);
        withAreaForm(c.form, [&](const auto& light) {
            const auto beam = light.beamFrom(c.apex, kPovShadowTolerance);
            if (!beam) return;
            const std::optional<BeamHull> hull = beam->hull(kPovShadowTolerance);
            REQUIRE(hull);
            f(i, seed, c, light, *beam, *hull);
        });
    }
}

}  // namespace

TEST_CASE("Beam hulls hold every ray of their light form's beam, up to the gap before the light",
          "[lights][hull][property]") {
    std::mt19937_64 rng;
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    const double gap = kPovShadowTolerance;
    int checked = 0;
    forEachBeam(0xbea4a11ull, 600, rng, [&](int i, std::uint64_t seed, const FormCase& c, const auto&,
                                            const auto& beam, const BeamHull& hull) {
        // Rays of the whole beam and of its pieces two levels down, to
        // their corners and inside: every point of each stretch inside
        // (a box of rounding's size about it is never outside).
        std::vector<LightPiece> pieces{beam.root()};
        LightPiece children[4];
        for (int level = 0; level < 2; ++level) {
            std::vector<LightPiece> next;
            for (const LightPiece& p : pieces) {
                const int n = beam.split(p, children);
                next.insert(next.end(), children, children + n);
            }
            pieces.insert(pieces.end(), next.begin(), next.end());
        }
        for (const LightPiece& p : pieces)
            for (int k = 0; k < 6; ++k) {
                const Vec2 xi = k < 4 ? Vec2(k & 1, k >> 1) : Vec2(u01(rng), u01(rng));
                forEachStretchPoint(k == 5 ? p.central : beam.sample(p, xi), gap, gap, 8, [&](const Vec3& x) {
                    INFO("case " << i << " (seed " << seed << "), " << lightFormName(c.form) << ", piece level "
                                 << p.level);
                    CHECK_FALSE(hull.missesBox(boxAbout(x, 1e-9 * (1.0 + glm::length(x)))));
                    ++checked;
                });
            }
    });
    CHECK(checked > 100000);
}

namespace {

// A random primitive about `near`, `size` across: every kind, turned and
// scaled, and planes.
Primitive randomPrimitive(std::mt19937_64& rng, const Vec3& near, double size) {
    std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
    const Transform place = Transform::translate(near) *
                            Transform::rotateDegrees({180.0 * u(rng), 180.0 * u(rng), 180.0 * u(rng)}) *
                            Transform::scale(Vec3(0.5 + u01(rng), 0.5 + u01(rng), 0.5 + u01(rng)) * size);
    switch (std::uniform_int_distribution<int>(0, 6)(rng)) {
        case 0: return Primitive::make(SphereShape{Vec3(0.0), 0.5}, place);
        case 1: return Primitive::make(BoxShape{Vec3(-0.5), Vec3(0.5)}, place);
        case 2: return Primitive::make(CylinderShape{{0, -0.5, 0}, {0, 0.5, 0}, 0.3, u01(rng) < 0.5}, place);
        case 3: return Primitive::make(ConeShape{{0, -0.5, 0}, 0.4, {0, 0.5, 0}, 0.1, u01(rng) < 0.5}, place);
        case 4: return Primitive::make(DiscShape{Vec3(0.0), {0, 1, 0}, 0.5, 0.2 * u01(rng)}, place);
        case 5:
            return Primitive::make(PolygonShape{{{-0.5, -0.3, 0}, {0.5, -0.4, 0}, {0.2, 0.5, 0}, {-0.5, -0.3, 0}}},
                                   place);
        default: {
            const Vec3 n = randomUnit(rng);
            return Primitive::make(PlaneShape{n, glm::dot(n, near)}, {});
        }
    }
}

}  // namespace

TEST_CASE("Objects shown outside a beam's hull meet none of its rays (dense rays, every primitive)",
          "[lights][hull][property]") {
    std::mt19937_64 rng;
    std::uniform_real_distribution<double> u(-1.0, 1.0), u01(0.0, 1.0);
    const double gap = kPovShadowTolerance;
    int outside = 0, beyond = 0, cases = 0;
    forEachBeam(0xbea4b21ull, 3000, rng, [&](int i, std::uint64_t seed, const FormCase& c, const auto& light,
                                             const auto& beam, const BeamHull& hull) {
        const LightPiece root = beam.root();
        // The box of the cone, as the tracer takes it.
        const Bounds3 reach = ConeBoxTest(root.cone).coneBounds();
        // Objects about the light (just beyond it, just in front of it,
        // beside it) and about the beam's rays.
        const Bounds3 lb = light.bounds();
        const Vec3 near = u01(rng) < 0.6 ? lb.center() + 0.7 * u(rng) * lb.diagonal() +
                                               randomUnit(rng) * (0.3 * glm::length(lb.diagonal()) * u01(rng))
                                         : root.central.ray.at(root.central.distance * u01(rng)) +
                                               randomUnit(rng) * (0.5 * u01(rng));
        const Primitive p = randomPrimitive(rng, near, 0.05 + 0.8 * u01(rng));
        const bool whole = p.outside(hull);
        const bool past = p.outside(hull.beyondLight(reach));
        ++cases;
        outside += whole;
        beyond += past;
        if (!whole && !past) return;
        for (int k = 0; k < 400; ++k) {
            const BeamRay r = beam.sample(root, Vec2(u01(rng), u01(rng)));
            const double t1 = r.distance - gap;
            INFO("case " << i << " (seed " << seed << "), " << lightFormName(c.form) << " light, a " << p.kindName()
                         << (whole ? ", outside the hull" : ", beyond the light"));
            CHECK_FALSE((gap < t1 && p.intersectAny(r.ray, gap, t1)));
        }
    });
    // Neither answer is vacuous.
    CHECK(outside > cases / 10);
    CHECK(beyond > cases / 20);
}
