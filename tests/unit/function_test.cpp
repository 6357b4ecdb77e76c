// User-defined functions (lang/functions.cpp, scene/function_program.cpp):
// known answers for expressions, default and named parameters, functions of
// functions, captured values, sum/prod, the located errors, the refused kinds
// (refused where used, not where declared), and the function pattern's values.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "asos/render/map_pattern.hpp"
#include "asos/scene/function_text.hpp"
#include "interpret_text.hpp"

using namespace asos;
using asos::test::floatOf;
using asos::test::ok;
using asos::test::run;

TEST_CASE("functions give POV-Ray's values", "[function]") {
    CHECK(floatOf("F(1, 2, 3)", "#declare F = function { x + 2*y + 3*z };") == 14.0);
    CHECK(floatOf("F(2, 5)", "#declare F = function(a, b) { a*a - b };") == -1.0);
    CHECK(floatOf("F(1, 2)", "#declare F = function(x, y) { x - y };") == -1.0);
    // u and v are x and y among the default parameters.
    CHECK(floatOf("F(4, 7, 0)", "#declare F = function { u * 10 + v };") == 47.0);
    CHECK(floatOf("F(3)", "#declare F = function(a) { pow(a, 2) + sqrt(16) + abs(-1) + pi - pi };") == 14.0);
    CHECK(floatOf("F(0.5)", "#declare F = function(a) { sin(a) };") == Approx(std::sin(0.5)));
    CHECK(floatOf("F(7, 2)", "#declare F = function(a, b) { mod(a, b) + div(a, b) * 10 + floor(-0.5) };") == 30.0);
    CHECK(floatOf("F(2)", "#declare F = function(a) { min(5, a, 3) + max(1, a, 0, -4) };") == 4.0);
    CHECK(floatOf("F(1)", "#declare F = function(a) { atan2(a, 1) * 4 };") == Approx(std::numbers::pi));
}

TEST_CASE("comparisons, logic and select in functions", "[function]") {
    const char* d = "#declare F = function(a) { (a < 0) + 2*(a = 0) + 4*(a > 0 & a < 2) + 8*(a > 5 | a < -5) };";
    CHECK(floatOf("F(-1)", d) == 1.0);
    CHECK(floatOf("F(0)", d) == 2.0);
    CHECK(floatOf("F(1)", d) == 4.0);
    CHECK(floatOf("F(9)", d) == 8.0);
    CHECK(floatOf("F(-9)", d) == 9.0);
    // Comparisons need no parentheses inside a function, as in POV-Ray.
    CHECK(floatOf("F(3)", "#declare F = function(a) { a > 2 };") == 1.0);
    CHECK(floatOf("F(-2)", "#declare F = function(a) { select(a, 1, 2) };") == 1.0);
    CHECK(floatOf("F(0)", "#declare F = function(a) { select(a, 1, 2, 3) };") == 2.0);
    CHECK(floatOf("F(4)", "#declare F = function(a) { select(a, 1, 2, 3) };") == 3.0);
}

TEST_CASE("functions call functions, and capture floats when declared", "[function]") {
    const char* d = "#declare K = 10;\n"
                    "#declare G = function(a, b) { a * K + b };\n"
                    "#declare K = 1000;\n"  // G keeps 10
                    "#declare F = function { G(x, y) + G(z, 0) };";
    CHECK(floatOf("F(1, 2, 3)", d) == 42.0);
    CHECK(floatOf("G(1, 2)", d) == 12.0);
    // A part that needs no parameter is computed once: vectors may serve there.
    CHECK(floatOf("F(2)", "#declare V = <1, 2, 3>; #declare F = function(a) { a * V.y + vlength(<3, 4, 0>) };") ==
          9.0);
    // A function passed to a macro and called there.
    CHECK(floatOf("M(function { x * 3 }, 2)", "#macro M(Fn, A) Fn(A, 0, 0) #end") == 6.0);
    // A macro whose value is a function.
    CHECK(floatOf("H(5, 0, 0)", "#macro Make(K) function { x * K } #end #declare H = Make(3);") == 15.0);
}

TEST_CASE("sum and prod run their variable over the range", "[function]") {
    CHECK(floatOf("F(4)", "#declare F = function(n) { sum(i, 1, n, i) };") == 10.0);
    CHECK(floatOf("F(5)", "#declare F = function(n) { prod(i, 1, n, i) };") == 120.0);
    CHECK(floatOf("F(0)", "#declare F = function(n) { sum(i, 1, n, i) + prod(j, 1, n, 7) };") == 1.0);
    CHECK(floatOf("F(3)", "#declare F = function(n) { sum(i, 1, n, sum(j, 1, i, i * j)) };") == 1 + (2 + 4) + (3 + 6 + 9));
    CHECK(floatOf("F(2)", "#declare F = function(n) { sum(n, 1, 3, n) + n };") == 8.0);  // the variable hides n
}

namespace {
// The errors (not the warnings) of `text`, as "line:col: message" lines.
std::string errorsOf(const std::string& text) {
    const auto r = asos::test::run(text + "\nsphere { 0, 1 }");
    std::string s;
    for (const auto& d : r.diagnostics.all())
        if (d.severity == Severity::Error)
            s += std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " + d.message + "\n";
    return s;
}
}  // namespace

TEST_CASE("function errors are located", "[function]") {
    CHECK(errorsOf("#declare F = function { x + Nope };") == "1:29: 'Nope' is not declared\n");
    CHECK(errorsOf("#declare F = function(a) { a + x };") ==
          "1:32: 'x' is not a parameter of this function (its parameters are a)\n");
    CHECK(errorsOf("#declare F = function(a) { a };\n#declare B = F(1, 2);") ==
          "2:14: 'F' takes 1 argument, not 2\n");
    CHECK(errorsOf("#declare G = function(a) { a };\n#declare F = function { G(x, y) };") ==
          "2:25: 'G' takes 1 argument, not 2\n");
    CHECK(errorsOf("#declare F = function { F(x, y, z) + 1 };") ==
          "1:25: a function cannot call itself: 'F' is the function being declared (POV-Ray's functions are not "
          "recursive)\n");
    CHECK(errorsOf("#declare F = function(a, a) { a };") == "1:26: the parameter 'a' is named twice\n");
    CHECK(errorsOf("#declare F = function { vlength(<x, y, z>) };") ==
          "1:25: 'vlength' is not allowed in a function: POV-Ray's functions take and give floats only\n");
    // What POV-Ray's function parser refuses.
    CHECK(errorsOf("#declare F = function { x > 0 ? 1 : 2 };") ==
          "1:31: '?:' is not allowed in a function, as in POV-Ray\n");
    CHECK(errorsOf("#declare F = function { !x };") == "1:25: '!' is not allowed in a function, as in POV-Ray\n");
    CHECK(errorsOf("#declare F = function { sqr(x) };") ==
          "1:25: 'sqr' is not allowed in a function, as in POV-Ray\n");
    CHECK(errorsOf("#declare F = function { x + true };") ==
          "1:29: 'true' is not allowed in a function, as in POV-Ray\n");
    CHECK(errorsOf("#declare F = function { \"s\" };") == "1:25: a function holds floats only; this is a string\n");
    CHECK(errorsOf("#declare B = sum(i, 1, 2, i);") ==
          "1:14: 'sum' is allowed only inside a function { … }, as in POV-Ray\n");
    CHECK(errorsOf("#declare F = function { sqrt(x) };\n#declare B = F(-1, 0, 0);") ==
          "2:14: 'F': the result is not a finite number (nan)\n");
}

TEST_CASE("internal, pigment and pattern functions are refused where used", "[function]") {
    // Declaring them (functions.inc does) is fine.
    const char* d = "#declare f_noise3d = function { internal(76) }\n"
                    "#declare f_snoise3d = function { 2*f_noise3d(x, y, z) - 1 }\n"
                    "#declare f_gradientX = function { pattern { gradient x } }\n"
                    "#declare f_pig = function { pigment { checker color rgb 0, color rgb 1 } }\n";
    CHECK(errorsOf(d).empty());
    CHECK(errorsOf(std::string(d) + "#declare B = f_snoise3d(1, 2, 3);") ==
          "5:14: 'internal' is not supported by asos (the function { internal(76) } declared at t.pov:1:22), called "
          "here as 'f_snoise3d'\n");
    CHECK(errorsOf(std::string(d) + "#declare B = f_gradientX(1, 2, 3);") ==
          "5:14: 'pattern' in a function is not supported by asos (the function { pattern { … } } declared at "
          "t.pov:3:24), called here as 'f_gradientX'\n");
    CHECK(errorsOf(std::string(d) + "#declare G = function { f_pig(x, y, z).gray }\n#declare B = G(1, 2, 3);") ==
          "6:14: 'pigment' in a function is not supported by asos (the function { pigment { … } } declared at "
          "t.pov:4:18), called here as 'G'\n");
    CHECK(errorsOf("#declare F = function { x }\n#declare G = function { F(x, y, z).x }") ==
          "2:35: '.x' needs a vector; a float function's value has no members\n");
    CHECK(errorsOf(std::string(d) + "plane { y, 0 pigment { function { f_pig(x, y, z) } } }") ==
          "5:35: 'pigment' in a function is not supported by asos (the function { pigment { … } } declared at "
          "t.pov:4:18)\n");
}

TEST_CASE("the function pattern takes the function's value, wrapped as POV-Ray's", "[function][pattern]") {
    const auto r = run("#declare F = function { x * 0.5 + y }\n"
                       "plane { z, 0 pigment { function { F(x, y, z) } color_map { [0 rgb 0] [1 rgb 1] } } }");
    const auto& scene = ok(r);
    REQUIRE(scene.objects.size() == 1);
    const Pigment& p = scene.objects[0].texture->pigment;
    REQUIRE(p.kind == Pigment::Kind::Function);
    CHECK(mapPatternValue(p, Vec3(0.5, 0.25, 0.0)) == Approx(0.5));
    CHECK(mapPatternValue(p, Vec3(0.0, 1.0, 0.0)) == Approx(1.0));           // 1 stays 1
    CHECK(mapPatternValue(p, Vec3(0.0, 1.25, 0.0)) == Approx(0.25));         // above 1: wrapped
    CHECK(mapPatternValue(p, Vec3(0.0, -0.25, 0.0)) == Approx(0.75));        // below 0: as the wave wraps it
    const std::string xyz[] = {"x", "y", "z"};
    CHECK(functionText(*p.function, xyz) == "((x * 0.5) + y)");
}
