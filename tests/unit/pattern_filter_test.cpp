// ASOS's pattern filter (render/pattern_filter.hpp): the share of a
// footprint in a pattern's second colour, by image area, against known
// answers on a plane facing an orthographic camera (a footprint inside one
// cell, across one edge at a known fraction, across a corner, a huge one at
// the pattern's mean) and against dense supersampling of the footprint
// through perspective cameras, tilted planes and rotated patterns.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

#include "asos/render/pattern_edges.hpp"
#include "asos/render/pattern_filter.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

// A plane seen through `camera`: the filter's footprint of a square, and the
// dense count of the pattern over the same square (n x n rays at the
// centres of its cells, each meeting the plane), within about 1/n per edge
// crossing the square.
struct PlaneView {
    CameraModel camera;
    Vec3 point;
    Vec3 normal;

    double filtered(const Pigment& pigment, const ImageSquare& square) const {
        const std::optional<PatternFootprint> f = PatternFootprint::make(
            camera, square, point, normal, pigment.worldFromPattern.inverseMatrix());
        REQUIRE(f);
        return patternShare(pigment, *f);
    }
    double dense(const Pigment& pigment, const ImageSquare& square, int n) const {
        long ones = 0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const Vec2 p = square.pointAt({(i + 0.5) / n, (j + 0.5) / n});
                const Ray ray = camera.ray(p.x, p.y);
                const double t = glm::dot(normal, point - ray.origin) / glm::dot(normal, ray.dir);
                ones += pigmentIndex(pigment, ray.at(t));
            }
        return double(ones) / (double(n) * n);
    }
};

// The plane z = depth seen straight on: image point (u, v) sees world
// (u, -v), as in the tracer's tests.
PlaneView facing(double depth = 0.0) {
    return {CameraModel(orthoCamera(8, 8), 8, 8), {0.0, 0.0, depth}, {0.0, 0.0, -1.0}};
}

// The image square that sees world x in [x0, x1], y in [y0, y1] in `facing`.
ImageSquare seeing(double x0, double x1, double y0, double y1) { return {x0, -y1, x1, -y0}; }

Pigment checker(const Transform& worldFromPattern = Transform()) {
    Pigment p;
    p.kind = Pigment::Kind::Checker;
    p.color1.rgb = Vec3(0.0);
    p.color2.rgb = Vec3(1.0);
    p.worldFromPattern = worldFromPattern;
    return p;
}

Pigment brick(const Vec3& size, double mortar, const Transform& worldFromPattern = Transform()) {
    Pigment p = checker(worldFromPattern);
    p.kind = Pigment::Kind::Brick;
    p.brickSize = size;
    p.mortar = mortar;
    return p;
}

}  // namespace

TEST_CASE("The filtered checker has its known answers", "[pattern-filter]") {
    const PlaneView view = facing();
    const Pigment p = checker();
    // On z = 0 the checker is that of x and y: cell (0, -1) is colour 2.
    CHECK(view.filtered(p, seeing(0.2, 0.8, -0.8, -0.2)) == 1.0);
    CHECK(view.filtered(p, seeing(1.2, 1.8, -0.8, -0.2)) == 0.0);
    // Across the edge x = 1, 30 % of it before the edge, in colour 2.
    CHECK(view.filtered(p, seeing(0.7, 1.7, -0.8, -0.2)) == Approx(0.3));
    // Across a corner, centred: half; off centre: x 2/3 in cell 0, y 3/4 in
    // cell -1, colour 2 in cells (0, -1) and (1, -2).
    CHECK(view.filtered(p, seeing(0.75, 1.25, -1.5, -0.5)) == Approx(0.5));
    CHECK(view.filtered(p, seeing(0.6, 1.2, -1.25, -0.25)) ==
          Approx(2.0 / 3.0 * 0.75 + 1.0 / 3.0 * 0.25));
    // A huge footprint: the mean.
    CHECK(view.filtered(p, seeing(-700.3, 900.1, -1200.6, 300.2)) == Approx(0.5).margin(1e-3));
    // So far out that whole cells are no longer told apart: a share all the
    // same, without counting the cells.
    const double far = view.filtered(checker(Transform::translate({-1e17, 0.0, 0.0})), seeing(0.2, 0.8, -0.8, -0.2));
    CHECK(far >= 0.0);
    CHECK(far <= 1.0);
    // A footprint of a few whole cells, clipped exactly: 3 x 2, and 3 x 1
    // with cells (-1, 0) and (1, 0) in colour 2.
    CHECK(view.filtered(p, seeing(-1.0, 2.0, 0.0, 2.0)) == Approx(0.5));
    CHECK(view.filtered(p, seeing(-1.0, 2.0, 0.0, 1.0)) == Approx(2.0 / 3.0));
}

TEST_CASE("The filtered brick has its known answers", "[pattern-filter][brick]") {
    // Bricks 4 x 2 (x, y), mortar 0.5, on the plane z = 1, clear of the
    // joints along z: bed joints at y in [-0.5, 0] + 2k; head joints of
    // course 0 (y in (0, 1.5)) at x in [-0.5, 0] + 4k, of course 1 at
    // x in [1.5, 2] + 4k.
    const PlaneView view = facing(1.0);
    const Pigment p = brick({4.0, 2.0, 4.0}, 0.5);
    CHECK(view.filtered(p, seeing(0.5, 1.5, 0.25, 1.25)) == 1.0);   // inside a brick
    CHECK(view.filtered(p, seeing(0.5, 1.5, -0.4, -0.1)) == 0.0);   // inside a bed joint
    CHECK(view.filtered(p, seeing(1.0, 2.0, -0.25, 0.75)) == Approx(0.75));  // across its top
    // Across the corner of a bed joint and course 0's head joint.
    CHECK(view.filtered(p, seeing(-0.25, 0.25, -0.25, 0.75)) == Approx(0.375));
    // Across two courses: y in [1, 1.5] brick, [1.5, 2] the bed joint, and
    // [2, 2.5] course 1, whose head joint x in [1.5, 2] takes half of it.
    CHECK(view.filtered(p, seeing(1.0, 2.0, 1.0, 2.5)) == Approx((0.5 + 0.25) / 1.5));
    // A huge footprint: the mean of the pattern on this plane.
    CHECK(view.filtered(p, seeing(-900.3, 700.1, -600.6, 800.2)) ==
          Approx((1.0 - 0.5 / 2.0) * (1.0 - 0.5 / 4.0)).margin(2e-3));
}

namespace {

// Random views of random planes under random pattern transforms: for each
// footprint of up to a few cells that the tangent plane holds, the filter
// against a dense count of the pattern over the same image square.
void checkAgainstDense(const Pigment& base, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0), signedUnit(-1.0, 1.0), degrees(0.0, 360.0);
    const double sides[] = {0.25, 0.5, 1.0, 2.0, 4.0};
    int checked = 0, crossed = 0;
    for (int i = 0; i < 400 && checked < 120; ++i) {
        const Vec3 target(3.0 * signedUnit(rng), 0.0, 3.0 * signedUnit(rng));
        const Vec3 eye(6.0 * signedUnit(rng), 1.0 + 4.0 * unit(rng), -8.0);
        const Camera c = lookAtCamera(eye, target, 50.0);
        const int width = 64, height = 48;
        // A plane through the target, tilted up to 60 degrees from level.
        const Vec3 normal = glm::normalize(Vec3(signedUnit(rng), 1.2, signedUnit(rng)));
        const PlaneView view{CameraModel(c, width, height), target, normal};
        Pigment p = base;
        p.worldFromPattern = Transform::translate({signedUnit(rng), signedUnit(rng), signedUnit(rng)}) *
                             Transform::rotateDegrees({degrees(rng), degrees(rng), degrees(rng)}) *
                             Transform::scale(Vec3(0.2 + 0.8 * unit(rng)));
        const double side = sides[i % 5];
        const double x = (width - side) * unit(rng), y = (height - side) * unit(rng);
        const ImageSquare square{x, y, x + side, y + side};
        const std::optional<PatternFootprint> f = PatternFootprint::make(
            view.camera, square, view.point, view.normal, p.worldFromPattern.inverseMatrix());
        if (!f) continue;
        Vec3 lo(kInfinity), hi(-kInfinity);
        for (const Vec2 corner : {Vec2(x, y), Vec2(x + side, y), Vec2(x, y + side), Vec2(x + side, y + side)}) {
            lo = glm::min(lo, f->at(corner.x, corner.y));
            hi = glm::max(hi, f->at(corner.x, corner.y));
        }
        // Only footprints of a few cells: beyond, the filter's closed form
        // is near the mean rather than exact.
        const Vec3 extent = hi - lo;
        if (std::max({extent.x, extent.y, extent.z}) > 3.0) continue;
        ++checked;
        const double share = patternShare(p, *f);
        const double dense = view.dense(p, square, 128);
        crossed += dense > 0.0 && dense < 1.0;
        INFO("case " << i << ": square " << x << ", " << y << " side " << side);
        CHECK(share == Approx(dense).margin(0.015));
    }
    // Enough footprints were met, many of them across edges.
    CHECK(checked >= 100);
    CHECK(crossed >= 40);
}

}  // namespace

TEST_CASE("The filtered checker matches dense supersampling of the footprint", "[pattern-filter]") {
    checkAgainstDense(checker(), 3);
}

TEST_CASE("The filtered brick matches dense supersampling of the footprint", "[pattern-filter][brick]") {
    checkAgainstDense(brick({2.0, 1.0, 1.5}, 0.25), 7);
    checkAgainstDense(brick({-1.5, 0.7, 1.0}, 0.3), 8);
}

TEST_CASE("The filtered pigment mixes the two colours by the share", "[pattern-filter]") {
    const PlaneView view = facing();
    Pigment p = checker();
    p.color1.rgb = {0.2, 0.4, 0.6};
    p.color2.rgb = {1.0, 0.0, 0.5};
    const ImageSquare square = seeing(0.7, 1.7, -0.8, -0.2);  // 30 % colour 2
    const std::optional<PatternFootprint> f =
        PatternFootprint::make(view.camera, square, view.point, view.normal, Mat4(1.0));
    REQUIRE(f);
    const Color mixed = filteredPigment(p, *f);
    CHECK(mixed.rgb.x == Approx(0.7 * 0.2 + 0.3 * 1.0));
    CHECK(mixed.rgb.y == Approx(0.7 * 0.4));
    CHECK(mixed.rgb.z == Approx(0.7 * 0.6 + 0.3 * 0.5));
    // Inside one cell: exactly that cell's colour, as a point sample.
    const std::optional<PatternFootprint> inside = PatternFootprint::make(
        view.camera, seeing(0.2, 0.8, -0.8, -0.2), view.point, view.normal, Mat4(1.0));
    REQUIRE(inside);
    CHECK(filteredPigment(p, *inside).rgb == p.color2.rgb);
}

TEST_CASE("A footprint that leaves the plane's visible side has no filter", "[pattern-filter]") {
    // A level floor seen from above: a square reaching above the horizon
    // has corner rays that never meet it.
    const Camera c = lookAtCamera({0.0, 1.0, -5.0}, {0.0, 1.0, 0.0}, 60.0);
    const CameraModel camera(c, 40, 30);
    const Vec3 point(0.0, 0.0, 5.0), up(0.0, 1.0, 0.0);
    CHECK(PatternFootprint::make(camera, {10.0, 20.0, 11.0, 21.0}, point, up, Mat4(1.0)));
    CHECK_FALSE(PatternFootprint::make(camera, {10.0, 10.0, 11.0, 16.0}, point, up, Mat4(1.0)));
    // The plane through the eye.
    CHECK_FALSE(PatternFootprint::make(camera, {10.0, 20.0, 11.0, 21.0}, {0.0, 1.0, 3.0}, up, Mat4(1.0)));
}
