// Spotlights, cylinder lights and parallel lights (lights/light_beam.hpp):
// POV-Ray's factors (lightsource.cpp, Attenuate_Light) at known points, and
// where a parallel light stands for a point.
#include <catch2/catch.hpp>

#include <cmath>

#include "asos/lights/light_beam.hpp"

using namespace asos;

namespace {

double cosDeg(double degrees) { return std::cos(degrees * 3.14159265358979323846 / 180.0); }

}  // namespace

TEST_CASE("POV-Ray's cubic_spline is a smooth step from low to high", "[lights][spotlight]") {
    CHECK(povCubicSpline(0.2, 0.6, 0.1) == 0.0);
    CHECK(povCubicSpline(0.2, 0.6, 0.6) == 1.0);
    CHECK(povCubicSpline(0.2, 0.6, 0.9) == 1.0);
    CHECK(povCubicSpline(0.2, 0.6, 0.4) == Approx(0.5));
    CHECK(povCubicSpline(0.0, 1.0, 0.25) == Approx(0.15625));  // (3 - 0.5) / 16
}

TEST_CASE("A spotlight's factor: 1 inside radius, 0 beyond falloff, the step between", "[lights][spotlight]") {
    const double r = cosDeg(30.0), f = cosDeg(45.0);  // POV-Ray's defaults
    CHECK(spotlightFactor(cosDeg(0.0), r, f, 0.0) == 1.0);
    CHECK(spotlightFactor(cosDeg(29.9), r, f, 0.0) == 1.0);
    CHECK(spotlightFactor(cosDeg(45.1), r, f, 0.0) == 0.0);
    CHECK(spotlightFactor(cosDeg(120.0), r, f, 0.0) == 0.0);  // behind the light
    // The step is in the cosine: half way between the cosines gives 1/2...
    CHECK(spotlightFactor(0.5 * (r + f), r, f, 0.0) == Approx(0.5));
    // ... and half way between the angles, t = 0.54271, (3 - 2t) t^2.
    CHECK(spotlightFactor(cosDeg(37.5), r, f, 0.0) == Approx(0.563909).epsilon(1e-5));
    // tightness: cos^t inside the radius too.
    CHECK(spotlightFactor(cosDeg(20.0), r, f, 10.0) == Approx(std::pow(cosDeg(20.0), 10.0)));
    CHECK(spotlightFactor(cosDeg(20.0), r, f, 10.0) == Approx(0.53686).epsilon(1e-4));
    CHECK(spotlightFactor(cosDeg(37.5), r, f, 10.0) ==
          Approx(std::pow(cosDeg(37.5), 10.0) * 0.563909).epsilon(1e-5));
    // A radius of 90 degrees or more (cosine <= 0): no step, only tightness.
    CHECK(spotlightFactor(cosDeg(80.0), cosDeg(100.0), cosDeg(120.0), 0.0) == 1.0);
}

TEST_CASE("A cylinder light's factor by the distance from its axis", "[lights][spotlight]") {
    // POV-Ray's defaults: radius 0.75, falloff 1, tightness 0.
    CHECK(cylinderFactor(0.0, 0.75, 1.0, 0.0) == 1.0);
    CHECK(cylinderFactor(0.7, 0.75, 1.0, 0.0) == 1.0);
    CHECK(cylinderFactor(1.0, 0.75, 1.0, 0.0) == 0.0);
    CHECK(cylinderFactor(1.2, 0.75, 1.0, 0.0) == 0.0);
    // Half way between radius and falloff: 1 - d / falloff = 0.125 of 0.25.
    CHECK(cylinderFactor(0.875, 0.75, 1.0, 0.0) == Approx(0.5));
    // tightness: (1 - d / falloff)^t.
    CHECK(cylinderFactor(0.5, 0.75, 1.0, 2.0) == Approx(0.25));
}

TEST_CASE("A light's beam: spotlight, cylinder and parallel lights", "[lights][spotlight]") {
    Light spot;
    spot.position = {0, 10, 0};
    spot.type = LightType::Spot;
    spot.pointAt = {0, 0, 0};
    spot.radius = 30;
    spot.falloff = 45;
    const LightBeam beam = LightBeam::of(spot);
    CHECK_FALSE(beam.parallel);
    CHECK(beam.axis == Vec3(0, -1, 0));
    const auto at = [&](const LightBeam& b, const Vec3& point) {
        return b.factor(point, glm::normalize(b.sourceFor(point).value().position - point));
    };
    CHECK(at(beam, {1, 0, 0}) == 1.0);                                   // 5.7 degrees
    CHECK(at(beam, {20, 0, 0}) == 0.0);                                  // 63 degrees
    CHECK(at(beam, {0, 20, 0}) == 0.0);                                  // behind
    const double x = 10.0 * std::tan(37.5 * 3.14159265358979323846 / 180.0);
    CHECK(at(beam, {x, 0, 0}) == Approx(0.563909).epsilon(1e-5));

    Light cylinder = spot;
    cylinder.type = LightType::Cylinder;
    cylinder.radius = 0.75;
    cylinder.falloff = 1.0;
    const LightBeam tube = LightBeam::of(cylinder);
    CHECK(tube.parallel);
    // Lit straight down the axis, from the plane through the position.
    CHECK(tube.sourceFor({0.875, 2, 0}).value().position == Vec3(0.875, 10, 0));
    CHECK_FALSE(tube.sourceFor({0.5, 11, 0}));  // behind the light
    CHECK(at(tube, {0.5, -50, 0}) == 1.0);
    CHECK(at(tube, {0.875, 2, 0}) == Approx(0.5));
    CHECK(at(tube, {0, 0.8, 1.5}) == 0.0);

    // A parallel spotlight is not narrowed: its light arrives along the axis.
    Light parallel = spot;
    parallel.parallel = true;
    const LightBeam flat = LightBeam::of(parallel);
    CHECK(flat.sourceFor({30, 0, 0}).value().position == Vec3(30, 10, 0));
    CHECK(at(flat, {30, 0, 0}) == 1.0);
    CHECK_FALSE(flat.sourceFor({30, 12, 0}));  // behind the plane: not narrowed to nothing, unlit
    CHECK(lightSourceFor(spot, {30, 0, 0}).value().position == spot.position);

    // A parallel point light lights points behind its plane too, unshadowed
    // (POV-Ray's shadow ray has no length there).
    Light sun;
    sun.position = {0, 1, 0};
    sun.parallel = true;
    sun.pointAt = {0, 0, 0};
    const auto behind = lightSourceFor(sun, {0, 4, 0});
    REQUIRE(behind);
    CHECK(behind->unshadowed);
    CHECK(behind->position == Vec3(0, 5, 0));
    const auto before = lightSourceFor(sun, {3, -2, 0});
    REQUIRE(before);
    CHECK_FALSE(before->unshadowed);
    CHECK(before->position == Vec3(3, 1, 0));
}
