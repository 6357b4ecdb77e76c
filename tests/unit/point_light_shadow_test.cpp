// Known answers for antialiased point light shadows (paper: "Antialiased
// Point Light Sources"): the lit fraction of a footprint that a straight
// shadow edge crosses is within the light's EPS of the exact fraction.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "asos/render/point_light_shadow.hpp"
#include "render_scenes.hpp"

using namespace asos;
using namespace asos::testing;

namespace {

// A camera looking straight down at the floor y = 0: image point (u, v) sees
// floor point (x, z) = (u * pixel, -v * pixel).
Camera topDownCamera(int width, int height, double pixel) {
    Camera c;
    c.projection = Camera::Projection::Orthographic;
    c.location = {0.5 * width * pixel, 10.0, -0.5 * height * pixel};
    c.direction = {0.0, -1.0, 0.0};
    c.right = {width * pixel, 0.0, 0.0};
    c.up = {0.0, 0.0, height * pixel};
    return c;
}

struct ShadowSetup {
    SceneDescription d;
    std::unique_ptr<Scene> scene;
    std::unique_ptr<CameraModel> camera;
    ShadowScratch scratch;
    static constexpr double kPixel = 0.05;

    // A floor, and a slab above it whose edge (object x = 0, y = 1) casts a
    // straight shadow edge; the slab is turned by `degrees` about y.
    explicit ShadowSetup(double degrees, const Vec3& shift) {
        d.camera = topDownCamera(64, 64, kPixel);
        d.objects.push_back(makeObject(PlaneShape{{0, 1, 0}, 0.0}, litTexture(Vec3(1.0))));
        d.objects.push_back(makeObject(BoxShape{{-50, 1.0, -50}, {0.0, 1.2, 50}}, litTexture(Vec3(1.0)),
                                       Transform::translate(shift) *
                                           Transform::rotateDegrees({0.0, degrees, 0.0})));
        scene = buildScene(d);
        camera = std::make_unique<CameraModel>(d.camera, 64, 64);
    }

    // A light one unit beyond the slab's edge, five above it: the edge it
    // sees the slab's outline by is the lower one, object y = 1.
    Vec3 light(double along = 0.0) const {
        return d.objects[1].worldFromObject.point({1.0, 6.0, along});
    }

    double litFraction(const ImageSquare& square, const Vec3& light, const AsosSettings& settings,
                       RenderCounters& counters) {
        const Vec3 centre = camera->ray(square.uMid(), square.vMid()).at(10.0);
        const Footprint footprint(*camera, square, centre, {0, 1, 0}, 10.0);
        PointShadowQuery q;
        q.lightPosition = light;
        q.settings = settings;
        q.shadedObject = 0;
        return pointLightLitFraction(*scene, footprint, q, scratch, counters);
    }

    // The exact lit part of the image square: the slab's edge projected from
    // the light onto the floor is a line; the side away from the slab is lit.
    double exactLit(const ImageSquare& sq, const Vec3& light) const {
        const Transform& t = d.objects[1].worldFromObject;
        auto onFloor = [&](const Vec3& p) {
            const Vec3 q = t.point(p);
            const double s = light.y / (light.y - q.y);
            return Vec2(light.x + s * (q.x - light.x), light.z + s * (q.z - light.z));
        };
        const Vec2 a = onFloor({0.0, 1.0, -10.0}), b = onFloor({0.0, 1.0, 10.0});
        // The line through a and b in floor (x, z); image u = x / pixel, v = -z / pixel.
        Vec2 n(b.y - a.y, a.x - b.x);
        double c = glm::dot(n, a);
        // Orient so that the slab's footprint (object x < 0) is on the > side.
        const Vec3 inside = t.point({-5.0, 1.0, 0.0});
        if (n.x * inside.x + n.y * inside.z < c) {
            n = -n;
            c = -c;
        }
        const double area = halfPlaneArea(sq.u0, sq.v0, sq.u1, sq.v1, n.x * kPixel, -n.y * kPixel, c);
        return area / ((sq.u1 - sq.u0) * (sq.v1 - sq.v0));
    }
};

}  // namespace

TEST_CASE("A half-shadowed footprint is lit within EPS of the exact fraction", "[shadow]") {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> angle(-60.0, 60.0), shift(-0.4, 0.4);
    const AsosSettings settings{1.0 / 64.0, 6, false};
    int partial = 0;
    for (int i = 0; i < 60; ++i) {
        ShadowSetup s(angle(rng), {1.6 + shift(rng), 0.0, -1.6 + shift(rng)});
        const Vec3 light = s.light(shift(rng));
        // Pixels along the middle row: some lit, some dark, some crossed.
        for (int x = 20; x < 44; x += 3) {
            const ImageSquare sq{double(x), 32.0, x + 1.0, 33.0};
            RenderCounters counters;
            const double lit = s.litFraction(sq, light, settings, counters);
            const double exact = s.exactLit(sq, light);
            INFO("case " << i << ", pixel " << x << ": exact " << exact);
            CHECK(std::abs(lit - exact) <= settings.eps + 1e-9);
            if (exact > 0.05 && exact < 0.95) {
                ++partial;
                CHECK(counters.shadowPyraysByLevel[1] > 0);
            }
        }
    }
    CHECK(partial > 20);
}

TEST_CASE("Footprints wholly lit or wholly shadowed cost no shadow ray", "[shadow]") {
    ShadowSetup s(0.0, {1.6, 0.0, -1.6});
    const Vec3 light = s.light();
    const AsosSettings settings{1.0 / 64.0, 4, false};
    // Pixel 50 lies far on the lit side, pixel 5 under the slab.
    RenderCounters lit, dark;
    CHECK(s.litFraction({50, 32, 51, 33}, light, settings, lit) == 1.0);
    CHECK(s.litFraction({5, 32, 6, 33}, light, settings, dark) == 0.0);
    CHECK(lit.shadowRays == 0);
    CHECK(dark.shadowRays == 0);
    CHECK(lit.shadowPyraysByLevel[0] == 1);
}

TEST_CASE("A shadow pyray that starts at MAX is one point sample", "[shadow]") {
    ShadowSetup s(20.0, {1.6, 0.0, -1.6});
    const Vec3 light = s.light();
    const Vec3 centre = s.camera->ray(28.5, 32.5).at(10.0);
    const Footprint footprint(*s.camera, {28, 32, 29, 33}, centre, {0, 1, 0}, 10.0);
    PointShadowQuery q;
    q.lightPosition = light;
    q.settings = {1.0 / 64.0, 2, false};
    q.level = 2;
    RenderCounters counters;
    const double lit = pointLightLitFraction(*s.scene, footprint, q, s.scratch, counters);
    CHECK((lit == 0.0 || lit == 1.0));
    CHECK(counters.shadowRays == 1);
    CHECK(counters.coneTests == 0);
}

TEST_CASE("Footprints on the tangent plane, or the cross-section when grazing", "[shadow]") {
    Camera c = topDownCamera(8, 8, 1.0);
    const CameraModel camera(c, 8, 8);
    const Vec3 p = camera.ray(3.5, 3.5).at(10.0);
    // Facing the camera: the footprint is the pixel's square on the floor.
    const Footprint flat(camera, {3, 3, 4, 4}, p, {0, 1, 0}, 10.0);
    CHECK(flat.onTangentPlane());
    const Vec3 corner = flat.at(3.0, 3.0);
    CHECK(corner.x == Approx(3.0));
    CHECK(corner.z == Approx(-3.0));
    CHECK(corner.y == Approx(0.0).margin(1e-12));
    // Seen edge on, the plane gives no footprint: the cross-section at the
    // hit's depth stands in.
    const Footprint grazing(camera, {3, 3, 4, 4}, p, glm::normalize(Vec3(1, 1e-3, 0)), 10.0);
    CHECK_FALSE(grazing.onTangentPlane());
    CHECK(grazing.at(3.0, 3.0).y == Approx(0.0).margin(1e-12));
    CHECK(grazing.at(3.0, 3.0).x == Approx(3.0));
}
