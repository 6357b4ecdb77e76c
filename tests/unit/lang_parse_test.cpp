// The parser: the trees it builds, and the syntax errors it reports (with the
// location of the offending token and what it found there).
#include <catch2/catch.hpp>

#include <string>

#include "asos/lang/parse.hpp"

using namespace asos;
using namespace asos::lang;

namespace {

struct Parsed {
    std::optional<Ast> ast;
    Diagnostics diagnostics;
    NameTable names;
};

std::unique_ptr<Parsed> parse(const std::string& text) {
    auto p = std::make_unique<Parsed>();
    p->ast = parseScene(text, std::make_shared<const std::string>("t.pov"), p->names, p->diagnostics);
    return p;
}

// "line:col: message" of the one error.
std::string errorOf(const std::string& text) {
    auto p = parse(text);
    REQUIRE_FALSE(p->ast);
    REQUIRE(p->diagnostics.all().size() == 1);
    const Diagnostic& d = p->diagnostics.all().front();
    return std::to_string(d.loc.line) + ":" + std::to_string(d.loc.column) + ": " + d.message;
}

}  // namespace

TEST_CASE("a sphere becomes a block with two positional arguments", "[lang][parse]") {
    auto p = parse("sphere { <1, 2, 3>, 0.5 translate x }");
    REQUIRE(p->ast);
    const Node& root = p->ast->root;
    REQUIRE(root.kind == NodeKind::Sequence);
    REQUIRE(root.count == 1);
    const Node& sphere = root[0];
    CHECK(sphere.kind == NodeKind::Block);
    CHECK(sphere.word == Word::Sphere);
    CHECK(sphere.flags == 2);
    REQUIRE(sphere.count == 3);
    CHECK(sphere[0].kind == NodeKind::Vector);
    CHECK(sphere[0].count == 3);
    CHECK(sphere[0][2].number == 3.0);
    CHECK(sphere[1].kind == NodeKind::Number);
    CHECK(sphere[1].number == 0.5);
    CHECK(sphere[2].kind == NodeKind::Item);
    CHECK(sphere[2].word == Word::Translate);
    CHECK(sphere[2][0].kind == NodeKind::Constant);
    CHECK(sphere[2][0].word == Word::X);
    CHECK(sphere.line == 1);
    CHECK(sphere.column == 1);
    CHECK(sphere[1].column == 21);
}

TEST_CASE("operators follow POV-Ray's precedence", "[lang][parse]") {
    auto p = parse("#declare A = 1 + 2 * -3;");
    REQUIRE(p->ast);
    const Node& declare = p->ast->root[0];
    REQUIRE(declare.kind == NodeKind::Declare);
    CHECK(p->names.name(declare[0].id) == "A");
    const Node& sum = declare[1];
    REQUIRE(sum.kind == NodeKind::Binary);
    CHECK(sum.word == Word::OpAdd);
    const Node& product = sum[1];
    CHECK(product.word == Word::OpMul);
    CHECK(product[1].kind == NodeKind::Unary);

    auto q = parse("#if (A < 2 & B | !C) #end");
    REQUIRE(q->ast);
    const Node& condition = q->ast->root[0][0];
    CHECK(condition.word == Word::OpOr);
    CHECK(condition[0].word == Word::OpAnd);
    CHECK(condition[0][0].word == Word::OpLess);
}

TEST_CASE("plain and general vectors give the same tree", "[lang][parse]") {
    auto a = parse("#declare V = <1, -2.5, 3e2>;");
    auto b = parse("#declare V = <1, -(2.5), 3e2 + 0>;");
    REQUIRE(a->ast);
    REQUIRE(b->ast);
    const Node& v = a->ast->root[0][1];
    REQUIRE(v.kind == NodeKind::Vector);
    REQUIRE(v.count == 3);
    CHECK(v[1].number == -2.5);
    CHECK(v[2].number == 300.0);
    CHECK(v[1].column == 18);
    CHECK(b->ast->root[0][1].kind == NodeKind::Vector);
}

TEST_CASE("directives nest inside blocks", "[lang][parse]") {
    auto p = parse("union { #while (I < 3) sphere { I*x, 1 } #declare I = I + 1; #end pigment { rgb 1 } }");
    REQUIRE(p->ast);
    const Node& u = p->ast->root[0];
    REQUIRE(u.word == Word::Union);
    REQUIRE(u.count == 2);
    const Node& loop = u[0];
    REQUIRE(loop.kind == NodeKind::While);
    CHECK(loop[1].kind == NodeKind::Sequence);
    CHECK(loop[1].count == 2);
    CHECK(u[1].word == Word::Pigment);
}

TEST_CASE("the entries of a file are handed over one by one", "[lang][parse]") {
    NameTable names;
    Diagnostics diagnostics;
    std::vector<Word> words;
    const bool ok = parseSceneEntries("sphere { 0, 1 } #declare A = 1; box { 0, 1 }",
                                      std::make_shared<const std::string>("t.pov"), names, diagnostics,
                                      [&](const Ast&, const Node& n) { words.push_back(n.word); });
    CHECK(ok);
    CHECK(words == std::vector<Word>{Word::Sphere, Word::Declare, Word::Box});

    words.clear();  // a lone '#' is no entry
    CHECK(parseSceneEntries("sphere { 0, 1 } # // nothing after it", std::make_shared<const std::string>("t.pov"), names,
                            diagnostics, [&](const Ast&, const Node& n) { words.push_back(n.word); }));
    CHECK(words == std::vector<Word>{Word::Sphere});
}

TEST_CASE("syntax errors name the place and what was found there", "[lang][parse]") {
    CHECK(errorOf("sphere { 0 }") == "1:12: expected the radius of the sphere, found '}'");
    CHECK(errorOf("sphere { 0, 1\n") == "1:14: expected an object modifier or '}', found the end of the file");
    CHECK(errorOf("sphere { 0, 1 foo }") == "1:15: expected an object modifier or '}', found 'foo'");
    CHECK(errorOf("#declare X = 1\nsphere { X, 1 }") == "2:1: expected ';' after the declared value, found 'sphere'");
    CHECK(errorOf("spheres { 0, 1 }") ==
          "1:1: expected a scene item (camera, light_source, an object, global_settings, background, sky_sphere, "
          "fog) or a directive, found 'spheres'");
    CHECK(errorOf("#declare V = <1, 2, 3, 4, 5, 6>;") == "1:14: a vector has 2 to 5 components, this one has 6");
    CHECK(errorOf("#declare V = vrotate(x);") == "1:14: 'vrotate' takes 2 arguments, not 1");
    CHECK(errorOf("#declare S = \"abc\n\";") == "1:18: unterminated string: expected '\"' before the end of the line");
    CHECK(errorOf("sphere { 0, 1 }\n/* a /* b */\nbox { 0, 1 }") == "2:1: unterminated comment: no '*/' closes this '/*'");
}

TEST_CASE("unsupported POV-Ray constructs are named at their keyword", "[lang][parse]") {
    CHECK(errorOf("isosurface { function { x } }") == "1:1: 'isosurface' is not supported by asos");
    CHECK(errorOf("sphere { 0, 1\n  interior { media { } } }") == "2:14: 'media' is not supported by asos");
    CHECK(errorOf("#statistics \"x\"") == "1:1: '#statistics' is not supported by asos");
    CHECK(errorOf("#declare V = vturbulence(2, 0.5, 6, x);") == "1:14: 'vturbulence' is not supported by asos");
    CHECK(errorOf("sphere { 0, 1 pigment { quilted } }") == "1:25: 'quilted' is not supported by asos");
    CHECK(errorOf("light_source { 0, 1 projected_through { sphere { 0, 1 } } }") ==
          "1:21: 'projected_through' is not supported by asos");
    CHECK(errorOf("camera { normal { bumps 0.1 } }") == "1:10: 'normal' in a camera is not supported by asos");
    CHECK(errorOf("sphere { 0, 1 normal { checker } }") ==
          "1:24: 'checker' in a normal (a pattern of normals) is not supported by asos");
    CHECK(errorOf("sphere { 0, 1 normal { bumps slope_map { [0 <0, 1>] } } }") ==
          "1:30: 'slope_map' is not supported by asos");
    CHECK(errorOf("#frobnicate") == "1:1: unknown directive '#frobnicate'");
}
