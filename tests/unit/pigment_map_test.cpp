// POV-Ray's pigment_map and average: the blend halfway between two pigments
// and at the map's ends, entries evaluated in the outer pigment's pattern
// space (their own transforms relative to it), a nested map, average's
// weighted mean (weights left out are 1), transparency found through the
// entries, the interpreter's reading of the entries and its errors for
// misuse, and one map shared by every object that uses the pigment. Against
// POV-Ray's renders: tests/golden/povray/pigment_map.pov.
#include <catch2/catch.hpp>

#include <memory>

#include "asos/render/map_pattern.hpp"
#include "asos/render/pattern_edges.hpp"
#include "asos/render/shading.hpp"
#include "interpret_text.hpp"

using namespace asos;

namespace {

Color rgb(double r, double g, double b) { return Color{Vec3(r, g, b), 0.0, 0.0}; }

std::shared_ptr<const Pigment> solid(const Color& c) {
    auto p = std::make_shared<Pigment>();
    p->color1 = c;
    return p;
}

// gradient x over the given entries.
Pigment gradientOf(PigmentMap entries) {
    Pigment p;
    p.kind = Pigment::Kind::Gradient;
    p.gradient = Vec3(1.0, 0.0, 0.0);
    p.pigmentMap = std::make_shared<const PigmentMap>(std::move(entries));
    return p;
}

void checkColour(const Color& got, const Color& expected) {
    CHECK(got.rgb.x == Approx(expected.rgb.x).margin(1e-12));
    CHECK(got.rgb.y == Approx(expected.rgb.y).margin(1e-12));
    CHECK(got.rgb.z == Approx(expected.rgb.z).margin(1e-12));
    CHECK(got.filter == Approx(expected.filter).margin(1e-12));
    CHECK(got.transmit == Approx(expected.transmit).margin(1e-12));
}

}  // namespace

TEST_CASE("A pigment map blends its entries' pigments as a colour map its colours", "[pattern][pigment_map]") {
    const Pigment p = gradientOf({{0.2, solid(rgb(1, 0, 0))}, {0.6, solid(Color{Vec3(0, 0, 1), 0.0, 0.5})}});
    checkColour(evaluatePigment(p, Vec3(0.1, 0, 0)), rgb(1, 0, 0));   // before the first entry
    checkColour(evaluatePigment(p, Vec3(0.4, 0, 0)), Color{Vec3(0.5, 0, 0.5), 0.0, 0.25});  // halfway
    checkColour(evaluatePigment(p, Vec3(0.5, 0, 0)), Color{Vec3(0.25, 0, 0.75), 0.0, 0.375});
    checkColour(evaluatePigment(p, Vec3(0.9, 0, 0)), Color{Vec3(0, 0, 1), 0.0, 0.5});  // after the last
    CHECK_FALSE(hasPattern(p));  // sampled at points, as the map patterns
}

TEST_CASE("A pigment map's entries are evaluated in the outer pigment's pattern space", "[pattern][pigment_map]") {
    // Entry 2: gradient x of its own, black to white, scaled by 4 relative
    // to the outer pigment, itself scaled by 2: at world x = 1.2 the outer
    // value is 0.6 (the second entry alone), the entry's value 0.6 / 4.
    auto inner = std::make_shared<Pigment>();
    inner->kind = Pigment::Kind::Gradient;
    inner->gradient = Vec3(1.0, 0.0, 0.0);
    inner->worldFromPattern = Transform::scale(Vec3(4.0));
    Pigment p = gradientOf({{0.0, solid(rgb(1, 0, 0))}, {0.5, inner}});
    p.worldFromPattern = Transform::scale(Vec3(2.0));
    checkColour(evaluatePigment(p, Vec3(1.2, 0, 0)), rgb(0.15, 0.15, 0.15));
    // At world x = 0.5: outer value 0.25, halfway between red and the
    // inner gradient's 0.25 / 4.
    checkColour(evaluatePigment(p, Vec3(0.5, 0, 0)), rgb(0.5 + 0.5 * 0.0625, 0.5 * 0.0625, 0.5 * 0.0625));
}

TEST_CASE("Pigment maps nest", "[pattern][pigment_map]") {
    const Pigment inner = gradientOf({{0.0, solid(rgb(0, 1, 0))}, {1.0, solid(rgb(0, 0, 1))}});
    Pigment outer;
    outer.kind = Pigment::Kind::Gradient;
    outer.gradient = Vec3(0.0, 1.0, 0.0);
    outer.pigmentMap = std::make_shared<const PigmentMap>(
        PigmentMap{{0.0, solid(rgb(1, 0, 0))}, {1.0, std::make_shared<const Pigment>(inner)}});
    // y = 0.5: half red, half the inner map at x = 0.25 (green to blue).
    checkColour(evaluatePigment(outer, Vec3(0.25, 0.5, 0)), rgb(0.5, 0.375, 0.125));
}

TEST_CASE("average is the weighted mean of its pigments at the point", "[pattern][pigment_map]") {
    Pigment p;
    p.kind = Pigment::Kind::Average;
    p.pigmentMap = std::make_shared<const PigmentMap>(PigmentMap{
        {1.0, solid(rgb(1, 0, 0))}, {3.0, solid(rgb(0, 0, 1))}, {0.0, solid(rgb(0, 1, 0))}});
    checkColour(evaluatePigment(p, Vec3(0.3, 0.7, 0.1)), rgb(0.25, 0, 0.75));
    // An entry that is a pattern of its own is evaluated where the point is.
    const Pigment g = gradientOf({{0.0, solid(rgb(0, 0, 0))}, {1.0, solid(rgb(1, 1, 1))}});
    p.pigmentMap = std::make_shared<const PigmentMap>(
        PigmentMap{{1.0, std::make_shared<const Pigment>(g)}, {1.0, solid(rgb(1, 0, 0))}});
    checkColour(evaluatePigment(p, Vec3(0.5, 0, 0)), rgb(0.75, 0.25, 0.25));
}

TEST_CASE("A texture is transparent where an entry of its pigment map may be", "[pattern][pigment_map]") {
    Texture t;
    t.pigment = gradientOf({{0.0, solid(rgb(1, 0, 0))}, {1.0, solid(Color{Vec3(1.0), 0.0, 1.0})}});
    CHECK(mayBeTransparent(t));
    t.pigment = gradientOf({{0.0, solid(rgb(1, 0, 0))}, {1.0, solid(rgb(1, 1, 1))}});
    CHECK_FALSE(mayBeTransparent(t));
}

TEST_CASE("The interpreter reads pigment_map and average", "[lang][pigment_map]") {
    const auto r = test::run(R"(
        #declare Spots = pigment { bozo scale 0.5 }
        #declare P = pigment { gradient x pigment_map { [0.2 rgb <1, 0, 0>] [0.5, Spots rotate 30 * z] [0.8 checker rgb 0, rgb 1] } scale 2 }
        sphere { 0, 1 pigment { P } }
        sphere { 0, 1 pigment { P } }
        sphere { 0, 1 pigment { average pigment_map { [Spots] [2 rgb 1] [rgb 0] } } }
    )");
    // The last entry's weight is the colour written where POV-Ray reads it:
    // refused, as POV-Ray refuses it.
    CHECK(r.errors() == "6:74: expected the weight of the average entry, found a colour (POV-Ray reads a colour "
                        "there as the weight; write [1 colour])\n");
    const auto good = test::run(R"(
        #declare Spots = pigment { bozo scale 0.5 }
        #declare P = pigment { gradient x pigment_map { [0.2 rgb <1, 0, 0>] [0.5, Spots rotate 30 * z] [0.8 checker rgb 0, rgb 1] } scale 2 }
        sphere { 0, 1 pigment { P } }
        sphere { 0, 1 pigment { P translate x } }
        sphere { 0, 1 pigment { average pigment_map { [Spots] [2 rgb 1] } } }
    )");
    const SceneDescription& s = test::ok(good);
    REQUIRE(s.objects.size() == 3);
    const Pigment& a = s.objects[0].texture->pigment;
    REQUIRE(a.pigmentMap);
    REQUIRE(a.pigmentMap->size() == 3);
    CHECK((*a.pigmentMap)[0].value == 0.2);
    CHECK((*a.pigmentMap)[1].pigment->kind == Pigment::Kind::Bozo);
    CHECK((*a.pigmentMap)[2].pigment->kind == Pigment::Kind::Checker);
    // The outer transform is the outer pigment's only; the entries keep theirs.
    CHECK(a.worldFromPattern.matrix()[0][0] == 2.0);
    CHECK((*a.pigmentMap)[1].pigment->worldFromPattern.matrix()[0][0] == Approx(0.5 * std::cos(glm::radians(30.0))));
    // The map is shared, not copied, by every pigment made from P.
    CHECK(s.objects[1].texture->pigment.pigmentMap == a.pigmentMap);
    const Pigment& avg = s.objects[2].texture->pigment;
    CHECK(avg.kind == Pigment::Kind::Average);
    REQUIRE(avg.pigmentMap->size() == 2);
    CHECK((*avg.pigmentMap)[0].value == 1.0);
    CHECK((*avg.pigmentMap)[0].pigment->kind == Pigment::Kind::Bozo);
    CHECK((*avg.pigmentMap)[1].value == 2.0);
}

TEST_CASE("A declared pigment map is shared by the pigments that name it", "[lang][pigment_map]") {
    const auto r = test::run(R"(
        #declare M = pigment_map { [0 rgb 1] [1 bozo] }
        sphere { 0, 1 pigment { gradient y pigment_map { M } } }
        sphere { 0, 1 pigment { average pigment_map { M } } }
    )");
    const SceneDescription& s = test::ok(r);
    REQUIRE(s.objects[0].texture->pigment.pigmentMap);
    CHECK(s.objects[0].texture->pigment.pigmentMap == s.objects[1].texture->pigment.pigmentMap);
    CHECK(test::run("#declare C = color_map { [0 rgb 1] }\nsphere { 0, 1 pigment { bozo pigment_map { C } } }")
              .errors() == "2:44: 'C' is a colour map, not a pigment map\n");
}

TEST_CASE("Misused pigment maps get POV-Ray's errors", "[lang][pigment_map]") {
    auto errorOf = [](const std::string& text) { return test::run(text).errors(); };
    CHECK(errorOf("sphere { 0, 1 pigment { rgb 1 pigment_map { [0 rgb 1] } } }") ==
          "1:31: Cannot use pigment_map with this pigment type (a plain colour); give it a pattern first\n");
    CHECK(errorOf("sphere { 0, 1 pigment { checker pigment_map { [0 rgb 1] } } }") ==
          "1:33: Cannot use pigment_map with this pigment type (checker); give it a pattern first\n");
    CHECK(errorOf("sphere { 0, 1 pigment { average } }") == "1:15: Missing pigment_map in average pigment\n");
    CHECK(errorOf("sphere { 0, 1 pigment { average color_map { [0 rgb 1] } } }") ==
          "1:33: Cannot use color_map with this pattern type (average)\n");
    CHECK(errorOf("sphere { 0, 1 pigment { bozo pigment_map { [rgb 1] } } }") ==
          "1:45: expected the value of the pigment map entry, found a colour\n");
    CHECK(errorOf("sphere { 0, 1 pigment { bozo pigment_map { } } }") ==
          "1:30: a pigment map needs at least one entry\n");
}

TEST_CASE("checker and brick of two pigments show each cell's pigment", "[pattern][pigment_map][lang]") {
    const auto r = test::run(R"(
        sphere { 0, 1 pigment { checker pigment { gradient x } pigment { rgb <1, 0, 0> } scale 2 } }
        sphere { 0, 1 pigment { brick pigment { rgb 1 } } }
    )");
    const SceneDescription& s = test::ok(r);
    const Pigment& checker = s.objects[0].texture->pigment;
    REQUIRE(checker.pigmentMap);
    CHECK_FALSE(hasPattern(checker));  // sampled at points: its pigments vary inside its cells
    // Cell (0, 0, 0) of the scaled checker: the gradient, read at the
    // pattern-space point (world x 0.5 is pattern x 0.25).
    checkColour(evaluatePigment(checker, Vec3(0.5, 0.5, 0.5)), rgb(0.25, 0.25, 0.25));
    checkColour(evaluatePigment(checker, Vec3(2.5, 0.5, 0.5)), rgb(1, 0, 0));
    // A brick given one pigment: the brick is POV-Ray's default brick colour.
    const Pigment& brick = s.objects[1].texture->pigment;
    REQUIRE(brick.pigmentMap->size() == 2);
    CHECK((*brick.pigmentMap)[1].pigment->color1.rgb == Vec3(0.6, 0.15, 0.15));
}
