// The light forms (lights/light_model.hpp): which area_light is a rectangle,
// a segment, a sphere or a point, the grid counts and --light-samples, and
// what the renderer refuses or warns about.
#include <catch2/catch.hpp>

#include "asos/lights/light_model.hpp"
#include "asos/render/scene_lights.hpp"

using namespace asos;

namespace {

Light withArea(const Vec3& axis1, const Vec3& axis2, int n1, int n2) {
    Light l;
    l.position = {1, 5, 2};
    l.color = {0.5, 1.0, 2.0};
    AreaLight a;
    a.axis1 = axis1;
    a.axis2 = axis2;
    a.size1 = n1;
    a.size2 = n2;
    l.area = a;
    return l;
}

}  // namespace

TEST_CASE("area_light forms: rectangle, segment, sphere, point", "[lights]") {
    const AsosSettings scene;
    const Vec3 x(1, 0, 0), z(0, 0, 1);

    const LightModel rect = makeLightModel(withArea(2.0 * x, 3.0 * z, 4, 5), scene);
    REQUIRE(std::holds_alternative<RectangleLight>(rect.form));
    const RectangleLight& r = std::get<RectangleLight>(rect.form);
    CHECK(r.corner == Vec3(0, 5, 0.5));
    CHECK(r.edgeA == 2.0 * x);
    CHECK(r.edgeB == 3.0 * z);
    CHECK(rect.size() == 6.0);
    CHECK(rect.intensity() == Vec3(0.5, 1.0, 2.0) / 6.0);
    CHECK((rect.count1 == 4 && rect.count2 == 5));
    CHECK_FALSE(rect.adaptive);

    // A zero axis, or a count of 1: a segment along the other axis.
    for (const Light& l : {withArea(2.0 * x, Vec3(0.0), 8, 3), withArea(2.0 * x, z, 8, 1)}) {
        const LightModel seg = makeLightModel(l, scene);
        REQUIRE(std::holds_alternative<SegmentLight>(seg.form));
        CHECK(std::get<SegmentLight>(seg.form).start == Vec3(0, 5, 2));
        CHECK(std::get<SegmentLight>(seg.form).end == Vec3(2, 5, 2));
        CHECK(seg.size() == 2.0);
        CHECK((seg.count1 == 8 && seg.count2 == 1));
    }
    const LightModel along2 = makeLightModel(withArea(x, 4.0 * z, 1, 6), scene);
    REQUIRE(std::holds_alternative<SegmentLight>(along2.form));
    CHECK(std::get<SegmentLight>(along2.form).end - std::get<SegmentLight>(along2.form).start == 4.0 * z);
    CHECK(along2.count1 == 6);

    // 1 x 1, or both axes zero: a point light, as in POV-Ray.
    CHECK_FALSE(makeLightModel(withArea(x, z, 1, 1), scene).isArea());
    CHECK_FALSE(makeLightModel(withArea(Vec3(0.0), Vec3(0.0), 4, 4), scene).isArea());
    Light plain;
    CHECK(std::holds_alternative<PointLight>(makeLightModel(plain, scene).form));

    // circular orient: POV-Ray's disc of half the first axis's length,
    // facing the point; with the paper's emitter a sphere of that radius.
    Light sphere = withArea(3.0 * x, 3.0 * z, 6, 6);
    sphere.area->circular = sphere.area->orient = true;
    sphere.area->adaptive = 1;
    sphere.area->jitter = true;
    const LightModel disc = makeLightModel(sphere, scene);
    REQUIRE(std::holds_alternative<OrientedDiscLight>(disc.form));
    CHECK(std::get<OrientedDiscLight>(disc.form).radius == 1.5);
    CHECK(std::get<OrientedDiscLight>(disc.form).centre == Vec3(1, 5, 2));
    CHECK(disc.emitter == LightEmitter::Povray);
    sphere.asos.emitter = LightEmitter::Panel;
    const LightModel ball = makeLightModel(sphere, scene);
    CHECK(ball.emitter == LightEmitter::Panel);
    REQUIRE(std::holds_alternative<SphereLight>(ball.form));
    CHECK(std::get<SphereLight>(ball.form).radius == 1.5);
    CHECK(std::get<SphereLight>(ball.form).centre == Vec3(1, 5, 2));
    CHECK(ball.size() == Approx(kPi * 2.25));
    CHECK(ball.adaptive == 1);
    CHECK(ball.jitter);
    CHECK(ball.position == Vec3(1, 5, 2));

    // --light-samples replaces the counts; the light's asos block refines the scene's.
    Light tuned = withArea(2.0 * x, 3.0 * z, 4, 5);
    tuned.asos.eps = 0.25;
    const LightModel sampled = makeLightModel(tuned, AsosSettings{0.01, 6, true}, 12);
    CHECK((sampled.count1 == 12 && sampled.count2 == 12));
    CHECK(sampled.asos == AsosSettings{0.25, 6, true});
    CHECK(makeLightModel(withArea(2.0 * x, Vec3(0.0), 8, 3), scene, 12).count1 == 12);

    // POV-Ray's fade and area_illumination travel with the model.
    Light faded = withArea(2.0 * x, 3.0 * z, 4, 5);
    faded.fadeDistance = 2.0;
    faded.fadePower = 2.0;
    faded.areaIllumination = true;
    const LightModel fading = makeLightModel(faded, scene);
    CHECK(fading.areaIllumination);
    CHECK(fading.fade(4.0) == Approx(2.0 / 5.0));
    CHECK(makeLightModel(withArea(2.0 * x, 3.0 * z, 4, 5), scene).fade(4.0) == 1.0);
}

TEST_CASE("Light forms asos refuses or warns about", "[lights]") {
    const Vec3 x(1, 0, 0), z(0, 0, 1);
    auto check = [](const Light& l) {
        Diagnostics d;
        const bool ok = checkLight(l, d);
        return std::make_pair(ok, d.all());
    };
    CHECK(check(withArea(x, z, 4, 4)).first);
    CHECK(check(withArea(x, z, 4, 4)).second.empty());

    Light disc = withArea(x, z, 4, 4);
    disc.area->circular = true;
    disc.loc.line = 9;
    auto [discOk, discMessages] = check(disc);
    CHECK_FALSE(discOk);
    REQUIRE(discMessages.size() == 1);
    CHECK(discMessages[0].loc.line == 9);
    CHECK_THAT(discMessages[0].message, Catch::Contains("circular") && Catch::Contains("orient"));

    Light oriented = withArea(x, 2.0 * z, 4, 4);
    oriented.area->orient = true;
    auto [orientOk, orientMessages] = check(oriented);
    CHECK(orientOk);
    REQUIRE(orientMessages.size() == 2);  // not circular; unequal axes
    CHECK(orientMessages[0].severity == Severity::Warning);
    CHECK(orientMessages[1].severity == Severity::Warning);
    CHECK(std::get<OrientedDiscLight>(makeLightModel(oriented, AsosSettings{}).form).radius == 0.5);

    // Counts: unequal ones warn (as POV-Ray does); a count of 1 along one
    // axis is refused (POV-Ray turns a line toward each point); 1 x 1 is a
    // point light, with POV-Ray's warning.
    Light uneven = withArea(x, z, 4, 6);
    uneven.area->circular = uneven.area->orient = true;
    auto [unevenOk, unevenMessages] = check(uneven);
    CHECK(unevenOk);
    REQUIRE(unevenMessages.size() == 1);
    CHECK_THAT(unevenMessages[0].message, Catch::Contains("counts"));
    Light line = withArea(x, z, 4, 1);
    line.area->circular = line.area->orient = true;
    CHECK_FALSE(check(line).first);
    Light single = withArea(x, z, 1, 1);
    single.area->circular = single.area->orient = true;
    auto [singleOk, singleMessages] = check(single);
    CHECK(singleOk);
    REQUIRE(singleMessages.size() == 1);
    CHECK(singleMessages[0].severity == Severity::Warning);
    CHECK_FALSE(makeLightModel(single, AsosSettings{}).isArea());
    // circular without orient and a count of 1: POV-Ray drops circular.
    Light flatLine = withArea(x, z, 4, 1);
    flatLine.area->circular = true;
    auto [flatOk, flatMessages] = check(flatLine);
    CHECK(flatOk);
    REQUIRE(flatMessages.size() == 1);
    CHECK(flatMessages[0].severity == Severity::Warning);
    CHECK(std::holds_alternative<SegmentLight>(makeLightModel(flatLine, AsosSettings{}).form));

    CHECK_FALSE(check(withArea(x, 2.0 * x, 4, 4)).first);  // parallel axes
    Light negative = withArea(x, z, 4, 4);
    negative.area->adaptive = -1;
    CHECK_FALSE(check(negative).first);
    CHECK_FALSE(check(withArea(x, z, 4, kMaxLightSamplesPerSide + 1)).first);
}

TEST_CASE("Light method, shadow apex and light form names", "[lights]") {
    CHECK(parseLightMethod("asos") == LightMethod::Asos);
    CHECK(parseLightMethod("grid") == LightMethod::Grid);
    CHECK_FALSE(parseLightMethod("stochastic"));
    CHECK(std::string(lightMethodName(LightMethod::Grid)) == "grid");
    CHECK(parseShadowApex("behind") == ShadowApex::Behind);
    CHECK(parseShadowApex("surface") == ShadowApex::Surface);
    CHECK_FALSE(parseShadowApex("under"));
    CHECK(std::string(lightFormName(LightForm(SegmentLight{}))) == "linear");
    CHECK(std::string(lightFormName(LightForm(OrientedDiscLight{}))) == "oriented disc");
    CHECK(std::string(lightFormName(LightForm{})) == "point");
}

TEST_CASE("parallel and cylinder area lights are refused, area spotlights are not", "[lights][spotlight]") {
    Light l = withArea({1, 0, 0}, {0, 0, 1}, 3, 3);
    l.type = LightType::Spot;
    l.radius = 20;
    l.falloff = 30;
    {
        Diagnostics d;
        CHECK(checkLight(l, d));
        CHECK_FALSE(d.hasErrors());
        const LightModel m = makeLightModel(l, AsosSettings{});
        REQUIRE(m.beam);
        CHECK(m.beam->type == LightType::Spot);
    }
    l.type = LightType::Cylinder;
    {
        Diagnostics d;
        CHECK_FALSE(checkLight(l, d));
        CHECK(d.hasErrors());
    }
    l.type = LightType::Point;
    l.parallel = true;
    {
        Diagnostics d;
        CHECK_FALSE(checkLight(l, d));
        CHECK(d.hasErrors());
    }
}
