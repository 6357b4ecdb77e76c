// POV-Ray 3.7's noise and the map patterns: the scalar noise under each
// generator against POV-Ray's own values (printed by povray through
// functions.inc's f_noise3d, which evaluates the same noise), the colour
// map's lookup (ends, blends, a sharp step, values out of order as POV-Ray
// takes them), the waves, and the patterns' values at known points. The
// patterns against POV-Ray's renders: tests/golden/povray/map_*.pov.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "asos/render/crackle_pattern.hpp"
#include "asos/render/map_pattern.hpp"
#include "asos/render/pattern_edges.hpp"
#include "asos/render/pov_noise.hpp"
#include "asos/render/shading.hpp"

using namespace asos;

namespace {

struct NoiseCase {
    Vec3 p;
    double generator1, generator2, generator3;
};

// #debug str(f_noise3d(x, y, z), 0, 12) under global_settings { noise_generator G }.
const NoiseCase kPovrayNoise[] = {
    {{0.3, 0.7, 0.1}, 0.253942564736, 0.395001395366, 0.507016502894},
    {{-2.25, 3.5, 11.75}, 0.107647782361, 0.323338044784, 0.469415566070},
    {{100.1, -50.2, 7.3}, 0.559476343094, 0.544668894901, 0.460145852459},
    {{0.0, 0.0, 0.0}, 0.056580500000, 0.298322439308, 0.511354305373},
    {{-0.001, 0.5, -7.9}, 0.457534037537, 0.494731863220, 0.678000370574},
};

Color grey(double v) { return Color{Vec3(v), 0.0, 0.0}; }

}  // namespace

TEST_CASE("The noise is POV-Ray's under each generator", "[pattern][noise]") {
    const PovNoise& noise = PovNoise::tables();
    for (const NoiseCase& c : kPovrayNoise) {
        INFO(c.p.x << ", " << c.p.y << ", " << c.p.z);
        CHECK(noise.noise(c.p, 1) == Approx(c.generator1).margin(1e-11));
        CHECK(noise.noise(c.p, 2) == Approx(c.generator2).margin(1e-11));
        CHECK(noise.noise(c.p, 3) == Approx(c.generator3).margin(1e-11));
    }
}

TEST_CASE("Turbulence sums octaves of the noise", "[pattern][noise]") {
    const PovNoise& noise = PovNoise::tables();
    const Vec3 p(0.3, 0.7, 0.1);
    // One octave is the noise itself (generator 2: stretched and clipped).
    CHECK(noise.turbulence(p, 1, 0.5, 2.0, 1) == noise.noise(p, 1));
    CHECK(noise.turbulence(p, 1, 0.5, 2.0, 2) == std::clamp(2.0 * noise.noise(p, 2) - 0.5, 0.0, 1.0));
    CHECK(noise.turbulence(p, 2, 0.5, 2.0, 1) == noise.noise(p, 1) + 0.5 * noise.noise(2.0 * p, 1));
    const Vec3 d = noise.dturbulence(p, 2, 0.25, 3.0);
    const Vec3 expected = noise.dnoise(p) + 0.25 * noise.dnoise(3.0 * p);
    CHECK(d.x == expected.x);
    CHECK(d.y == expected.y);
    CHECK(d.z == expected.z);
}

TEST_CASE("A colour map blends between its entries as POV-Ray's does", "[pattern]") {
    const ColourMapEntry map[] = {{0.2, grey(0.0)}, {0.6, grey(1.0)}, {0.6, grey(0.5)}, {0.8, grey(0.25)}};
    CHECK(colourMapAt(map, 0.0) == grey(0.0));        // below the first: the first
    CHECK(colourMapAt(map, 0.9) == grey(0.25));       // above the last: the last
    CHECK(colourMapAt(map, 0.4).rgb.x == Approx(0.5));
    CHECK(colourMapAt(map, 0.6) == grey(1.0));        // a sharp step: the lower side at the value
    CHECK(colourMapAt(map, 0.7).rgb.x == Approx(0.375));
    // Values out of order, as POV-Ray takes them: at or below the first, the
    // first; at or above the last, the last.
    const ColourMapEntry unordered[] = {{0.5, grey(1.0)}, {0.2, grey(0.0)}};
    CHECK(colourMapAt(unordered, 0.3) == grey(1.0));
    CHECK(colourMapAt(unordered, 0.7) == grey(0.0));
}

TEST_CASE("The map patterns' values", "[pattern]") {
    Pigment p;
    p.kind = Pigment::Kind::Gradient;
    p.gradient = Vec3(1.0, 0.0, 0.0);
    CHECK(mapPatternValue(p, Vec3(0.25, 5.0, 5.0)) == Approx(0.25));
    CHECK(mapPatternValue(p, Vec3(-0.25, 0.0, 0.0)) == Approx(0.75));  // negative values wrap
    CHECK(mapPatternValue(p, Vec3(2.5, 0.0, 0.0)) == Approx(0.5));
    p.wave = Pigment::Wave::Triangle;
    CHECK(mapPatternValue(p, Vec3(0.25, 0.0, 0.0)) == Approx(0.5));
    CHECK(mapPatternValue(p, Vec3(0.75, 0.0, 0.0)) == Approx(0.5));
    p.wave = Pigment::Wave::Sine;
    CHECK(mapPatternValue(p, Vec3(0.25, 0.0, 0.0)) == Approx(1.0));
    p.wave = Pigment::Wave::Ramp;
    p.frequency = 2.0;
    p.phase = 0.1;
    CHECK(mapPatternValue(p, Vec3(0.3, 0.0, 0.0)) == Approx(0.7));

    Pigment onion;
    onion.kind = Pigment::Kind::Onion;
    CHECK(mapPatternValue(onion, Vec3(0.0, 3.0, 4.0)) == Approx(0.0).margin(1e-12));
    CHECK(mapPatternValue(onion, Vec3(0.0, 0.0, 1.5)) == Approx(0.5));

    Pigment radial;
    radial.kind = Pigment::Kind::Radial;
    // -z: 1.25 before the wave, which takes it modulo POV-Ray's 1.00001.
    CHECK(mapPatternValue(radial, Vec3(0.0, 0.0, -1.0)) == Approx(1.25 - 1.00001));
    CHECK(mapPatternValue(radial, Vec3(0.0, 7.0, 0.0)) == Approx(0.25));   // on the axis

    Pigment leopard;
    leopard.kind = Pigment::Kind::Leopard;
    const double h = std::numbers::pi / 2.0;
    CHECK(mapPatternValue(leopard, Vec3(h, h, h)) == Approx(1.0));
}

TEST_CASE("Map patterns are sampled at points, not filtered", "[pattern]") {
    Pigment p;
    p.kind = Pigment::Kind::Bozo;
    CHECK_FALSE(hasPattern(p));
    // The default bozo map: white below 0.4.
    const Vec3 at(0.3, 0.7, 0.1);  // noise 0.395 there (generator 2)
    CHECK(evaluatePigment(p, at) == Color{Vec3(1.0), 0.0, 0.0});
}

// The normal patterns as pigment patterns against POV-Ray's values, printed
// by povray 3.7.0 through `function { pigment { P } }` (its red channel, a
// float: hence the tolerance) at three points, under the default generator
// (2) unless said.
TEST_CASE("bumps, dents, wrinkles, ripples and waves as pigments give POV-Ray's values", "[pattern]") {
    const Vec3 points[] = {{0.3, 0.7, 0.1}, {-2.25, 3.5, 11.75}, {1.1, -0.4, 2.6}};
    struct Case {
        Pigment::Kind kind;
        double frequency, phase;
        int generator;
        double values[3];
    };
    const Case cases[] = {
        {Pigment::Kind::Bumps, 1.0, 0.0, 0, {0.395001381636, 0.323338031769, 0.427360773087}},
        {Pigment::Kind::Dents, 1.0, 0.0, 0, {0.061630528420, 0.033804181963, 0.078051984310}},
        {Pigment::Kind::Wrinkles, 1.0, 0.0, 0, {0.461333215237, 0.402962327003, 0.459846347570}},
        {Pigment::Kind::Wrinkles, 1.0, 0.0, 1, {0.428862065077, 0.369282394648, 0.427344411612}},
        {Pigment::Kind::Ripples, 1.0, 0.0, 0, {0.280421525240, 0.544350028038, 0.443206280470}},
        {Pigment::Kind::Waves, 1.0, 0.0, 0, {0.681625902653, 0.704053044319, 0.392501085997}},
        // frequency and phase inside the pattern, and again as the wave.
        {Pigment::Kind::Ripples, 2.0, 0.3, 0, {0.178480356932, 0.040751449764, 0.148157015443}},
        {Pigment::Kind::Waves, 1.5, 0.2, 0, {0.903958678246, 0.829548001289, 0.977406203747}},
    };
    for (const Case& c : cases) {
        Pigment p;
        p.kind = c.kind;
        p.frequency = c.frequency;
        p.phase = c.phase;
        p.noiseGenerator = c.generator;
        for (int i = 0; i < 3; ++i) {
            INFO("kind " << static_cast<int>(c.kind) << ", point " << i);
            CHECK(mapPatternValue(p, points[i]) == Approx(c.values[i]).margin(1e-6));
        }
    }
}

// crackle against POV-Ray's values, printed by povray 3.7.0 through
// `function { pigment { crackle … color_map { [0 rgb 0] [1 rgb 1] } } }`
// (its red channel, a float: hence the tolerance) at five points.
TEST_CASE("crackle gives POV-Ray's values", "[pattern]") {
    const Vec3 points[] = {{0.3, 0.7, 0.1}, {-2.25, 3.5, 11.75}, {1.1, -0.4, 2.6}, {100.1, -50.2, 7.3}, {0, 0, 0}};
    struct Case {
        const char* name;
        Vec3 form;
        double metric, offset;
        bool solid;
        double values[5];
    };
    const Case cases[] = {
        {"default", {-1, 1, 0}, 2.0, 0.0, false,
         {0.157559543848, 0.073333889246, 0.270912557840, 0.165171772242, 0.109558716416}},
        {"metric 1", {-1, 1, 0}, 1.0, 0.0, false,
         {0.243861094117, 0.152977645397, 0.492088884115, 0.215919449925, 0.184853881598}},
        {"metric 3 offset 0.2", {-1, 1, 0}, 3.0, 0.2, false,
         {0.135726124048, 0.048524614424, 0.200528547168, 0.139489054680, 0.096732050180}},
        {"form <1, 0, 0>", {1, 0, 0}, 2.0, 0.0, false,
         {0.551982760429, 0.441605359316, 0.298547774553, 0.341674745083, 0.635122716427}},
        {"form <0.5, 0.3, -0.2> offset 0.1", {0.5, 0.3, -0.2}, 2.0, 0.1, false,
         {0.315670460463, 0.175477623940, 0.190046370029, 0.146420478821, 0.368169873953}},
        {"solid", {-1, 1, 0}, 2.0, 0.0, true,
         {0.432515680790, 0.312351942062, 0.451300561428, 0.589416325092, 0.457736402750}},
        // Above 1, clipped.
        {"metric 1 offset 0.3 form <0.2, 0.3, 0.4>", {0.2, 0.3, 0.4}, 1.0, 0.3, false, {1, 1, 1, 1, 1}},
    };
    for (const Case& c : cases) {
        Pigment p;
        p.kind = Pigment::Kind::Crackle;
        p.crackleForm = c.form;
        p.crackleMetric = c.metric;
        p.crackleOffset = c.offset;
        p.crackleSolid = c.solid;
        for (int i = 0; i < 5; ++i) {
            INFO(c.name << ", point " << i);
            CHECK(mapPatternValue(p, points[i]) == Approx(c.values[i]).margin(1e-6));
        }
    }
}

// POV-Ray's points, one per unit cube: in their cube, and the same each time.
TEST_CASE("crackle's points lie in their cubes", "[pattern]") {
    const CracklePattern& crackle = CracklePattern::tables();
    for (int x = -3; x <= 3; ++x)
        for (int y = -3; y <= 3; ++y) {
            const Vec3 point = crackle.pointInCube(x, y, 4097);
            CHECK(point.x >= x);
            CHECK(point.x < x + 1);
            CHECK(point.y >= y);
            CHECK(point.y < y + 1);
            CHECK(point.z >= 4097);
            CHECK(point.z < 4098);
            CHECK(crackle.pointInCube(x, y, 4097) == point);
        }
}
