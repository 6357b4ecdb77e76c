// Macros, #switch and #break: known answers, most checked against `povray`
// 3.7 with #debug (the scenes of the comments print the same values there).
#include <catch2/catch.hpp>

#include <filesystem>

#include "asos/lang/parse.hpp"
#include "interpret_text.hpp"

using namespace asos;
using namespace asos::lang;
using namespace asos::test;
using Catch::Matchers::Contains;

TEST_CASE("a macro's value", "[lang][macro]") {
    CHECK(floatOf("Twice(3) + 1", "#macro Twice(V) (2 * V) #end") == 7);
    CHECK(floatOf("Twice(3) + 1", "#macro Twice(V) 2 * V #end") == 7);  // an operand as a whole
    const std::string fact = "#macro Fact(N) #if (N <= 1) 1 #else N * Fact(N - 1) #end #end";
    CHECK(floatOf("Fact(5)", fact) == 120);
    CHECK(floatOf("Mean(2, 4)", "#macro Mean(A, B) #local S = A + B; S / 2 #end") == 3);
    CHECK(valueOf("#macro V(A) <A, 2 * A, 3> #end", "V(1) + x") == Vec3(2, 2, 3));
    // A macro that gives an object, a texture, a string.
    Run r = run("#macro Ball(R) sphere { 0, R } #end\n"
                "#macro Red() texture { pigment { rgb <1, 0, 0> } } #end\n"
                "#macro Name() concat(\"a\", \"b\") #end\n"
                "#declare B = Ball(2)\n"
                "object { B Red() }\n"
                "object { Ball(strlen(Name())) }\n");
    const auto& scene = ok(r);
    REQUIRE(scene.objects.size() == 2);
    CHECK(std::get<SphereShape>(scene.objects[0].shape).radius == 2);
    CHECK(scene.objects[0].texture->pigment.color1.rgb == Vec3(1, 0, 0));
    CHECK(std::get<SphereShape>(scene.objects[1].shape).radius == 2);
}

TEST_CASE("a macro's body is read as entries of the block it is called in", "[lang][macro]") {
    Run r = run("#macro Up(H) translate H * y #end\n"
                "#macro Items() ambient 0.3 phong 1 #end\n"
                "#macro Two() sphere { 0, 1 } box { 0, 1 } #end\n"
                "#macro Light() light_source { 0, 1 } #end\n"
                "#macro Look() location -5 * z look_at 0 #end\n"
                "union { Two() Up(2) }\n"
                "sphere { 0, 1 Up(1) finish { Items() } }\n"
                "Light()\n"
                "camera { Look() }\n");
    const auto& scene = ok(r);
    REQUIRE(scene.objects.size() == 3);
    CHECK(scene.objects[0].worldFromObject.point(Vec3(0)) == Vec3(0, 2, 0));
    CHECK(scene.objects[1].worldFromObject.point(Vec3(0)) == Vec3(0, 2, 0));
    CHECK(scene.objects[2].worldFromObject.point(Vec3(0)) == Vec3(0, 1, 0));
    CHECK(scene.objects[2].texture->finish.phong == 1);
    CHECK(scene.lights.size() == 1);
    CHECK(scene.camera.location == Vec3(0, 0, -5));
}

TEST_CASE("macro arguments: by value, and a bare identifier by reference", "[lang][macro]") {
    // povray: Q=2, Z not global, P in G=7, Q after G=7, Q after H=7, W=5.
    const auto lines = debugOf(R"(
        #declare Q = 1;
        #macro M(A) #declare A = A + 1; #end
        M(Q)
        #debug concat("Q=", str(Q, 0, 0))
        #macro F() #local Z = 1; #declare Z = 2; #end
        F()
        #ifdef (Z) #debug "Z global" #else #debug "Z not global" #end
        #macro G(P) #local P = 7; #debug concat("P in G=", str(P, 0, 0)) #end
        G(Q)
        #debug concat("Q after G=", str(Q, 0, 0))
        #macro H(P) #declare P = 9; #end
        H(Q + 0)
        #debug concat("Q after H=", str(Q, 0, 0))
        #declare W = 1;
        #macro K() #declare W = 5; #end
        K()
        #debug concat("W=", str(W, 0, 0))
    )");
    CHECK(lines == std::vector<std::string>{"Q=2", "Z not global", "P in G=7", "Q after G=7", "Q after H=7", "W=5"});
    // Passed on through a second macro; an array's element through its array.
    CHECK(floatOf("X", "#declare X = 1;\n#macro Inner(B) #declare B = 10; #end\n"
                       "#macro Outer(A) Inner(A) #end\nOuter(X)") == 10);
    CHECK(floatOf("Arr[1]", "#declare Arr = array[2] {1, 2};\n#macro Set(A) #declare A[1] = 5; #end\nSet(Arr)") == 5);
}

TEST_CASE("macro scopes: #local per call, dynamic, recursion", "[lang][macro]") {
    // The body sees its caller's locals; its own vanish with the call.
    CHECK(floatOf("Outer()", "#macro Inner() L * 2 #end\n#macro Outer() #local L = 4; Inner() #end") == 8);
    Run r = run("#macro Leaf(N) #local Here = N; sphere { 0, Here } #end\n"
                "Leaf(1)\n#ifdef (Here) #error \"leaked\" #end\n");
    ok(r);
    // Each recursive call has its own parameters, evaluated in its caller.
    CHECK(floatOf("Sum(4)", "#macro Sum(N) #if (N = 0) 0 #else N + Sum(N - 1) #end #end") == 10);
    // A macro defines a macro when called; a macro may be redefined and #undef'd.
    CHECK(floatOf("Made()", "#macro Maker() #macro Made() 3 #end #end\nMaker()") == 3);
    CHECK(floatOf("Two()", "#macro Two() 1 #end\n#macro Two() 2 #end") == 2);
    Run undef = run("#macro Gone() 1 #end\n#undef Gone\n#declare A = Gone();\n");
    CHECK_THAT(undef.errors(), Contains("'Gone' is not declared"));
    // #break returns from the macro.
    CHECK(floatOf("Early(1)", "#macro Early(A) #if (A) 5 #break #end 6 #end") == 5);
}

TEST_CASE("macro errors", "[lang][macro]") {
    CHECK_THAT(run("#macro M(A) sphere { 0, A } #end\nM()").errors(), Contains("2:1: the macro 'M' takes 1 argument, not 0"));
    CHECK_THAT(run("#declare A = 1;\nA(2)").errors(), Contains("2:1: 'A' is a float, not a macro"));
    CHECK_THAT(run("#macro M() #end\n#declare X = M();").errors(),
               Contains("2:14: the macro 'M' gives no value, and one is wanted here"));
    CHECK_THAT(run("#macro M() 1 2 #end\n#declare X = M();").errors(),
               Contains("1:14: the macro 'M' gives a second value here; one is wanted"));
    CHECK_THAT(run("#macro M(A, A) #end").errors(), Contains("two parameters named 'A'"));
    // An error in the body carries the call as its context.
    Run r = run("#macro M() sphere { 0, -1 } #end\n\nM()");
    REQUIRE(r.diagnostics.all().size() == 1);
    const Diagnostic& d = r.diagnostics.all()[0];
    CHECK(d.loc.line == 1);
    REQUIRE(d.context.size() == 1);
    CHECK(d.context[0].what == "in macro M called at");
    CHECK(d.context[0].loc.line == 3);
    CHECK(d.context[0].loc.column == 1);
}

TEST_CASE("runaway recursion ends in a located error, not the end of the stack", "[lang][macro]") {
    Run r = run("#macro F(N) union { #if (1) sphere { <F(N + 1), 0, 0>, 1 } #end } #end\nF(0)");
    CHECK_FALSE(r.scene);
    REQUIRE(r.diagnostics.hasErrors());
    const Diagnostic& d = r.diagnostics.all()[0];
    CHECK_THAT(d.message, Contains("nested too deep"));
    CHECK_THAT(d.message, Contains(std::to_string(kMaxNesting)));
    // The chain shows its ends: 5 innermost calls, a count, 5 outermost.
    REQUIRE(d.context.size() == 11);
    CHECK_THAT(d.context[5].what, Contains("more"));
    CHECK(d.context.back().loc.line == 2);
}

TEST_CASE("#switch runs on from the clause that holds until #break", "[lang][switch]") {
    const std::string pick = R"(
        #macro Pick(V)
          #local R = "";
          #switch (V)
            #case (1) #local R = concat(R, "1");
            #case (2) #local R = concat(R, "2"); #break
            #range (3, 4) #local R = concat(R, "r");
            #else #local R = concat(R, "e");
          #end
          R
        #end)";
    auto pickOf = [&](const std::string& v) { return debugOf(pick + "\n#debug Pick(" + v + ")").at(0); };
    CHECK(pickOf("1") == "12");
    CHECK(pickOf("2") == "2");
    CHECK(pickOf("1 + 1e-11") == "12");  // #case compares with POV-Ray's epsilon
    CHECK(pickOf("3") == "re");          // no #break: on into #else
    CHECK(pickOf("4") == "re");          // #range includes its ends
    CHECK(pickOf("4.001") == "e");
    CHECK(pickOf("0") == "e");
}

TEST_CASE("#break leaves #while and #for, and #for compares with POV-Ray's epsilon", "[lang][switch]") {
    CHECK(floatOf("I", "#declare I = 0;\n#while (1) #if (I = 3) #break #end #declare I = I + 1; #end") == 3);
    CHECK(floatOf("N", "#declare N = 0;\n#for (J, 0, 9) #declare N = N + 1; #if (J = 4) #break #end #end") == 5);
    // povray: 0, 0.1, 0.2, 0.30000000000000004; and a loop ending 1e-11 short still runs.
    CHECK(floatOf("N", "#declare N = 0;\n#for (I, 0, 0.3, 0.1) #declare N = N + 1; #end") == 4);
    CHECK(floatOf("N", "#declare N = 0;\n#for (I, 1, 1 - 1e-11) #declare N = N + 1; #end") == 1);
    CHECK(floatOf("N", "#declare N = 0;\n#for (I, 1, 0) #declare N = N + 1; #end") == 0);
}

TEST_CASE("POV-Ray's own macros give POV-Ray's numbers", "[lang][macro]") {
    // rand.inc, strings.inc, arrays.inc and colors.inc, as installed with POV-Ray
    // (scripts/setup.sh); povray 3.7 prints the same lines.
    const std::filesystem::path includes = "/usr/share/povray-3.7/include";
    REQUIRE(std::filesystem::is_directory(includes));
    InterpreterOptions options;
    options.libraryPaths = {includes};
    Run r = run(R"(
        #include "colors.inc"
        #include "strings.inc"
        #include "rand.inc"
        #include "arrays.inc"
        #declare R = seed(7);
        #debug concat(Str(RRand(1, 2, R)), " ", VStr(VRand(R)), " ", Str(Rand_Normal(0, 1, R)))
        #debug CRGBStr(CHSL2RGB(<200, 0.5, 0.5>), 0, 4)
        #declare A = array[5] {5, 3, 9, 1, 7};
        Sort_Array(A)
        #debug concat(Str(A[0]), Str(A[1]), Str(A[4]))
        #debug VStr(VRand_In_Sphere(R))
        #debug CRGBFTStr(Red, 0, 2)
        sphere { 0, 1 }
    )", options);
    ok(r);
    std::vector<std::string> lines;
    for (const auto& d : r.diagnostics.all())
        if (d.severity == Severity::Debug) lines.push_back(d.message);
    CHECK(lines == std::vector<std::string>{"1.953933 <0.610466,0.166852,0.034867> -0.271535",
                                            "color rgb <   0.2500, 0.5833, 0.7500>", "1.0000003.0000009.000000",
                                            "<0.189713,-0.563139,0.511525>",
                                            "color rgbft < 1.00, 0.00, 0.00, 0.00, 0.00>"});
}
