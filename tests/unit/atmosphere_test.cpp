// sky_sphere and fog (render/atmosphere.hpp) by known answers: the sky's
// pigment at known directions, through its transform and its layers;
// constant fog's exp(-d / D) mix; ground fog's density at known heights;
// several fogs together; and how the language reads both. Side by side
// with POV-Ray: tests/golden/povray/atmosphere*.pov.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "asos/render/atmosphere.hpp"
#include "interpret_text.hpp"

using namespace asos;

namespace {

Pigment gradientY() {
    Pigment p;
    p.kind = Pigment::Kind::Gradient;
    p.gradient = Vec3(0.0, 1.0, 0.0);
    return p;  // POV-Ray's default map: black at 0 to white at 1
}

Pigment solid(const Color& c) {
    Pigment p;
    p.color1 = c;
    return p;
}

SceneDescription withSky(std::vector<Pigment> pigments) {
    SceneDescription d;
    d.skySphere.emplace();
    d.skySphere->pigments = std::move(pigments);
    return d;
}

void requireNear(const Vec3& a, const Vec3& b, double tolerance = 1e-12) {
    INFO("got <" << a.x << ", " << a.y << ", " << a.z << ">, expected <" << b.x << ", " << b.y << ", " << b.z << ">");
    REQUIRE(glm::length(a - b) <= tolerance);
}

}  // namespace

TEST_CASE("A sky gradient's colour at known directions", "[atmosphere]") {
    const SceneDescription d = withSky({gradientY()});
    const Atmosphere a(d);
    // The direction itself is the pattern's point: gradient y reads its y.
    requireNear(a.sky(Vec3(0.0, 1.0, 0.0)), Vec3(1.0));
    requireNear(a.sky(glm::normalize(Vec3(0.0, 1.0, std::sqrt(3.0)))), Vec3(0.5));
    requireNear(a.sky(Vec3(1.0, 0.0, 0.0)), Vec3(0.0));
    // Below the horizon POV-Ray's gradient repeats: -0.25 reads 0.75.
    requireNear(a.sky(glm::normalize(Vec3(0.0, -0.25, std::sqrt(1.0 - 0.0625)))), Vec3(0.75), 1e-9);
    CHECK(a.skyVaries());

    SECTION("turned by the sky_sphere's transform") {
        SceneDescription t = d;
        t.skySphere->worldFromSky = Transform::rotateDegrees(Vec3(0.0, 0.0, 90.0));
        // Turned 90 degrees about z, the sky's top lies along -x.
        requireNear(Atmosphere(t).sky(Vec3(-1.0, 0.0, 0.0)), Vec3(1.0), 1e-12);
        requireNear(Atmosphere(t).sky(Vec3(0.0, 1.0, 0.0)), Vec3(0.0), 1e-12);
    }
    SECTION("times its emission") {
        SceneDescription e = d;
        e.skySphere->emission = Vec3(0.5, 1.0, 2.0);
        requireNear(Atmosphere(e).sky(Vec3(0.0, 1.0, 0.0)), Vec3(0.5, 1.0, 2.0));
    }
}

TEST_CASE("Sky layers and the background under them, as POV-Ray 3.7 and 3.6 compose them", "[atmosphere]") {
    // The last pigment written is on top: half transmitting red over blue.
    SceneDescription d = withSky({solid({Vec3(0.0, 0.0, 1.0), 0.0, 0.0}), solid({Vec3(1.0, 0.0, 0.0), 0.0, 0.5})});
    d.background = Color{Vec3(0.0, 1.0, 0.0), 0.0, 0.0};
    requireNear(Atmosphere(d).sky(Vec3(0.0, 0.0, 1.0)), Vec3(0.5, 0.0, 0.5));
    // A filtering top layer over the background alone: 3.7 tints what it
    // lets through by its colour (rgb f + t).
    SceneDescription f = withSky({solid({Vec3(1.0, 0.5, 0.0), 0.5, 0.25})});
    f.background = Color{Vec3(0.4), 0.0, 0.0};
    const Vec3 through = Vec3(1.0, 0.5, 0.0) * 0.5 + Vec3(0.25);
    requireNear(Atmosphere(f).sky(Vec3(0.0, 0.0, 1.0)), Vec3(1.0, 0.5, 0.0) * 0.25 + Vec3(0.4) * through);
    // Before 3.7 the same: one layer composes alike under both.
    f.version = 3.62;
    requireNear(Atmosphere(f).sky(Vec3(0.0, 0.0, 1.0)), Vec3(1.0, 0.5, 0.0) * 0.25 + Vec3(0.4) * through);
    // Two filtering layers differ: 3.6 tints the background by the product
    // of their colours times the product of their filters, plus that of
    // their transmits.
    SceneDescription two = withSky({solid({Vec3(0.5, 1.0, 1.0), 0.5, 0.0}), solid({Vec3(1.0, 1.0, 0.5), 0.5, 0.0})});
    two.background = Color{Vec3(1.0), 0.0, 0.0};
    two.version = 3.62;
    // col = top 0.5 * rgb(1,1,.5) + bottom (|0.5| + 0) * 0.5 * rgb(.5,1,1);
    // background through rgb(.5,1,.5) * 0.25.
    requireNear(Atmosphere(two).sky(Vec3(0.0, 0.0, 1.0)),
                Vec3(0.5, 0.5, 0.25) + Vec3(0.125, 0.25, 0.25) + Vec3(0.5, 1.0, 0.5) * 0.25);
    two.version = 3.7;
    // 3.7: top 0.5 * rgb(1,1,.5); through it rgb(.5,.5,.25); the bottom
    // adds 0.5 * rgb(.5,1,1) * that; the background the product of both.
    const Vec3 t1(0.5, 0.5, 0.25), t2(0.25, 0.5, 0.5);
    requireNear(Atmosphere(two).sky(Vec3(0.0, 0.0, 1.0)), Vec3(0.5, 0.5, 0.25) + Vec3(0.25, 0.5, 0.5) * t1 + t1 * t2);
}

TEST_CASE("Constant fog mixes by exp(-d / D)", "[atmosphere]") {
    SceneDescription d;
    Fog fog;
    fog.distance = 10.0;
    fog.color = Color{Vec3(0.8, 0.6, 0.4), 0.0, 0.0};
    d.fogs.push_back(fog);
    const Atmosphere a(d);
    const Ray ray{Vec3(0.0), Vec3(0.0, 0.0, 1.0)};
    const double k = std::exp(-2.5 / 10.0);
    requireNear(a.fogged(Vec3(0.1, 0.2, 0.3), ray, 2.5), k * Vec3(0.1, 0.2, 0.3) + (1.0 - k) * Vec3(0.8, 0.6, 0.4));
    // A ray that hits nothing is fogged over POV-Ray's BOUND_HUGE: the fog's colour.
    requireNear(a.miss(ray), Vec3(0.8, 0.6, 0.4));

    SECTION("its transmit is the least it lets through, its filter tints that") {
        d.fogs[0].color = Color{Vec3(0.8, 0.6, 0.4), 0.5, 0.3};
        const Atmosphere t(d);
        // att = max(exp(-huge), 0.3); through: att (0.5 + 0.5 rgb).
        const Vec3 through = 0.3 * (Vec3(0.5) + 0.5 * Vec3(0.8, 0.6, 0.4));
        requireNear(t.miss(ray), 0.7 * Vec3(0.8, 0.6, 0.4));  // black background
        requireNear(t.fogged(Vec3(1.0), ray, 1e9), 0.7 * Vec3(0.8, 0.6, 0.4) + through);
    }
    SECTION("several fogs: their attenuations multiply, their colours add") {
        Fog second;
        second.distance = 5.0;
        second.color = Color{Vec3(0.0, 0.0, 1.0), 0.0, 0.0};
        d.fogs.push_back(second);
        const double k2 = std::exp(-2.5 / 5.0);
        requireNear(Atmosphere(d).fogged(Vec3(1.0), ray, 2.5),
                    k * k2 * Vec3(1.0) + (1.0 - k) * Vec3(0.8, 0.6, 0.4) + (1.0 - k2) * Vec3(0.0, 0.0, 1.0));
    }
    SECTION("a fog without a distance is none") {
        d.fogs[0].distance = 0.0;
        requireNear(Atmosphere(d).fogged(Vec3(0.3), ray, 100.0), Vec3(0.3));
    }
}

TEST_CASE("Ground fog's density at known heights", "[atmosphere]") {
    Fog fog;
    fog.type = 2;
    fog.distance = 1.0;
    fog.offset = 1.0;
    fog.alt = 2.0;
    const double d = 3.0;
    auto level = [&](double y) { return fogTransmittance(fog, Ray{Vec3(0.0, y, 0.0), Vec3(1.0, 0.0, 0.0)}, d, 2); };
    // Below fog_offset the density is 1; at height h above it 1 / (1 + (h / alt)^2).
    CHECK(level(0.5) == Approx(std::exp(-d)).epsilon(1e-12));
    CHECK(level(1.0) == Approx(std::exp(-d)).epsilon(1e-12));
    CHECK(level(3.0) == Approx(std::exp(-d * 0.5)).epsilon(1e-12));   // h / alt = 1
    CHECK(level(5.0) == Approx(std::exp(-d * 0.2)).epsilon(1e-12));   // h / alt = 2
    // Straight up from fog_offset through one fog_alt: the mean of 1 / (1 + h^2) over [0, 1], pi / 4.
    const double up = fogTransmittance(fog, Ray{Vec3(0.0, 1.0, 0.0), Vec3(0.0, 1.0, 0.0)}, 2.0, 2);
    CHECK(up == Approx(std::exp(-2.0 * std::numbers::pi / 4.0)).epsilon(1e-12));
    // From below the offset to above: the part below counts whole.
    const double across = fogTransmittance(fog, Ray{Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0)}, 4.0, 2);
    CHECK(across == Approx(std::exp(-4.0 * (std::atan(1.0) + 1.0) / 2.0)).epsilon(1e-12));
}

TEST_CASE("The language reads sky_sphere and fog as POV-Ray does", "[atmosphere][lang]") {
    const auto r = test::run(R"(
        sky_sphere { pigment { rgb 1 } rotate 90 * x pigment { gradient y } emission rgb <1, 0.5, 2> }
        sky_sphere { pigment { rgb <0, 0, 1> } }
        fog { fog_type 2 distance 5 color rgbt <1, 1, 1, 0.2> fog_offset 1 fog_alt 0.5 up <0, 2, 0> rotate 90 * z }
        fog { rgb 0.5 distance 20 turbulence 0.3 octaves 3 }
    )");
    const SceneDescription& d = test::ok(r);
    // The last sky_sphere is the scene's.
    REQUIRE(d.skySphere);
    REQUIRE(d.skySphere->pigments.size() == 1);
    CHECK(d.skySphere->pigments[0].color1.rgb == Vec3(0.0, 0.0, 1.0));
    REQUIRE(d.fogs.size() == 2);
    CHECK(d.fogs[0].type == 2);
    CHECK(d.fogs[0].distance == 5.0);
    CHECK(d.fogs[0].color.transmit == Approx(0.2));
    CHECK(d.fogs[0].alt == 0.5);
    // up is turned by the rotation and made unit.
    CHECK(glm::length(d.fogs[0].up - Vec3(-1.0, 0.0, 0.0)) < 1e-12);
    CHECK(d.fogs[1].turbulent);
    CHECK(d.fogs[1].octaves == 3);
    CHECK(d.fogs[1].color.rgb == Vec3(0.5));

    const auto first = test::run("sky_sphere { pigment { rgb 1 } scale 2 pigment { gradient y } emission rgb <1, 0.5, 2> }");
    const SceneDescription& s = test::ok(first);
    REQUIRE(s.skySphere->pigments.size() == 2);
    CHECK(s.skySphere->emission == Vec3(1.0, 0.5, 2.0));
    CHECK(s.skySphere->pigments[1].kind == Pigment::Kind::Gradient);
    CHECK_FALSE(s.skySphere->worldFromSky.isIdentity());

    CHECK(test::run("sky_sphere { }").errors() ==
          "1:1: a sky_sphere needs at least one pigment (POV-Ray: empty sky_sphere statement)\n");
    CHECK(test::run("fog { fog_type 2 distance 3 }").errors() ==
          "1:1: a ground fog (fog_type 2) needs a fog_alt other than 0 (its density divides by it)\n");
    // Warnings, before those of a scene without #version or assumed_gamma.
    using Catch::Matchers::StartsWith;
    CHECK_THAT(test::run("fog { distance 3 translate y }").errors(),
               StartsWith("1:18: a fog's up vector can't be translated (as in POV-Ray, ignored)\n0:0:"));
    CHECK_THAT(test::run("fog { 3 }").errors(), StartsWith("1:7: should use the distance keyword (as POV-Ray warns)\n0:0:"));
    CHECK(test::run("sphere { 0, 1 finish { emission 1 } }").errors() ==
          "1:24: 'emission' in a finish is not supported by asos\n");
    CHECK(test::run("rainbow { angle 42 }").errors() == "1:1: 'rainbow' is not supported by asos\n");
    CHECK(test::run("fog { distance 3 media { } }").errors() == "1:18: 'media' is not supported by asos\n");
}

TEST_CASE("A declared sky_sphere or fog starts the one that names it, as POV-Ray", "[atmosphere][lang]") {
    // POV-Ray's Parse_Skysphere: the declared one's pigments, emission and
    // transform, then the block's pigments added after them and its
    // transforms composed onto the declared one's.
    const auto sky = test::run(R"(
        #declare S = sky_sphere { pigment { rgb 1 } emission rgb 0.5 rotate 90 * z }
        sky_sphere { S pigment { gradient y } scale 2 })");
    const SceneDescription& s = test::ok(sky);
    REQUIRE(s.skySphere);
    REQUIRE(s.skySphere->pigments.size() == 2);
    CHECK(s.skySphere->pigments[0].kind == Pigment::Kind::Solid);
    CHECK(s.skySphere->pigments[1].kind == Pigment::Kind::Gradient);
    CHECK(s.skySphere->emission == Vec3(0.5));
    requireNear(s.skySphere->worldFromSky.point(Vec3(1.0, 0.0, 0.0)), Vec3(0.0, 2.0, 0.0), 1e-12);
    CHECK(s.skySphere->loc.line == 3);

    // Alone, the declared sky_sphere is the scene's as written.
    const auto alone = test::run("#declare S = sky_sphere { pigment { rgb <1, 0, 0> } }\nsky_sphere { S }");
    REQUIRE(test::ok(alone).skySphere->pigments.size() == 1);
    CHECK(test::ok(alone).skySphere->pigments[0].color1.rgb == Vec3(1.0, 0.0, 0.0));

    // A declared fog: its items, then the block's over them.
    const auto fog = test::run(R"(
        #local F = fog { fog_type 2 distance 3 fog_alt 0.5 rgb <0.2, 0.3, 0.4> }
        fog { F fog_offset 1 distance 5 })");
    const SceneDescription& f = test::ok(fog);
    REQUIRE(f.fogs.size() == 1);
    CHECK(f.fogs[0].type == 2);
    CHECK(f.fogs[0].distance == 5.0);
    CHECK(f.fogs[0].alt == 0.5);
    CHECK(f.fogs[0].offset == 1.0);
    CHECK(f.fogs[0].color.rgb == Vec3(0.2, 0.3, 0.4));

    CHECK(test::run("#declare S = sky_sphere { pigment { rgb 1 } }\nsky_sphere { pigment { rgb 0 } S }").errors() ==
          "2:32: a declared sky_sphere must come first in the sky_sphere\n");
    CHECK(test::run("#declare P = pigment { rgb 1 }\nsky_sphere { P pigment { rgb 0 } }").errors() ==
          "2:14: 'P' is a pigment, not a sky_sphere\n");
    CHECK(test::run("#declare F = fog { distance 3 }\nfog { distance 2 F }").errors() ==
          "2:18: a declared fog must come first in the fog\n");
    CHECK(test::run("#declare S = sky_sphere { pigment { rgb 1 } }\nfog { S }").errors() ==
          "2:7: expected a colour, a float or a declared fog, found a sky_sphere\n");
    CHECK(test::run("#declare S = sky_sphere { pigment { rgb 1 } }\nsphere { 0, 1 pigment { S } }").errors() ==
          "2:25: expected a colour or a pigment, found a sky_sphere\n");
}
