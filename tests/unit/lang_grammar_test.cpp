// The grammar alone: no cycles without progress, and tables of accepted and
// rejected inputs for each family of rules. (Tests may include PEGTL; in src/
// only src/lang/parse.cpp does.)
#include <catch2/catch.hpp>

#include <string>
#include <tao/pegtl/contrib/analyze.hpp>

#include "grammar/errors.hpp"

namespace g = asos::grammar;
namespace pegtl = tao::pegtl;

namespace {

// Whether `text` is exactly one `Rule` (plus trailing space). Errors raised
// by must<> count as rejection.
template <typename Rule>
bool accepts(const std::string& text) {
    pegtl::memory_input in(text, "test");
    try {
        return pegtl::parse<pegtl::seq<Rule, pegtl::eof>, pegtl::nothing, g::control>(in);
    } catch (const pegtl::parse_error&) {
        return false;
    }
}

template <typename Rule>
void checkTable(std::initializer_list<const char*> good, std::initializer_list<const char*> bad) {
    for (const char* text : good) {
        INFO("accepted: " << text);
        CHECK(accepts<Rule>(text));
    }
    for (const char* text : bad) {
        INFO("rejected: " << text);
        CHECK_FALSE(accepts<Rule>(text));
    }
}

}  // namespace

TEST_CASE("the grammar has no loops without progress", "[lang][grammar]") {
    CHECK(pegtl::analyze<g::scene_file>(false) == 0);
    CHECK(pegtl::analyze<g::expression_text>(false) == 0);
}

TEST_CASE("lexical rules", "[lang][grammar]") {
    checkTable<g::number_literal>({"1", "0", "12.5", ".5", "1.", "1e-3", "2.5E+10", "3e7 ", "1 // c\n"},
                                  {"", "-1", "e3", ".", "1e", "1x"});
    checkTable<g::string_literal>({R"("")", R"("abc")", R"("a\"b")", R"("tab\there" )"},
                                  {R"("abc)", "\"a\nb\"", "abc"});
    checkTable<g::skip>({"", " \t\r\n", "// line\n", "/* block */", "/* nested /* inner */ outer */",
                         "// no newline at the end"},
                        {"/* unterminated", "/* nested /* inner */ unterminated", "x"});
    checkTable<g::name>({"Foo", "_x1", "spheres", "sphere_2", "MyRed", "eps", "asos"},
                        {"sphere", "x", "pigment", "isosurface", "1abc", "rgb", "max"});
}

TEST_CASE("keywords never match the front of a longer identifier", "[lang][grammar]") {
    checkTable<g::kw_sphere>({"sphere", "sphere ", "sphere/*c*/"}, {"spheres", "sphere_", "Sphere"});
    checkTable<g::kw_color>({"color", "colour"}, {"colors", "colour_map"});
    checkTable<g::constant>({"x", "pi", "clock", "on", "off", "image_width"}, {"xx", "pie", "Pi"});
    checkTable<g::function_name>({"sin", "vrotate", "max"}, {"sine", "vrotation"});
}

TEST_CASE("expressions", "[lang][grammar]") {
    checkTable<g::expression>(
        {"1", "-1", "1+2*3", "(1+2)*3", "<1,2,3>", "<1, 2>", "<1,2,3,4,5>", "x*2 + <0,1,0>",
         "sin(pi/2)", "max(1, 2, 3)", "V.x", "C.red", "rgb <1,0,0>", "rgb 1", "color Red",
         "color red 1 green .5", "colour rgb <1,0,0> filter 0.5", "rgbft <1,1,1,0,0>", "!A",
         "(A < B)", "(A <= B & C != D | E)", "(A ? 1 : 2)", "(1 ? 0 ? 5 : 6 : 7)", "\"str\"",
         "concat(\"a\", str(1, 0, 2))", "<(1 > 0), 0, 0>", "-(-x)", "A.x.y",
         "rgb <1,0,0> green 1", "red 1 blue 1 filter 0", "color Red green 1 transmit 0.5"},
        {"", "1 +", "(1", "<1,2", "<1,,2>", "sin 1", "sin()", "V.", "V.w", "A < B", "color", "rgb",
         "(A ? 1)", "1 * * 2",
         // As in POV-Ray, a whole colour only opens a colour: these are two values.
         "rgb 1 rgb 0", "rgb <1,0,0> green 1 rgb 0", "red 1 rgb 0", "color Red rgb 1", "color rgb 1 color 0"});
}

TEST_CASE("directives", "[lang][grammar]") {
    using top = g::entries<g::top_entry>;
    checkTable<top>(
        {"#declare A = 1;", "#local B = <1,2,3>;", "#declare S = sphere { 0, 1 }",
         "#declare S = sphere { 0, 1 };", "#declare P = pigment { rgb 1 }", "#undef A",
         "#include \"colors.inc\"", "#version 3.7;", "#version 3.7", "#debug \"hi\\n\"",
         "#warning \"w\"", "#error \"e\"", "#if (1) #end", "#if (A) sphere {0,1} #else box {0,1} #end",
         "#if (A) #elseif (B) #elseif (C) #else #end", "#ifdef (A) #end", "#ifndef (A) #else #end",
         "#while (I < 3) #declare I = I + 1; #end", "#for (I, 1, 10) #end", "#for (I, 10, 1, -1) #end",
         "# declare A = 1;", "#if (1) #if (2) #end #end", "#declare S = \"no ';' after a string\"",
         "#declare S = concat(\"a\", \"b\") #declare T = str(1, 0, 0)", "sphere { 0, 1 # }", "#"},
        {"#declare A = 1", "#declare = 1;", "#declare sphere = 1;", "#if 1 #end", "#if (1)",
         "#while (1)", "#for (I, 1) #end", "#undef", "#include", "#end", "#else"});
}

TEST_CASE("file directives", "[lang][grammar][files]") {
    using top = g::entries<g::top_entry>;
    checkTable<top>(
        {"#fopen F \"a.txt\" read", "#fopen F concat(\"a\", \".txt\") write", "#fopen F \"a\" append",
         "#fclose F", "#read (F, A, B)", "#read (F A B)", "#read (F)", "#read (F, A,)",
         "#write (F, \"x\", 1, <1,2,3>, \"\\n\")", "#write (F \"x\" -1 \"y\")", "#write (F)",
         "#write (F, str(1, 0, 0) \",\" V.x)", "#if (file_exists(\"a.txt\")) #end"},
        {"#fopen F \"a.txt\"", "#fopen F \"a.txt\" READ", "#fopen \"a.txt\" read", "#fopen sphere \"a\" read",
         "#fclose", "#read F, A", "#read (F, A[1])", "#read (F, 1)", "#read (F, A", "#write F, 1",
         "#write (F, 1", "#write (F, sphere { 0, 1 })", "#read (, A)"});
}

TEST_CASE("objects and scene items", "[lang][grammar]") {
    using top = g::entries<g::top_entry>;
    checkTable<top>(
        {"sphere { <0,0,0>, 1 }", "sphere { 0 1 }", "sphere { <0,1,0>, .5 translate x }",
         "box { <0,0,0>, <1,1,1> }", "cone { 0, 1, y, 0 open }", "cone { 0 1 y 0 }",
         "cylinder { 0, y, 1 open }", "disc { 0, y, 1 }", "disc { 0, y, 2, 1 }",
         "polygon { 4, <0,0>, <1,0>, <1,1>, <0,1> }", "polygon { 3 <0,0> <1,0> <0,1> }",
         "plane { y, 0 }", "union { sphere { 0, 1 } box { 0, 1 } pigment { rgb 1 } }",
         "quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 }", "quadric { 1 0 0, -1 translate y }",
         "torus { 1, 0.5 }", "torus { 1 0.5 sturm translate y }", "triangle { 0, x, y }",
         "poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> }", "poly { 2 <1 0 0 0 1 0 0 1 0 -1> sturm }",
         "quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 56, "
         "0, 0, 0, 0, 1, 0, -104, 0, 784> sturm translate y }",
         "cubic { <0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0> }",
         "smooth_triangle { 0, z, x, z, y, z pigment { rgb 1 } }",
         "mesh { triangle { 0, x, y } smooth_triangle { 0 z x z y z } translate x }",
         "mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } }",
         "mesh2 { vertex_vectors { 3 0 x y } normal_vectors { 1 z } face_indices { 1 <0 1 2> } "
         "normal_indices { 1 <0 0 0> } scale 2 }",
         "sphere { 0, 1 texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } } }",
         "object { Thing translate x }", "object { sphere { 0, 1 } scale 2 }",
         "light_source { <0,10,0>, rgb 1 }", "light_source { <0,10,0> color White shadowless }",
         "light_source { 0, 1 area_light x, z, 4, 4 adaptive 1 jitter circular orient }",
         "light_source { 0, 1 fade_distance 2 fade_power 2 asos { eps 0.1 } }",
         "light_source { 0, 1 area_light x, z, 4, 4 area_illumination }",
         "light_source { 0, 1 area_light x, z, 4, 4 area_illumination off jitter }",
         "light_source { 0, 1 area_illumination asos { emitter panel } }",
         "light_source { 0, 1 asos { eps 0.1 emitter povray } }",
         "camera { location <0,1,-5> look_at 0 angle 60 }", "camera { orthographic right x up y }",
         "camera { perspective location 0 direction z sky y right x*4/3 up y rotate <0,10,0> }",
         "global_settings { assumed_gamma 1 max_trace_level 5 ambient_light rgb 1 }",
         "global_settings { asos { eps 0.01 max 4 jitter on } }", "background { color rgb <0,0,1> }",
         "sphere { 0, 1 #if (A) pigment { Red } #end }",
         "union { #while (I < 3) sphere { I*x, 1 } #declare I = I + 1; #end }",
         "difference { box { 0, 1 } sphere { 0, 1 inverse } pigment { rgb 1 } }",
         "intersection { sphere { 0, 1 } plane { y, 0 } light_source { 0, 1 } }",
         "merge { sphere { 0, 1 } sphere { x, 1 } translate y inverse }"},
        {"sphere { 0 }", "difference { sphere { 0, 1 } ", "merge sphere { 0, 1 }", "intersection { inverse", "sphere { 0, 1", "sphere 0, 1", "box { 0 }", "cone { 0, 1, y }",
         "polygon { }", "union { sphere { 0, 1 } ", "camera { location }", "light_source { }",
         "spheres { 0, 1 }", "sphere { 0, 1 look_at x }", "background { }",
         "light_source { 0, 1 asos { emitter } }", "light_source { 0, 1 asos { emitter lambert } }",
         "light_source { 0, 1 area_illumination ( }", "poly { 2 }", "quartic { 1, 2 }", "poly { 2, <1, 2 }",
         "cubic { <1, 2,> }"});
}

TEST_CASE("modifiers", "[lang][grammar]") {
    using top = g::entries<g::top_entry>;
    checkTable<top>(
        {"sphere { 0, 1 pigment { rgb <1,0,0> } }", "sphere { 0, 1 pigment { Red } }",
         "sphere { 0, 1 pigment { checker Red, White scale 2 } }",
         "sphere { 0, 1 pigment { checker color Red color White } }",
         "sphere { 0, 1 pigment { checker } }", "sphere { 0, 1 pigment { brick } }",
         "sphere { 0, 1 pigment { brick Red, White brick_size <8, 3, 4.5> mortar 0.5 } }",
         "sphere { 0, 1 pigment { brick color Red color White scale 2 mortar 0.2 brick_size 1 } }",
         "sphere { 0, 1 pigment { checker mortar 0.2 } }",  // grammatical; the interpreter refuses it
         "sphere { 0, 1 finish { ambient 0.2 diffuse 0.8 phong 1 phong_size 60 } }",
         "sphere { 0, 1 finish { F specular 0.5 roughness 0.01 reflection 0.3 brilliance 2 } }",
         "sphere { 0, 1 finish { ambient rgb <0.1,0.2,0.3> reflection rgb <0.5,0.5,0.5> } }",
         "sphere { 0, 1 texture { pigment { rgb 1 } finish { phong 1 } scale 2 } }",
         "sphere { 0, 1 texture { T } }", "sphere { 0, 1 no_shadow asos { eps 1e-3 max 6 jitter off } }",
         "sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 0,0,0> }",
         "sphere { 0, 1 rotate <0,45,0> scale <1,2,1> translate -x }",
         "sphere { 0, 1 normal { bumps 0.5 scale 0.2 } }", "sphere { 0, 1 normal { granite, -0.3 turbulence 0.2 } }",
         "sphere { 0, 1 normal { N bump_size 2 } }", "sphere { 0, 1 normal { ripples Size frequency 4 phase 0.5 } }",
         "sphere { 0, 1 normal { gradient x 0.4 accuracy 0.01 sine_wave } }",
         "sphere { 0, 1 texture { normal { wrinkles } } }", "sphere { 0, 1 finish { crand 0.05 diffuse 0.7 } }",
         "sphere { 0, 1 pigment { bozo pigment_map { [0 Red] [0.5, P scale 2] [1 checker Red, White] } } }",
         "sphere { 0, 1 pigment { gradient y pigment_map { [0 wood pigment_map { [0 Red] [1 rgb 1] }] } } }",
         "sphere { 0, 1 pigment { average pigment_map { [P] [2 rgb 1] [function { x } rotate y] } } }",
         "sphere { 0, 1 pigment { bozo pigment_map { [0 #if (A) Red #else White #end] } } }",
         "sphere { 0, 1 pigment { brick pigment { Red } pigment { White } } }",
         "sphere { 0, 1 pigment { checker pigment { P scale 2 }, pigment { bozo } scale 3 } }"},
        {"sphere { 0, 1 pigment { rgb } }", "sphere { 0, 1 pigment { checker Red, } }",
         "sphere { 0, 1 pigment { brick Red, } }", "sphere { 0, 1 pigment { brick mortar } }",
         "sphere { 0, 1 pigment { brick brick_size } }",
         "sphere { 0, 1 texture { brick texture { T } texture { U } } }",
         "sphere { 0, 1 finish { phong } }",         "sphere { 0, 1 translate }", "sphere { 0, 1 asos { eps } }", "sphere { 0, 1 asos { foo 1 } }",
         "sphere { 0, 1 normal { bump_size } }", "sphere { 0, 1 normal { accuracy } }", "sphere { 0, 1 finish { crand } }",
         "sphere { 0, 1 pigment { bozo pigment_map { [0 Red } } }", "sphere { 0, 1 pigment { bozo pigment_map { 0 Red } } }",
         "sphere { 0, 1 pigment { bozo pigment_map { [0 Red]  } }", "sphere { 0, 1 normal { bozo pigment_map { } } }"});
}

TEST_CASE("macros, #switch, #break, #default", "[lang][grammar]") {
    using top = g::entries<g::top_entry>;
    checkTable<top>(
        {"#macro M() #end", "#macro M(A, B) sphere { A, B } #end", "#macro M(A B) #end",
         "#macro M() #if (1) #end #while (0) #end #end", "#macro M() \"#end\" // #end\n #end",
         "#macro M() /* #end */ #end", "#macro Outer() #macro Inner() #end #end",
         "M()", "M(1, <1,2,3>, \"s\")", "M(sphere { 0, 1 }, pigment { rgb 1 })", "M (1) M(2)",
         "M(N(1))", "sphere { 0, 1 M() }", "sphere { M(), 1 }", "sphere { 0, 1 pigment { M() } }",
         "sphere { 0, 1 pigment { M() * 0.5 } }", "#declare A = M();", "#declare A = M()",
         "#declare A = M() + 1;", "object { M() scale 2 }", "#if (M(1)) #end",
         "#switch (A) #case (1) #break #range (2, 3) #else #end", "#switch (A) #case (1) #case (2) #end",
         "#while (1) #break #end", "#default { finish { phong 1 } pigment { rgb 1 } }",
         "#default { texture { pigment { rgb 1 } } }", "default { finish { ambient 0 } }", "#default { }"},
        {"#macro M(", "#macro M() sphere { 0, 1 }", "#macro (A) #end", "#macro M(1) #end", "M(1,)", "M(,1)",
         "M(1", "#declare A = M() + ;", "#switch (A) #end", "#switch (A) #else #end", "#switch (A) #case 1 #end",
         "#switch (A) #range (1) #end", "#switch (A) #case (1)", "#default { sphere { 0, 1 } }",
         "#default finish { }"});
}

TEST_CASE("arrays and subscripts", "[lang][grammar]") {
    using top = g::entries<g::top_entry>;
    checkTable<top>(
        {"#declare A = array[3];", "#declare A = array[3]", "#declare A = array[2][3];",
         "#declare A = array[3] {1, 2, 3};", "#declare A = array[3] {1 2 3}", "#declare A = array[2][2] {{1,2},{3,4}}",
         "#declare A = array[2] { sphere { 0, 1 }, box { 0, 1 } }", "#declare A[1] = 2;", "#declare A[I][J + 1] = x;",
         "#local A[0] = 1;", "sphere { A[1], B[1][2] }", "#ifdef (A[1]) #end", "#declare D = defined(A[0]);",
         "object { Shapes[2] }", "sphere { 0, 1 texture { T[1] } }", "#declare B = A", "#declare N = dimension_size(A, 1);"},
        {"#declare A = array;", "#declare A = array[];", "#declare A = array[3;", "#declare A = array[2] {1, 2",
         "#declare A[ = 1;", "#declare A[1 = 1;", "sphere { A[, 1 }", "#declare B = A + 1"});
}
