// Shadow beams, shadow pyrays and plain shadow rays end at the light
// (docs/lights.md, "Where a beam ends"): an object just beyond a light never
// shadows it and costs no shadow ray, one just in front of it always
// shadows it, under every light form and method; and an object beside a
// marginal piece of a beam, within its cone, costs its point samples no ray.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "asos/lang/interpreter.hpp"
#include "asos/render/area_light.hpp"
#include "asos/render/renderer.hpp"
#include "asos/scene/pov_tolerances.hpp"
#include "asos/shapes/primitive.hpp"

using namespace asos;

namespace {

// A light 3 above the ground, as written in a scene, and its extent along y.
struct LightCase {
    const char* name;
    const char* text;
    double bottom, top;
};
const LightCase kLights[] = {
    {"point", "light_source { <0, 3, 0>, 1 }", 3.0, 3.0},
    {"rectangular", "light_source { <0, 3, 0>, 1 area_light <1, 0, 0>, <0, 0, 1>, 4, 4 }", 3.0, 3.0},
    {"linear", "light_source { <0, 3, 0>, 1 area_light <1.5, 0, 0>, <0, 0, 0>, 8, 1 }", 3.0, 3.0},
    {"spherical", "light_source { <0, 3, 0>, 1 area_light <1, 0, 0>, <0, 0, 1>, 4, 4 circular orient }", 2.5,
     3.5},
};

// The ground under `light` (within 2 of the point below it, which sees it
// at least 50 degrees above the horizon), with `extra` objects.
SceneDescription groundUnder(const std::string& light, const std::string& extra) {
    const std::string text = "global_settings { assumed_gamma 1.0 }\n"
                             "camera { location <0, 2, -0.5> look_at <0, 0, 0> angle 60 }\n"
                             "plane { y, 0 pigment { color rgb 1 } finish { ambient 0.1 diffuse 0.7 } }\n" +
                             light + "\n" + extra + "\n";
    Diagnostics diagnostics;
    std::optional<SceneDescription> d = lang::interpretText(text, "beam_end.pov", {}, diagnostics);
    REQUIRE(d);
    return std::move(*d);
}

// A slab of the given heights, far wider than the light and the view.
std::string slab(double y0, double y1) {
    return "box { <-30, " + std::to_string(y0) + ", -30>, <30, " + std::to_string(y1) + ", 30> }";
}

RenderOutput renderWith(const SceneDescription& d, RenderMethod method, std::optional<LightMethod> lights) {
    RenderSettings s;
    s.width = 24;
    s.height = 18;
    s.method = method;
    s.lightMethod = lights;
    s.threads = 1;
    Diagnostics diagnostics;
    std::optional<RenderOutput> out = render(d, s, diagnostics);
    REQUIRE(out);
    return std::move(*out);
}

bool sameImage(const Image& a, const Image& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c)
                if (a.at(x, y, c) != b.at(x, y, c)) return false;
    return true;
}

struct MethodCase {
    const char* name;
    RenderMethod method;
    std::optional<LightMethod> lights;
};
const MethodCase kMethods[] = {
    {"asos", RenderMethod::Asos, std::nullopt},                // ASOS beams, point-light shadow pyrays
    {"asos, grid lights", RenderMethod::Asos, LightMethod::Grid},  // plain shadow rays to the grid's points
    {"single", RenderMethod::Single, std::nullopt},            // plain shadow rays only
};

}  // namespace

TEST_CASE("Beams end at the light: an occluder just beyond it never shadows, one just in front always does",
          "[lights][shadow]") {
    for (const LightCase& light : kLights)
        for (const MethodCase& m : kMethods) {
            INFO(light.name << " light, " << m.name);
            const RenderOutput open = renderWith(groundUnder(light.text, ""), m.method, m.lights);
            // Beyond: slabs flush with the light's far side and a tenth of a
            // millimetre past it, a ceiling plane, a ceiling tilted across
            // the light's plane far to the side.
            const double top = light.top;
            const std::string tilted = "plane { <0.1, 1, 0>, " + std::to_string((top + 0.2) / std::sqrt(1.01)) + " }";
            for (const std::string& beyond : {slab(top, top + 0.3), slab(top + 1e-4, top + 0.05),
                                              "plane { y, " + std::to_string(top + 1e-4) + " }", tilted}) {
                INFO("beyond: " << beyond);
                const RenderOutput out = renderWith(groundUnder(light.text, beyond), m.method, m.lights);
                CHECK(sameImage(out.color, open.color));
                CHECK(out.stats.counters.shadowRays == open.stats.counters.shadowRays);
            }
            // Just in front: the ground receives ambient light only, as
            // without any light.
            const RenderOutput dark = renderWith(groundUnder("", ""), m.method, m.lights);
            const RenderOutput front =
                renderWith(groundUnder(light.text, slab(light.bottom - 0.02, light.bottom - 0.01)), m.method, m.lights);
            CHECK(sameImage(front.color, dark.color));
            CHECK_FALSE(sameImage(open.color, dark.color));
        }
}

TEST_CASE("A ceiling and a fitting just above an area light cost no shadow ray", "[lights][shadow]") {
    // The room of examples/bench/room.pov in small: the ground everywhere in
    // view sees the whole light.
    for (const LightCase& light : kLights) {
        if (std::string(light.name) == "point") continue;
        INFO(light.name << " light");
        const std::string above = "plane { y, " + std::to_string(light.top + 0.1) + " }\n" +
                                  slab(light.top + 0.05, light.top + 0.1);
        const RenderOutput out = renderWith(groundUnder(light.text, above), RenderMethod::Asos, std::nullopt);
        CHECK(out.stats.counters.shadowRays == 0);
    }
}

TEST_CASE("An object beside a marginal piece of a beam, within its cone, costs its point samples no ray",
          "[lights][shadow]") {
    // An oblong light (2 x 1): the cone about each of its quarters holds
    // twice the quarter's area. A slab's edge crosses the light's two right
    // quarters, which are point-sampled; a small ball lies in the cone of
    // the far right quarter, outside its pyramid (and the light's).
    const std::string light = "light_source { <0, 3, 0>, 1 area_light <2, 0, 0>, <0, 0, 1>, 8, 8 }";
    const std::string edge = "box { <-30, 1.5, -30>, <0.25, 1.6, 30> }";
    const std::string ball = "sphere { <0.5, 2.9, 0.7>, 0.04 }";
    const SceneDescription without = groundUnder(light, edge), with = groundUnder(light, edge + "\n" + ball);

    // The ball is in the far right quarter's cone from the point below the
    // light's centre, and outside its pyramid.
    LightSetup beams;
    beams.method = LightMethod::Asos;
    const SceneLights lights(with, beams);
    const RectangleLight& rect = std::get<RectangleLight>(lights[0].form);
    const Vec3 point(0.0, 0.0, 0.0);
    const auto beam = rect.beamFrom(point, kPovShadowTolerance);
    REQUIRE(beam);
    LightPiece quarters[4];
    beam->split(beam->root(), quarters);
    const Primitive ballShape = Primitive::make(SphereShape{{0.5, 2.9, 0.7}, 0.04}, {});
    CHECK(ballShape.classify(quarters[3].cone).coverage != Coverage::Miss);
    CHECK(quarters[3].b1 == 1.0);
    CHECK(rect.corner.z + rect.edgeB.z * 2.9 / 3.0 < 0.7 - 0.04);

    const auto query = [&beams](const SceneDescription& d, RenderCounters& counters) {
        Diagnostics diagnostics;
        const std::unique_ptr<Scene> scene = Scene::build(d, diagnostics);
        REQUIRE(scene);
        const SceneLights sceneLights(d, beams);
        AreaLightQuery q;
        q.point = Vec3(0.0);
        q.normal = {0, 1, 0};
        q.shadedObject = 0;
        AreaLightScratch scratch;
        return diffuseIrradiance(areaLightSamples(*scene, sceneLights, q, scratch, counters), q.normal).x;
    };
    RenderCounters a, b;
    const double litWithout = query(without, a);
    const double litWith = query(with, b);
    // The ball is classified against the quarters, then left out of their
    // point samples: the same rays, the same ray tests, the same light.
    CHECK(b.coneTests > a.coneTests + 1);
    CHECK(a.shadowRays > 0);
    CHECK(b.shadowRays == a.shadowRays);
    CHECK(b.rayTests == a.rayTests);
    CHECK(litWith == litWithout);
}
