// Arrays, strings, POV-Ray's random numbers, the clock's values and #default:
// known answers, checked against `povray` 3.7 with #debug.
#include <catch2/catch.hpp>

#include "interpret_text.hpp"

using namespace asos;
using namespace asos::lang;
using namespace asos::test;
using Catch::Matchers::Contains;

TEST_CASE("arrays: elements, copies, one kind", "[lang][array]") {
    const std::string a = "#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };";
    CHECK(floatOf("A[1][2]", a) == 6);
    CHECK(floatOf("dimensions(A)", a) == 2);
    CHECK(floatOf("dimension_size(A, 2)", a) == 3);
    CHECK(floatOf("dimension_size(A, 3)", a) == 0);  // a dimension it does not have
    CHECK(floatOf("A[0][1.9999999999]", a) == 3);     // the index plus 1e-10, truncated
    CHECK(floatOf("A[1][-1e-11]", a) == 4);
    // Values: a copy changes alone.
    CHECK(floatOf("A[0][0] + 10 * C[0][0]", a + "\n#declare C = A;\n#declare C[0][0] = 9;") == 91);
    const std::string b = "#declare B = array[3];\n#declare B[0] = 1;";
    CHECK(floatOf("defined(B[0]) + 2 * defined(B[1])", b) == 1);
    CHECK(floatOf("X", b + "\n#ifdef (B[1]) #declare X = 1; #else #declare X = 2; #end") == 2);
    // Elements of any one kind, blocks too.
    Run r = run("#declare S = array[2] { sphere { 0, 1 } sphere { 0, 2 } }\nobject { S[1] }\n"
                "#declare T = array[1] { texture { pigment { rgb 1 } } };\nbox { 0, 1 texture { T[0] } }\n");
    const auto& scene = ok(r);
    REQUIRE(scene.objects.size() == 2);
    CHECK(std::get<SphereShape>(scene.objects[0].shape).radius == 2);
    CHECK(scene.objects[1].texture->pigment.color1.rgb == Vec3(1));

    CHECK_THAT(run(b + "\n#declare B[1] = <1, 2, 3>;").errors(),
               Contains("an array holds one kind of value: this one holds a float, not a vector"));
    CHECK_THAT(run(b + "\nsphere { 0, B[2] }").errors(), Contains("this element of 'B' has no value yet"));
    CHECK_THAT(run(b + "\nsphere { 0, B[3] }").errors(), Contains("the index 3 is outside 'B'"));
    InterpreterOptions small;
    small.maxArrayElements = 100;
    CHECK_THAT(run("#declare Big = array[10][11];", small).errors(), Contains("more than 100 elements"));
}

TEST_CASE("POV-Ray's random numbers", "[lang][random]") {
    // povray: seed(123) gives 0.904772982212, 0.995137868914; seed(-5) 0.890052870123;
    // a generator's number is its order.
    const std::string s = "#declare S = seed(123);\n#declare T = seed(-5);";
    CHECK(floatOf("rand(S)", s) == Approx(0.904772982212).epsilon(1e-11));
    CHECK(floatOf("rand(S) + 0 * rand(T)", s) == Approx(0.904772982212).epsilon(1e-11));
    CHECK(floatOf("(rand(S) < 2) * rand(S)", s) == Approx(0.995137868914).epsilon(1e-11));
    CHECK(floatOf("rand(T)", s) == Approx(0.890052870123).epsilon(1e-11));
    CHECK(floatOf("T", s) == 1);
    CHECK_THAT(run("#declare R = rand(0);").errors(), Contains("no such generator"));
    CHECK_THAT(run("#declare S = seed(3e9);").errors(), Contains("the seed must be a whole number"));
}

TEST_CASE("string functions", "[lang][string]") {
    // povray: strcmp -1 1 0 -98; asc 65 0; vstr and str as below; substr, strupr, strlwr.
    CHECK(floatOf("strcmp(\"abc\", \"abd\")") == -1);
    CHECK(floatOf("strcmp(\"b\", \"a\")") == 1);
    CHECK(floatOf("strcmp(\"abc\", \"abc\")") == 0);
    CHECK(floatOf("strcmp(\"a\", \"abc\")") == -98);
    CHECK(floatOf("asc(\"A\")") == 65);
    CHECK(floatOf("asc(\"\")") == 0);
    const auto lines = debugOf(R"(
        #debug vstr(3, <1, 2, 3>, ", ", 0, 2)
        #debug vstr(2, 5, "/", 4, 1)
        #debug vstr(7, <1, 2, 3, 4, 5>, ",", -3, -1)
        #debug concat(substr("hello", 2, 3), strupr("aBc"), strlwr("XyZ"))
        #debug concat(str(1.5, -6, 2), "|", str(2, 0, -1), "|", str(-3.14159, 8, 3))
    )");
    CHECK(lines == std::vector<std::string>{"1.00, 2.00, 3.00", " 5.0/ 0.0",
                                            "1.000000,2.000000,3.000000,4.000000,5.000000", "ellABCxyz",
                                            "001.50|2.000000|  -3.142"});
    CHECK_THAT(run("#declare S = substr(\"abc\", 3, 2);").errors(), Contains("not within the string's 3 characters"));
    CHECK_THAT(run("#declare S = str(1, 0, 1e20);").errors(), Contains("the precision of str() must be a whole number"));
}

TEST_CASE("the clock's values when not animating", "[lang][clock]") {
    // povray, one frame: all 0; clock_on is 1 when the clock is given (+K).
    CHECK(floatOf("frame_number + initial_frame + final_frame + initial_clock + final_clock + clock_delta + clock_on") == 0);
    InterpreterOptions given;
    given.clock = 0.5;
    given.clockOn = true;
    Run r = run("sphere { <clock_on, clock, 0>, 1 }", given);
    CHECK(std::get<SphereShape>(ok(r).objects[0].shape).center == Vec3(1, 0.5, 0));
}

TEST_CASE("the clock's values of an animation's frame", "[lang][clock]") {
    // povray +KFI1 +KFF3 +KI2 +KF3, its second frame: each word reads its own option.
    InterpreterOptions frame;
    frame.clock = 2.5;
    frame.clockOn = true;
    frame.frameNumber = 2;
    frame.initialFrame = 1;
    frame.finalFrame = 3;
    frame.initialClock = 2;
    frame.finalClock = 3;
    frame.clockDelta = 0.5;
    Run r = run("sphere { <frame_number, initial_frame, final_frame>, clock }\n"
                "sphere { <initial_clock, final_clock, clock_delta>, clock_on }\n", frame);
    const auto& scene = ok(r);
    REQUIRE(scene.objects.size() == 2);
    CHECK(std::get<SphereShape>(scene.objects[0].shape).center == Vec3(2, 1, 3));
    CHECK(std::get<SphereShape>(scene.objects[0].shape).radius == 2.5);
    CHECK(std::get<SphereShape>(scene.objects[1].shape).center == Vec3(2, 3, 0.5));
    CHECK(std::get<SphereShape>(scene.objects[1].shape).radius == 1);
}

TEST_CASE("#default changes what textures start from", "[lang][default]") {
    Run r = run("sphere { 0, 1 }\n"
                "#default { finish { phong 0.5 } }\n"
                "#declare Later = sphere { 0, 1 }\n"
                "#default { pigment { rgb <1, 0, 0> } }\n"
                "object { Later }\n"                              // takes the default when placed
                "box { 0, 1 texture { finish { diffuse 0.9 } } }\n"  // a texture starts from it
                "default { texture { pigment { rgb 1 } } }\n"
                "cylinder { 0, y, 1 }\n");
    const auto& scene = ok(r);
    REQUIRE(scene.objects.size() == 4);
    CHECK(scene.objects[0].texture->finish.phong == 0);
    CHECK(scene.objects[1].texture->finish.phong == 0.5);
    CHECK(scene.objects[1].texture->pigment.color1.rgb == Vec3(1, 0, 0));
    CHECK(scene.objects[2].texture->finish.phong == 0.5);
    CHECK(scene.objects[2].texture->finish.diffuse == 0.9);
    CHECK(scene.objects[3].texture->pigment.color1.rgb == Vec3(1));
    CHECK(scene.objects[3].texture->finish.phong == 0.5);
}
