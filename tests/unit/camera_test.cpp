#include <catch2/catch.hpp>

#include <stdexcept>

#include "asos/render/camera.hpp"

using namespace asos;

namespace {
bool near(const Vec3& a, const Vec3& b, double tol = 1e-12) { return glm::length(a - b) <= tol; }

Camera povDefaultCamera() {
    Camera c;  // POV-Ray's defaults: location 0, direction z, right 1.33 x, up y
    return c;
}
}  // namespace

TEST_CASE("Perspective rays follow POV-Ray's pixel-centre mapping", "[camera]") {
    const CameraModel cam(povDefaultCamera(), 200, 100);
    // The image centre looks straight down direction.
    CHECK(near(cam.ray(100, 50).dir, {0, 0, 1}));
    CHECK(near(cam.ray(100, 50).origin, {0, 0, 0}));
    // The image corners reach the ends of right and up whatever the aspect
    // ratio: top-left is -right/2 + up/2.
    CHECK(near(cam.ray(0, 0).dir, glm::normalize(Vec3(-0.665, 0.5, 1))));
    CHECK(near(cam.ray(200, 100).dir, glm::normalize(Vec3(0.665, -0.5, 1))));
    // Pixel (0, 0)'s centre is half a pixel in from the corner; y grows downwards.
    const Vec3 expected = glm::normalize(Vec3(1.33 * (0.5 / 200 - 0.5), 0.5 - 0.5 / 100, 1.0));
    CHECK(near(cam.pixelCenterRay(0, 0).dir, expected));
    CHECK(cam.pixelCenterRay(0, 99).dir.y < 0.0);
    CHECK(cam.pixelCenterRay(199, 0).dir.x > 0.0);
    CHECK(glm::length(cam.ray(13.7, 81.2).dir) == Approx(1.0).epsilon(1e-15));
}

TEST_CASE("Orthographic rays are parallel and offset across the image plane", "[camera]") {
    Camera c;
    c.projection = Camera::Projection::Orthographic;
    c.location = {1, 2, -10};
    c.direction = {0, 0, 2};
    c.right = {4, 0, 0};
    c.up = {0, 3, 0};
    const CameraModel cam(c, 40, 30);
    const Ray centre = cam.ray(20, 15);
    CHECK(near(centre.origin, {1, 2, -10}));
    CHECK(near(centre.dir, {0, 0, 1}));
    const Ray topLeft = cam.ray(0, 0);
    CHECK(near(topLeft.origin, {-1, 3.5, -10}));
    CHECK(near(topLeft.dir, {0, 0, 1}));
    CHECK(near(cam.pixelCenterRay(39, 29).origin, {1 + 4 * (39.5 / 40 - 0.5), 2 + 3 * (0.5 - 29.5 / 30), -10}));
}

TEST_CASE("A look_at frame with a left-handed right vector maps like POV-Ray", "[camera]") {
    // location <0.3,1.2,-5> look_at <0.5,0.2,0> right x*1.6 angle 50, sky y:
    // POV-Ray's final vectors (direction scaled by 0.5*|right|/tan(angle/2)).
    Camera c;
    c.location = {0.3, 1.2, -5};
    const Vec3 d = glm::normalize(Vec3(0.5, 0.2, 0) - c.location);
    const Vec3 r = glm::normalize(glm::cross(Vec3(0, 1, 0), d));
    c.direction = d * (0.8 / std::tan(25.0 * kPi / 180.0));
    c.right = r * 1.6;
    c.up = glm::cross(d, r);
    const CameraModel cam(c, 160, 90);
    // Image positions of small spheres measured from `povray +W160 +H90`
    // (intensity centroids, see docs/rendering.md); a centroid differs from
    // the projected centre by a few hundredths of a pixel.
    struct Case { Vec3 p; double x, y; };
    const Case cases[] = {{{0, 0, 0}, 63.281, 51.034},
                          {{1.5, 0.8, 0.5}, 110.467, 25.564},
                          {{-1.2, -0.6, -1}, 12.450, 81.427},
                          {{0.9, -0.9, 1.5}, 88.572, 62.782}};
    for (const Case& k : cases) {
        const auto xy = cam.project(k.p);
        REQUIRE(xy);
        CHECK(xy->x == Approx(k.x).margin(0.05));
        CHECK(xy->y == Approx(k.y).margin(0.05));
    }
}

TEST_CASE("project inverts ray for both projections", "[camera]") {
    Camera c;
    c.location = {2, -1, 3};
    c.direction = {0.2, 0.1, 1.5};
    c.right = {1.2, 0.3, 0};
    c.up = {0, 1, -0.1};
    for (auto projection : {Camera::Projection::Perspective, Camera::Projection::Orthographic}) {
        c.projection = projection;
        const CameraModel cam(c, 64, 48);
        for (double x : {0.0, 3.25, 31.9, 64.0})
            for (double y : {0.0, 17.5, 48.0}) {
                const Ray r = cam.ray(x, y);
                const auto xy = cam.project(r.at(7.5));
                REQUIRE(xy);
                CHECK(xy->x == Approx(x).margin(1e-9));
                CHECK(xy->y == Approx(y).margin(1e-9));
                CHECK(near(cam.imagePlanePoint(x, y) - c.location,
                           projection == Camera::Projection::Perspective
                               ? r.dir * glm::length(cam.imagePlanePoint(x, y) - c.location)
                               : cam.imagePlanePoint(x, y) - c.location,
                           1e-12));
            }
        CHECK_FALSE(cam.project(c.location - c.direction));
    }
}

TEST_CASE("Degenerate cameras and image sizes are rejected", "[camera]") {
    Camera c;
    CHECK_THROWS_AS(CameraModel(c, 0, 10), std::invalid_argument);
    CHECK_THROWS_AS(CameraModel(c, 10, -1), std::invalid_argument);
    c.up = {0, 0, 0};
    CHECK_THROWS_AS(CameraModel(c, 10, 10), std::invalid_argument);
    c.up = {0, 0, 1};  // parallel to direction
    CHECK_THROWS_AS(CameraModel(c, 10, 10), std::invalid_argument);
}
