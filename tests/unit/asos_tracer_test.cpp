// Known answers for the ASOS eye tracer (paper: "Adaptive Supersampling in
// Object-Space"): coverage of an edge within EPS of the exact area, one ray
// for a covered pixel, thin objects found, the leaf count bounded by 4^MAX,
// and the pathological in/out construction stopped by MAX.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "asos/render/asos_tracer.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

// A scene seen by an orthographic camera with one world unit per pixel:
// image point (u, v) sees world (u, -v).
struct Setup {
    SceneDescription description;
    std::unique_ptr<Scene> scene;
    std::unique_ptr<RayTracer> tracer;
    std::unique_ptr<CameraModel> camera;
    std::unique_ptr<AsosTracer> asos;
    AsosScratch scratch;

    // The description's own camera when `keepCamera`, else orthoCamera.
    Setup(SceneDescription d, int width, int height, AsosSettings settings, std::uint64_t seed = 0,
          bool patternEdges = false, bool patternFilter = false, bool keepCamera = false)
        : description(std::move(d)) {
        if (!keepCamera) description.camera = orthoCamera(width, height);
        scene = buildScene(description);
        tracer = std::make_unique<RayTracer>(*scene);
        camera = std::make_unique<CameraModel>(description.camera, width, height);
        asos = std::make_unique<AsosTracer>(*tracer, *camera, settings, seed, patternEdges, patternFilter);
    }
    AsosPixelReport pixel(int x, int y) {
        RenderCounters counters;
        return asos->tracePixelReport(x, y, scratch, counters);
    }
};

// The in-plane normal of a half-plane's edge, for the exact areas.
Vec2 edgeNormal(double degrees) {
    const Vec3 n = Transform::rotateDegrees({0.0, 0.0, degrees}).vector({1.0, 0.0, 0.0});
    return glm::normalize(Vec2(n.x, n.y));
}

// A half-plane box: object space x <= 0, placed by rotating about z and
// moving its edge through `through`. Its side face x = 0 is turned 10 degrees
// away from the camera about its front edge, so that that edge alone
// outlines it (seen edge on, the back edge would lie on the outline too).
Object halfPlane(double degrees, const Vec2& through) {
    auto tiltBy = [](double beta) {
        return Transform::translate({0.0, 0.0, -1.0}) * Transform::rotateDegrees({0.0, beta, 0.0}) *
               Transform::translate({0.0, 0.0, 1.0});
    };
    Transform tilt = tiltBy(10.0);
    if (tilt.point({0.0, 0.0, 1.0}).x > 0.0) tilt = tiltBy(-10.0);
    const Transform t = Transform::translate({through.x, through.y, 0.0}) *
                        Transform::rotateDegrees({0.0, 0.0, degrees}) * tilt;
    return makeObject(BoxShape{{-1000.0, -1000.0, -1.0}, {0.0, 1000.0, 1.0}}, coverageTexture(), t);
}

struct PatternPixel {
    double exact = 0.0;  // the share of the pixel in the pattern's second colour
    std::uint32_t rays = 0;
};

// The share of pixel (x, y) of `Setup`'s camera in the second colour of
// `pigment` on the plane z = 0, by a 128 x 128 point count of the pattern
// (itself within about 1/128 of the area).
double pixelShare(const Pigment& pigment, int x, int y) {
    int ones = 0;
    for (int j = 0; j < 128; ++j)
        for (int k = 0; k < 128; ++k)
            ones += pigmentIndex(pigment, {x + (k + 0.5) / 128, -(y + (j + 0.5) / 128), 0.0});
    return ones / 16384.0;
}

// A plane facing the camera with `pigment` (its first colour black, its
// second white).
SceneDescription patternPlane(Pigment& pigment) {
    Texture texture = coverageTexture(0.0);
    pigment.color1 = texture.pigment.color1;
    pigment.color2.rgb = Vec3(1.0);
    texture.pigment = pigment;
    SceneDescription d;
    d.objects.push_back(makeObject(PlaneShape{{0, 0, -1}, 0.0}, texture));
    return d;
}

// The plane of `patternPlane`, traced with pattern edges: at every third
// pixel across and every `rowStep` down a 16 x 16 image, the pixel's value is
// within EPS of the share of the pixel in the second colour, and a pixel the
// pattern crosses is subdivided. `label` names the case in a failure.
std::vector<PatternPixel> measurePattern(Pigment pigment, const AsosSettings& settings, int rowStep, int label) {
    Setup s(patternPlane(pigment), 16, 16, settings, 0, true);
    std::vector<PatternPixel> pixels;
    for (int y = 0; y < 16; y += rowStep)
        for (int x = 0; x < 16; x += 3) {
            const double exact = pixelShare(pigment, x, y);
            const AsosPixelReport r = s.pixel(x, y);
            INFO("case " << label << ", pixel " << x << ", " << y << ": exact " << exact);
            CHECK(std::abs(r.result.color.x - exact) <= settings.eps + 0.008);
            if (exact > 0.02 && exact < 0.98) CHECK(r.result.level >= 1);
            pixels.push_back({exact, r.result.rays});
        }
    return pixels;
}

}  // namespace

TEST_CASE("ASOS measures a straight edge through a pixel within EPS of its exact area", "[asos]") {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> angle(0.0, 360.0), offset(0.05, 0.95);
    // MAX high enough that EPS ends the subdivision: the cones around the
    // pyrays also call pyrays within half a diagonal of the edge marginal,
    // so the bound may reach 1/64 up to two levels later than the paper's
    // log2(1/EPS) - 1 = 5.
    const AsosSettings settings{1.0 / 64.0, 8, false};
    for (int i = 0; i < 150; ++i) {
        const double degrees = angle(rng);
        // The edge passes through a point of pixel (3, 3), whose image square
        // [3, 4] x [3, 4] is world [3, 4] x [-4, -3].
        const Vec2 through{3.0 + offset(rng), -3.0 - offset(rng)};
        SceneDescription d;
        d.objects.push_back(halfPlane(degrees, through));
        Setup s(d, 8, 8, settings);
        // Covered: world points q with (q - through) . n <= 0, n the box's
        // local x axis; in image coordinates q = (u, -v).
        const Vec2 n = edgeNormal(degrees);
        const double exact = halfPlaneArea(3, 3, 4, 4, n.x, -n.y, glm::dot(n, through));
        const AsosPixelReport r = s.pixel(3, 3);
        INFO("angle " << degrees << ", through " << through.x << ", " << through.y);
        CHECK(std::abs(r.result.color.x - exact) <= settings.eps + 1e-9);
        REQUIRE_FALSE(r.levels.empty());
        // It stopped on EPS, not on MAX.
        CHECK(r.levels.back().bound <= settings.eps);
    }
}

TEST_CASE("ASOS spends one ray on a pixel inside a sphere", "[asos]") {
    SceneDescription d;
    d.objects.push_back(makeObject(SphereShape{{4.0, -4.0, 0.0}, 50.0}, coverageTexture(0.5)));
    Setup s(d, 8, 8, AsosSettings{});
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            RenderCounters counters;
            const PixelResult r = s.asos->tracePixel(x, y, s.scratch, counters);
            CHECK(r.rays == 1);
            CHECK(r.level == 0);
            CHECK(counters.eyeRays == 1);
            CHECK(r.color.x == Approx(0.5));
        }

    // The same through a perspective camera, and behind a second sphere's
    // silhouette elsewhere in the image.
    SceneDescription p;
    p.camera = lookAtCamera({0, 0, -10}, {0, 0, 0}, 40);
    p.objects.push_back(makeObject(SphereShape{{0, 0, 0}, 3.0}, coverageTexture()));
    p.objects.push_back(makeObject(SphereShape{{0, 0, 20}, 1.0}, coverageTexture()));
    const auto scene = buildScene(p);
    const RayTracer tracer(*scene);
    const CameraModel camera(p.camera, 64, 48);
    const AsosTracer asos(tracer, camera, AsosSettings{}, 0);
    AsosScratch scratch;
    RenderCounters counters;
    const PixelResult r = asos.tracePixel(32, 24, scratch, counters);
    CHECK(r.rays == 1);
    CHECK(counters.eyeRays == 1);
    CHECK(counters.rayTests == 1);  // only the sphere in front is intersected
}

TEST_CASE("ASOS finds a 0.2-pixel-wide object in every pixel it crosses", "[asos]") {
    // A strip 0.2 pixels wide at 23 degrees across a 16 x 16 image.
    const double degrees = 23.0, width = 0.2;
    const Vec2 through{8.0, -8.0};
    const Transform t = Transform::translate({through.x, through.y, 0.0}) *
                        Transform::rotateDegrees({0.0, 0.0, degrees});
    SceneDescription d;
    d.objects.push_back(makeObject(BoxShape{{-width / 2, -1000.0, -1.0}, {width / 2, 1000.0, 1.0}},
                                   coverageTexture(), t));
    const Vec3 n = glm::normalize(t.vector({1.0, 0.0, 0.0}));
    const double c = n.x * through.x + n.y * through.y;
    Setup s(d, 16, 16, AsosSettings{});

    int crossed = 0, missedBySingle = 0;
    double total = 0.0, exactTotal = 0.0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const double exact = halfPlaneArea(x, y, x + 1, y + 1, n.x, -n.y, c + width / 2) -
                                 halfPlaneArea(x, y, x + 1, y + 1, n.x, -n.y, c - width / 2);
            const AsosPixelReport r = s.pixel(x, y);
            total += r.result.color.x;
            exactTotal += exact;
            if (exact <= 0.0) continue;
            ++crossed;
            INFO("pixel " << x << ", " << y << ": exact " << exact);
            CHECK(r.result.level >= 1);  // detected and subdivided
            if (exact > 0.02) CHECK(r.result.color.x > 0.0);
            CHECK(std::abs(r.result.color.x - exact) < 0.05);
            // One ray through the pixel centre misses most of these pixels.
            const Ray centre = s.camera->pixelCenterRay(x, y);
            if (!s.scene->intersect(centre, 0.0, kInfinity)) ++missedBySingle;
        }
    CHECK(crossed > 16);
    CHECK(missedBySingle > crossed / 2);
    CHECK(total == Approx(exactTotal).epsilon(0.01));
}

TEST_CASE("ASOS never shades more than 4^MAX leaves in a pixel", "[asos]") {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 8.0), r(0.02, 0.6);
    SceneDescription d;
    for (int i = 0; i < 60; ++i)
        d.objects.push_back(
            makeObject(SphereShape{{u(rng), -u(rng), u(rng)}, r(rng)}, coverageTexture()));
    for (int maxLevel = 0; maxLevel <= 4; ++maxLevel) {
        for (bool jitter : {false, true}) {
            Setup s(d, 8, 8, AsosSettings{0.0, maxLevel, jitter});
            int deepest = 0;
            for (int y = 0; y < 8; ++y)
                for (int x = 0; x < 8; ++x) {
                    const AsosPixelReport rep = s.pixel(x, y);
                    CHECK(rep.leaves >= 1);
                    CHECK(rep.leaves <= (1 << (2 * maxLevel)));
                    CHECK(static_cast<int>(rep.result.level) <= maxLevel);
                    deepest = std::max(deepest, static_cast<int>(rep.result.level));
                }
            // EPS 0 subdivides every marginal pixel down to MAX.
            CHECK(deepest == maxLevel);
        }
    }
}

TEST_CASE("The paper's pathological pixel (K-rays alternately in and out) stops at MAX", "[asos]") {
    // Tiny spheres at the centres of the K-squares of pixel (0, 0) for K = 0,
    // 2 and 4: every K-ray hits for even K and misses for odd K, so the bound
    // never falls and only MAX ends the subdivision ("Upper Bound on Number
    // of Subdivisions").
    SceneDescription d;
    for (int level : {0, 2, 4}) {
        const int n = 1 << level;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                d.objects.push_back(makeObject(
                    SphereShape{{(i + 0.5) / n, -(j + 0.5) / n, 0.0}, 0.02}, coverageTexture()));
    }
    const AsosSettings settings{1.0 / 1024.0, 4, false};
    Setup s(d, 1, 1, settings);
    const AsosPixelReport r = s.pixel(0, 0);
    CHECK(r.result.level == 4);
    CHECK(r.leaves == 256);
    REQUIRE(r.levels.size() == 4);
    for (const AsosLevelReport& level : r.levels) {
        INFO("level " << level.level);
        CHECK(level.marginal == (1 << (2 * level.level)));
        CHECK(level.bound > settings.eps);
        // Even levels: every K-ray in; odd levels: none.
        CHECK(level.in == (level.level % 2 == 0 ? level.marginal : 0));
    }
    // The MAX-rays all hit their spheres.
    CHECK(r.result.color.x == Approx(1.0));
}

TEST_CASE("ASOS settings: EPS, MAX and jitter, per object the finest", "[asos]") {
    SceneDescription d;
    d.objects.push_back(halfPlane(31.0, {3.37, -3.61}));
    // A coarse EPS stops early, a fine one goes deeper.
    Setup coarse(d, 8, 8, AsosSettings{0.25, 4, false});
    Setup fine(d, 8, 8, AsosSettings{1.0 / 256.0, 8, false});
    const AsosPixelReport a = coarse.pixel(3, 3), b = fine.pixel(3, 3);
    CHECK(a.result.level < b.result.level);
    CHECK(a.result.rays < b.result.rays);

    // An object's own block refines the scene's setting.
    d.objects[0].asos.maxLevel = 1;
    Setup own(d, 8, 8, AsosSettings{0.0, 4, false});
    CHECK(own.pixel(3, 3).result.level == 1);
    // Two objects in a pixel: the finest of them rules.
    d.objects.push_back(halfPlane(-50.0, {3.5, -3.5}));
    d.objects.back().asos.maxLevel = 3;
    Setup both(d, 8, 8, AsosSettings{0.0, 4, false});
    CHECK(both.pixel(3, 3).result.level == 3);

    // Jitter moves MAX-rays inside their squares: the coverage changes but
    // stays within the leaves' resolution, and it depends on the seed only.
    d.objects.resize(1);
    d.objects[0].asos = {};
    Setup j1(d, 8, 8, AsosSettings{0.0, 3, true}, 1), j1again(d, 8, 8, AsosSettings{0.0, 3, true}, 1);
    Setup j2(d, 8, 8, AsosSettings{0.0, 3, true}, 2), plain(d, 8, 8, AsosSettings{0.0, 3, false}, 1);
    const double c1 = j1.pixel(3, 3).result.color.x, c2 = j2.pixel(3, 3).result.color.x;
    const double c0 = plain.pixel(3, 3).result.color.x;
    CHECK(c1 == j1again.pixel(3, 3).result.color.x);
    CHECK(c1 != c2);
    CHECK(std::abs(c1 - c0) < 0.1);
}

TEST_CASE("ASOS tallies interpenetrating Full objects", "[asos]") {
    // A sphere sunk into a slab seen from the front: inside the sphere's
    // silhouette both are Full, and the circle where the sphere leaves the
    // slab is a visible edge that no silhouette shows.
    SceneDescription d;
    d.objects.push_back(makeObject(BoxShape{{-100, -100, 0}, {100, 100, 100}}, coverageTexture(0.0)));
    d.objects.push_back(makeObject(SphereShape{{8, -8, 0}, 6.0}, coverageTexture(1.0)));
    // The sphere bulges out of the slab's face z = 0 toward the camera; where
    // it does, it is seen (value 1) and elsewhere the slab (0). Seen along z,
    // the visible disc is the whole sphere silhouette, radius 6, so the pixels
    // on the circle of radius 6 are edge pixels; those on the circle
    // x^2 + y^2 = 36 - z^2 at z = 3 lie inside it, with nothing marginal.
    d.objects[1].shape = SphereShape{{8, -8, 3}, 6.0};  // the slab cuts it at z = 0: radius sqrt(27)
    Setup s(d, 16, 16, AsosSettings{1.0 / 64.0, 4, false});
    const double radius = std::sqrt(27.0);
    int edgePixels = 0;
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            // Pixels that the circle of radius sqrt(27) about (8, 8) crosses.
            double nearest = kInfinity, farthest = 0.0;
            for (double cy : {double(y), y + 1.0})
                for (double cx : {double(x), x + 1.0})
                    farthest = std::max(farthest, std::hypot(cx - 8.0, cy - 8.0));
            nearest = std::hypot(std::max({x - 8.0, 0.0, 8.0 - (x + 1.0)}),
                                 std::max({y - 8.0, 0.0, 8.0 - (y + 1.0)}));
            if (!(nearest < radius - 0.05 && farthest > radius + 0.05)) continue;
            ++edgePixels;
            const AsosPixelReport r = s.pixel(x, y);
            INFO("pixel " << x << ", " << y);
            CHECK(r.result.level >= 1);
            CHECK(r.result.color.x > 0.0);
            CHECK(r.result.color.x < 1.0);
        }
    CHECK(edgePixels > 20);
}

TEST_CASE("ASOS takes one ray for a pixel on a rug just above a floor", "[asos]") {
    // Seen from a room's eye height, the rug's and the floor's depths over a
    // pixel's cone overlap far more than the 2 mm between them, but the rug
    // is in front over the whole cone: such a pixel is one object's.
    SceneDescription d;
    d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0.0}, coverageTexture(0.2)));
    d.objects.push_back(makeObject(DiscShape{{0.4, 0.002, 0.6}, {0, 1, 0}, 1.3, 0.0}, coverageTexture(0.8)));
    d.camera = lookAtCamera({2.4, 1.65, -2.8}, {0.4, 0.0, 0.6}, 40.0);
    Setup s(d, 32, 24, AsosSettings{1.0 / 64.0, 4, false}, 0, false, false, true);
    int inside = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            // A pixel whose corners all see the rug well inside its rim.
            bool deep = true;
            for (int corner = 0; corner < 4 && deep; ++corner) {
                const auto hit = s.tracer->nearestHit(s.camera->ray(x + (corner & 1), y + (corner >> 1)));
                deep = hit && hit->objectIndex == 1 &&
                       glm::length(hit->position - Vec3(0.4, 0.002, 0.6)) < 1.3 - 0.1;
            }
            if (!deep) continue;
            ++inside;
            const AsosPixelReport r = s.pixel(x, y);
            INFO("pixel " << x << ", " << y);
            CHECK(r.result.rays == 1);
            CHECK(r.result.color.x == Approx(0.8));
        }
    CHECK(inside > 50);
}

TEST_CASE("ASOS subdivides where a box's crease crosses a pixel and measures it within EPS", "[asos]") {
    // A cube turned 45 degrees about y shows the camera two faces, lit from
    // far away on the left: the left face bright, the right one dark. Its
    // crease, turned 20 degrees in the image, is no outline, yet the pixel
    // changes across it as across an edge.
    const Transform t = Transform::translate({8.0, -8.0, 20.0}) * Transform::rotateDegrees({0.0, 0.0, 20.0}) *
                        Transform::rotateDegrees({0.0, 45.0, 0.0});
    SceneDescription d;
    d.objects.push_back(makeObject(BoxShape{{-6, -6, -6}, {6, 6, 6}}, litTexture(Vec3(1.0), 0.1, 0.8), t));
    d.lights.push_back(pointLight({-1e6, 1e5, -1e6}));
    const AsosSettings settings{1.0 / 64.0, 8, false};
    Setup s(d, 16, 16, settings);
    // The crease facing the camera: the vertical edge of the cube nearest it.
    Vec3 a(0.0), b(0.0);
    for (const double x : {-6.0, 6.0})
        for (const double z : {-6.0, 6.0}) {
            const Vec3 lo = t.point({x, -6.0, z}), hi = t.point({x, 6.0, z});
            if (a == b || lo.z < a.z) {
                a = lo;
                b = hi;
            }
        }
    // In image coordinates q = (u, v) = (x, -y): the side n.q <= c of the line.
    const Vec2 qa(a.x, -a.y), qb(b.x, -b.y);
    const Vec2 n = glm::normalize(Vec2(-(qb - qa).y, (qb - qa).x));
    const double c = glm::dot(n, qa);
    RenderCounters counters;
    const auto valueAt = [&](const Vec2& q) { return s.tracer->radiance(s.camera->ray(q.x, q.y), 1, 1.0, counters).x; };
    const Vec2 mid = 0.5 * (qa + qb);
    const double below = valueAt(mid - 2.0 * n), above = valueAt(mid + 2.0 * n);
    REQUIRE(std::abs(below - above) > 0.5);
    int creasePixels = 0;
    for (int y = 3; y < 13; ++y)
        for (int x = 0; x < 16; ++x) {
            const double share = halfPlaneArea(x, y, x + 1, y + 1, n.x, n.y, c);
            if (share < 0.02 || share > 0.98) continue;
            ++creasePixels;
            const double exact = share * below + (1.0 - share) * above;
            const AsosPixelReport r = s.pixel(x, y);
            INFO("pixel " << x << ", " << y << ": share " << share);
            CHECK(r.result.level >= 1);
            CHECK(std::abs(r.result.color.x - exact) <= settings.eps * std::abs(below - above) + 1e-3);
        }
    CHECK(creasePixels >= 10);
}

TEST_CASE("With pattern edges, ASOS measures a checker edge within EPS", "[asos]") {
    // A checker plane facing the camera, the pattern turned about z so that
    // its cell edges cross the pixels at an angle: pixel values are the
    // fraction of the pixel in the colour-1 cells.
    std::mt19937 rng(21);
    std::uniform_real_distribution<double> angle(5.0, 40.0), offset(0.0, 1.0);
    const AsosSettings settings{1.0 / 64.0, 8, false};
    int pixels = 0, onePixelRays = 0;
    for (int i = 0; i < 24; ++i) {
        const double degrees = angle(rng);
        const Vec2 shift{offset(rng), offset(rng)};
        Pigment checker;
        checker.kind = Pigment::Kind::Checker;
        // Cells 5 pixels wide, so that a pixel meets at most one edge.
        checker.worldFromPattern = Transform::translate({shift.x, shift.y, 0.0}) *
                                   Transform::rotateDegrees({0.0, 0.0, degrees}) * Transform::scale(Vec3(5.0));
        for (const PatternPixel& p : measurePattern(checker, settings, 5, i)) {
            ++pixels;
            if (p.exact == 0.0 || p.exact == 1.0) onePixelRays += p.rays == 1;
        }
    }
    // Pixels inside one cell cost one ray, but for the few an edge barely
    // touches (too little for the point count to see).
    CHECK(onePixelRays > pixels / 2);
}

TEST_CASE("With pattern edges, ASOS measures brick's mortar within EPS", "[asos][brick]") {
    // The same with brick, the mortar's faces (BrickPattern::edgesCrossed)
    // crossing the pixels at an angle.
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> angle(5.0, 40.0), offset(0.0, 8.0);
    const AsosSettings settings{1.0 / 64.0, 8, false};
    int pixels = 0, onePixelRays = 0, insideBrick = 0;
    for (int i = 0; i < 12; ++i) {
        const double degrees = angle(rng);
        const Vec2 shift{offset(rng), offset(rng)};
        Pigment brick;
        brick.kind = Pigment::Kind::Brick;
        // Bricks 12 x 6 pixels, joints 1.5 pixels thick.
        brick.brickSize = {4.0, 2.0, 4.0};
        brick.mortar = 0.5;
        brick.worldFromPattern = Transform::translate({shift.x, shift.y, 0.0}) *
                                 Transform::rotateDegrees({0.0, 0.0, degrees}) * Transform::scale(Vec3(3.0));
        for (const PatternPixel& p : measurePattern(brick, settings, 3, i)) {
            ++pixels;
            if (p.exact == 1.0) {
                ++insideBrick;
                onePixelRays += p.rays == 1;
            }
        }
    }
    // A pixel inside a brick costs one ray but where a joint barely misses
    // it (the footprint's bounds, a box, may reach the joint).
    CHECK(insideBrick > pixels / 5);
    CHECK(onePixelRays > insideBrick / 2);
}

TEST_CASE("With the pattern filter, ASOS shades a pattern's share of a pixel with one ray", "[asos][pattern-filter]") {
    // Checker cells of 1.5 pixels and bricks of 3 x 1.5 pixels, turned about
    // z: most pixels hold an edge, many several. Each is one ray, within the
    // point count's accuracy of its exact share.
    Pigment checker;
    checker.kind = Pigment::Kind::Checker;
    checker.worldFromPattern = Transform::rotateDegrees({0.0, 0.0, 23.0}) * Transform::scale(Vec3(1.5));
    Pigment brick;
    brick.kind = Pigment::Kind::Brick;
    brick.brickSize = {4.0, 2.0, 4.0};
    brick.mortar = 0.5;
    brick.worldFromPattern = Transform::translate({0.3, 0.2, 0.0}) *
                             Transform::rotateDegrees({0.0, 0.0, -31.0}) * Transform::scale(Vec3(0.75));
    for (Pigment pigment : {checker, brick}) {
        Setup s(patternPlane(pigment), 16, 16, AsosSettings{}, 0, false, true);
        int between = 0;
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                const double exact = pixelShare(pigment, x, y);
                between += exact > 0.02 && exact < 0.98;
                const AsosPixelReport r = s.pixel(x, y);
                INFO("pixel " << x << ", " << y << ": exact " << exact);
                CHECK(r.result.rays == 1);
                CHECK(r.result.color.x == Approx(exact).margin(0.01));
            }
        CHECK(between > 100);
    }
}

TEST_CASE("Without pattern edges a pixel on one object costs one ray, as in the paper", "[asos]") {
    Texture checker = coverageTexture(0.0);
    checker.pigment.kind = Pigment::Kind::Checker;
    checker.pigment.color2.rgb = Vec3(1.0);
    checker.pigment.worldFromPattern = Transform::scale(Vec3(0.3));
    SceneDescription d;
    d.objects.push_back(makeObject(PlaneShape{{0, 0, -1}, 0.0}, checker));
    d.camera = orthoCamera(8, 8);
    const auto scene = buildScene(d);
    const RayTracer tracer(*scene);
    const CameraModel camera(d.camera, 8, 8);
    const AsosTracer paperOnly(tracer, camera, AsosSettings{}, 0, false);
    const AsosTracer withEdges(tracer, camera, AsosSettings{}, 0, true);
    AsosScratch scratch;
    RenderCounters counters;
    CHECK(paperOnly.tracePixel(3, 3, scratch, counters).rays == 1);
    CHECK(withEdges.tracePixel(3, 3, scratch, counters).rays > 1);
}
